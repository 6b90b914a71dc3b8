#include "styk/contact/tied_contact.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "surface_geometry.hpp"

namespace styk::contact {
namespace {

const Surface& surface_of(const Model& model, const std::string& name, const Tie& tie) {
  const auto it = model.surfaces.find(name);
  if (it == model.surfaces.end())
    throw InputError(tie.where, "*TIE " + tie.name + ": surface " + name + " is not defined");
  return it->second;
}

PlacedFace placed(const Model& model, const ElementRegistry& registry, const SurfaceFace& sf,
                  const SourceLoc& where) {
  PlacedFace f;
  const Element& element = model.elements[sf.element];
  f.element = registry.find(element.type);
  if (!f.element) throw InputError(where, "element type " + element.type + " is not registered");
  f.face = sf.face - 1;
  if (f.face < 0 || f.face >= static_cast<int>(f.element->faces().size()))
    throw InputError(where, "element " + std::to_string(element.id) + " has no face S" +
                                std::to_string(sf.face));
  const int* nodes = model.element_nodes(sf.element);
  f.geometry.X.resize(element.node_count, 3);
  for (int k = 0; k < element.node_count; ++k)
    for (int d = 0; d < 3; ++d) f.geometry.X(k, d) = model.coords[nodes[k]][d];
  f.geometry.id = element.id;
  f.geometry.where = element.where;
  return f;
}

// The nodes of a surface (face nodes of its faces, or its nodes).
std::set<int> nodes_of(const Model& model, const ElementRegistry& registry, const Surface& s) {
  if (s.kind == Surface::Kind::Nodes) return {s.nodes.begin(), s.nodes.end()};
  std::set<int> out;
  for (const SurfaceFace& sf : s.faces) {
    const TElement* element = registry.find(model.elements[sf.element].type);
    if (!element || sf.face < 1 || sf.face > static_cast<int>(element->faces().size())) continue;
    const int* nodes = model.element_nodes(sf.element);
    for (int local : element->faces()[sf.face - 1].nodes) out.insert(nodes[local]);
  }
  return out;
}

}  // namespace

double default_tie_tolerance(const Model& model, const ElementRegistry& registry,
                             const Surface& master, const SourceLoc& where) {
  double length = 0.0;
  int edges = 0;
  for (const SurfaceFace& sf : master.faces) {
    const PlacedFace f = placed(model, registry, sf, where);
    const std::vector<int>& corners = f.element->faces()[f.face].nodes;
    // Corner nodes come first; a face has as many corners as edges (3 or 4).
    const int n = corners.size() >= 8   ? 4
                  : corners.size() == 6 ? 3
                                        : static_cast<int>(corners.size());
    for (int k = 0; k < n; ++k) {
      length += (f.geometry.X.row(corners[k]) - f.geometry.X.row(corners[(k + 1) % n])).norm();
      ++edges;
    }
  }
  return edges > 0 ? 0.025 * length / edges : 0.0;
}

TiedSurfaces tie_surfaces(const Model& model, const ElementRegistry& registry, const Tie& tie) {
  const Surface& slave = surface_of(model, tie.slave, tie);
  const Surface& master = surface_of(model, tie.master, tie);
  if (master.kind != Surface::Kind::ElementFaces)
    throw InputError(tie.where, "*TIE " + tie.name + ": the master surface " + master.name +
                                    " must consist of element faces");
  TiedSurfaces out;
  const double fallback = default_tie_tolerance(model, registry, master, tie.where);
  out.tolerance = tie.position_tolerance.value_or(fallback);
  std::vector<PlacedFace> faces;
  std::vector<Eigen::Vector3d> lo, hi;
  for (const SurfaceFace& sf : master.faces) {
    faces.push_back(placed(model, registry, sf, tie.where));
    const PlacedFace& f = faces.back();
    Eigen::Vector3d a = Eigen::Vector3d::Constant(INFINITY), b = -a;
    for (int local : f.element->faces()[f.face].nodes) {
      a = a.cwiseMin(f.geometry.X.row(local).transpose());
      b = b.cwiseMax(f.geometry.X.row(local).transpose());
    }
    lo.push_back(a);
    hi.push_back(b);
  }
  const std::set<int> master_nodes = nodes_of(model, registry, master);
  for (int node : nodes_of(model, registry, slave)) {
    if (master_nodes.count(node) != 0) continue;  // on both surfaces: nothing to tie
    const Eigen::Vector3d xs(model.coords[node][0], model.coords[node][1], model.coords[node][2]);
    int best = -1;
    Projection best_projection;
    double best_distance = INFINITY;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const double reach = (hi[i] - lo[i]).norm() + out.tolerance;
      if (((lo[i].array() - reach) > xs.array()).any() ||
          ((hi[i].array() + reach) < xs.array()).any())
        continue;
      const Projection pr = project_on_face(faces[i], xs);
      if (!pr.converged) continue;
      // Beyond the face's edge by at most the default tolerance, measured along the face: in
      // natural coordinates, the excess times the face's size over 2.
      const double size = (hi[i] - lo[i]).norm();
      if (pr.outside() * 0.5 * size > fallback + 1e-12 * size) continue;
      const double distance = (pr.x - xs).norm();
      if (distance < best_distance) {
        best = static_cast<int>(i);
        best_projection = pr;
        best_distance = distance;
      }
    }
    if (best < 0 || best_distance > out.tolerance) {
      out.missed.push_back(node);
      continue;
    }
    const PlacedFace& f = faces[best];
    const FaceDef& face = f.element->faces()[f.face];
    const Eigen::VectorXd N =
        shape_values(*f.element, face_point(f, best_projection.p, best_projection.q));
    const int* nodes = model.element_nodes(master.faces[best].element);
    TiedNode t;
    t.slave = node;
    double sum = 0.0;
    for (int local : face.nodes)
      if (std::abs(N[local]) > 1e-12) {
        t.master.emplace_back(nodes[local], N[local]);
        sum += N[local];
      }
    for (auto& term : t.master) term.second /= sum;  // exact partition of unity
    t.projection = {best_projection.x[0], best_projection.x[1], best_projection.x[2]};
    t.distance = best_distance;
    out.tied.push_back(std::move(t));
  }
  return out;
}

}  // namespace styk::contact
