#include "styk/mesher/convert.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <memory>
#include <stdexcept>

#include "reference_shape.hpp"

namespace styk::mesher {
namespace {

using detail::natural_point;
using detail::ReferenceShape;
using CornerKey = std::vector<int>;  // sorted mesh node indices of a face's corners

std::string element_name(int e) { return "element " + std::to_string(e + 1); }

// What converting to one type means, worked out once from the two TElements.
struct Plan {
  std::string type;
  ElementConversion how;
  std::unique_ptr<ReferenceShape> target, base;
  std::vector<int> base_node;  // per target node: the base node at its natural point, or -1
  std::vector<char> conforms;  // per target face: the same natural nodes as the base type's face
};

const TElement& registered(const ElementRegistry& registry, const std::string& type) {
  const TElement* element = registry.find(type);
  if (!element)
    throw std::invalid_argument("element conversion: element type " + type +
                                " is not registered (are the plug-ins loaded?)");
  return *element;
}

// Natural points of the nodes of `shape` on face f.
std::vector<Eigen::Vector3d> face_points(const ReferenceShape& shape, int f) {
  std::vector<Eigen::Vector3d> out;
  for (const Vec3& xi : shape.natural())
    if (shape.on_face(f, natural_point(xi))) out.push_back(natural_point(xi));
  return out;
}

bool same_points(std::vector<Eigen::Vector3d> a, std::vector<Eigen::Vector3d> b, double tol) {
  if (a.size() != b.size()) return false;
  for (const Eigen::Vector3d& p : a) {
    const auto hit = std::find_if(b.begin(), b.end(),
                                  [&](const Eigen::Vector3d& q) { return (p - q).norm() < tol; });
    if (hit == b.end()) return false;
    b.erase(hit);
  }
  return true;
}

Plan make_plan(const ElementRegistry& registry, const std::string& type) {
  Plan plan;
  plan.type = to_upper(type);
  const TElement& target = registered(registry, plan.type);
  const std::optional<ElementConversion> how = target.conversion();
  if (!how)
    throw std::invalid_argument("element conversion: element type " + plan.type +
                                " does not describe a conversion (TElement::conversion())");
  plan.how = *how;
  plan.target = std::make_unique<ReferenceShape>(target);
  plan.base = std::make_unique<ReferenceShape>(registered(registry, plan.how.base));
  for (const Vec3& xi : target.natural_nodes())
    plan.base_node.push_back(plan.base->node_at(natural_point(xi)));
  if (plan.how.contact_face >= plan.target->face_count())
    throw std::invalid_argument("element conversion: " + plan.type + " names contact face S" +
                                std::to_string(plan.how.contact_face + 1) + ", which it lacks");
  for (int f = 0; f < plan.target->face_count(); ++f)
    plan.conforms.push_back(
        f < plan.base->face_count() &&
        same_points(face_points(*plan.target, f), face_points(*plan.base, f), 1e-9));
  return plan;
}

// One element as it will be converted: old = R new (identity when it converts as it is).
struct Orientation {
  CubeRotation R{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
};

std::vector<Vec3> coords_of(const Mesh& mesh, const MeshElement& element) {
  std::vector<Vec3> x;
  for (int n : element.nodes) x.push_back(mesh.nodes[n]);
  return x;
}

// Where target node k of element e lands when e converts with orientation o.
Eigen::Vector3d target_position(const Mesh& mesh, const Plan& plan, int e, const Orientation& o,
                                int k) {
  const Eigen::Vector3d xi = detail::turn(o.R, natural_point(plan.target->natural()[k]));
  return plan.base->place(coords_of(mesh, mesh.elements[e]), xi);
}

// Positions of the target nodes on old face `old_face` of e converted with orientation o.
std::vector<Eigen::Vector3d> converted_face(const Mesh& mesh, const Plan& plan, int e,
                                            const Orientation& o, int old_face) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = 0; k < plan.target->natural().size(); ++k) {
    const Eigen::Vector3d xi = detail::turn(o.R, natural_point(plan.target->natural()[k]));
    if (plan.base->on_face(old_face, xi))
      out.push_back(target_position(mesh, plan, e, o, static_cast<int>(k)));
  }
  return out;
}

CornerKey corner_key(const MeshElement& element, const ReferenceShape& shape, int face) {
  CornerKey key;
  for (int local : shape.face_corners(face)) key.push_back(element.nodes[local]);
  std::sort(key.begin(), key.end());
  return key;
}

// The orientation that turns old face `face` into the contact face.
Orientation orientation_to(const Plan& plan, int e, int face) {
  Orientation o;
  if (!plan.base->rotation_between(plan.how.contact_face, face, o.R))
    throw std::invalid_argument("element conversion: " + element_name(e) + " (" + plan.how.base +
                                ") cannot be turned so that its face S" + std::to_string(face + 1) +
                                " becomes the contact face of " + plan.type);
  return o;
}

// The layer's elements and faces from the surface, one face per element, all of the base type.
std::map<int, int> layer_of(const Mesh& mesh, const Plan& plan, const std::string& surface) {
  const auto it = mesh.surfaces.find(to_upper(surface));
  if (it == mesh.surfaces.end() || it->second.empty())
    throw std::invalid_argument("element conversion: no surface named " + to_upper(surface));
  std::map<int, int> layer;
  for (const FaceRef& f : it->second) {
    if (mesh.elements[f.element].type != plan.how.base)
      throw std::invalid_argument("element conversion: " + element_name(f.element) + " is " +
                                  mesh.elements[f.element].type + ", not " + plan.how.base);
    if (!layer.emplace(f.element, f.face).second)
      throw std::invalid_argument("element conversion: " + element_name(f.element) +
                                  " has two faces on surface " + to_upper(surface));
  }
  return layer;
}

// Faces of the base type's elements by their corner nodes.
std::map<CornerKey, std::vector<FaceRef>> faces_by_corners(const Mesh& mesh, const Plan& plan) {
  std::map<CornerKey, std::vector<FaceRef>> out;
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
    if (mesh.elements[e].type == plan.how.base)
      for (int f = 0; f < plan.base->face_count(); ++f)
        out[corner_key(mesh.elements[e], *plan.base, f)].push_back({e, f});
  return out;
}

// Closure: a target face other than the contact face that differs from the base type's face
// (C3D28's side faces) conforms only with the same face of another converted element, so every
// base element across it joins the layer, through the free face that makes its converted nodes
// meet ours.
void close_layer(const Mesh& mesh, const Plan& plan, std::map<int, int>& layer,
                 const std::string& surface, double tol) {
  const auto by_corners = faces_by_corners(mesh, plan);
  std::deque<int> queue;
  for (const auto& entry : layer) queue.push_back(entry.first);
  while (!queue.empty()) {
    const int e = queue.front();
    queue.pop_front();
    const Orientation o = orientation_to(plan, e, layer.at(e));
    for (int j = 0; j < plan.target->face_count(); ++j) {
      if (j == plan.how.contact_face || plan.conforms[j]) continue;
      const int old_face = plan.base->face_at(detail::turn(o.R, plan.target->face_centre(j)));
      const std::vector<Eigen::Vector3d> ours = converted_face(mesh, plan, e, o, old_face);
      const auto sharing = by_corners.find(corner_key(mesh.elements[e], *plan.base, old_face));
      if (sharing == by_corners.end()) continue;
      for (const FaceRef& other : sharing->second) {
        if (other.element == e) continue;
        const auto in_layer = layer.find(other.element);
        if (in_layer != layer.end()) {
          const Orientation oo = orientation_to(plan, other.element, in_layer->second);
          if (!same_points(ours, converted_face(mesh, plan, other.element, oo, other.face), tol))
            throw std::invalid_argument("element conversion: " + element_name(e) + " and " +
                                        element_name(other.element) +
                                        " share a face with their contact faces not aligned");
          continue;
        }
        int join = -1;
        for (int h = 0; h < plan.base->face_count() && join < 0; ++h) {
          if (h == other.face) continue;
          const CornerKey free = corner_key(mesh.elements[other.element], *plan.base, h);
          if (by_corners.at(free).size() != 1) continue;  // shared: not a free face
          Orientation candidate;
          if (!plan.base->rotation_between(plan.how.contact_face, h, candidate.R)) continue;
          if (same_points(ours, converted_face(mesh, plan, other.element, candidate, other.face),
                          tol))
            join = h;
        }
        if (join < 0)
          throw std::invalid_argument(
              "element conversion: the " + plan.type + " layer on surface " + to_upper(surface) +
              " cannot be closed: " + element_name(other.element) + " borders " + element_name(e) +
              " through a face that only another " + plan.type +
              " conforms with, but has no free face to turn into its contact face");
        layer.emplace(other.element, join);
        queue.push_back(other.element);
      }
    }
  }
}

// New nodes of converted elements, shared by the elements that reach the same point through the
// same edge or face of their base elements (identified by its corner nodes), never across a
// split interface.
class NewNodes {
 public:
  NewNodes(Mesh& mesh, double tol) : mesh_(mesh), tol_(tol) {}
  int at(const CornerKey& carrier, const Eigen::Vector3d& x) {
    std::vector<int>& bucket = by_carrier_[carrier];
    for (int n : bucket)
      if ((natural_point(mesh_.nodes[n]) - x).norm() < tol_) return n;
    bucket.push_back(mesh_.add_node({x[0], x[1], x[2]}));
    return bucket.back();
  }

 private:
  Mesh& mesh_;
  double tol_;
  std::map<CornerKey, std::vector<int>> by_carrier_;
};

// Converts element e with orientation o: renumbers it, updates the surfaces naming it, adds the
// target nodes.
void convert_one(Mesh& mesh, const Plan& plan, int e, const Orientation& o, NewNodes& added) {
  const std::vector<int> old_of_new = plan.base->renumbering(o.R);
  MeshElement& element = mesh.elements[e];
  std::vector<int> rotated(old_of_new.size());
  for (std::size_t k = 0; k < old_of_new.size(); ++k) rotated[k] = element.nodes[old_of_new[k]];
  for (auto& [name, faces] : mesh.surfaces) {
    bool touched = false;
    for (FaceRef& f : faces)
      if (f.element == e) {
        f.face = plan.base->rotated_face(o.R, f.face);
        touched = true;
      }
    if (touched) std::sort(faces.begin(), faces.end());
  }
  std::vector<int> nodes(plan.base_node.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (plan.base_node[k] >= 0) {
      nodes[k] = rotated[plan.base_node[k]];
      continue;
    }
    const Eigen::Vector3d xi = natural_point(plan.target->natural()[k]);
    CornerKey carrier;
    for (int local : plan.base->carrier_corners(xi)) carrier.push_back(rotated[local]);
    std::sort(carrier.begin(), carrier.end());
    if (carrier.empty()) carrier = {-1 - e};  // inside the element: its own
    nodes[k] = added.at(carrier, target_position(mesh, plan, e, o, static_cast<int>(k)));
  }
  element.nodes = std::move(nodes);
  element.type = plan.type;
}

void record_faces(Mesh& mesh, const Plan& plan) {
  std::vector<std::vector<int>>& faces = mesh.faces_of_type[plan.type];
  faces.clear();
  for (const FaceDef& f : plan.target->element().faces()) faces.push_back(f.nodes);
}

}  // namespace

std::vector<int> convert_elements(Mesh& mesh, const ElementRegistry& registry,
                                  const std::string& type, const std::string& surface,
                                  const std::vector<int>& elements) {
  const Plan plan = make_plan(registry, type);
  const double tol = 1e-9 * std::max(mesh.size(), 1e-300);
  NewNodes added(mesh, tol);
  std::vector<int> converted;
  if (plan.how.contact_face < 0) {
    std::vector<int> chosen = elements;
    if (chosen.empty())
      for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
        if (mesh.elements[e].type == plan.how.base) chosen.push_back(e);
    for (int e : chosen) {
      if (e < 0 || e >= static_cast<int>(mesh.elements.size()) ||
          mesh.elements[e].type != plan.how.base)
        throw std::invalid_argument(
            "element conversion to " + plan.type + ": " + element_name(e) + " is " +
            (e >= 0 && e < static_cast<int>(mesh.elements.size()) ? mesh.elements[e].type
                                                                  : std::string("no element")) +
            ", not " + plan.how.base);
      convert_one(mesh, plan, e, Orientation{}, added);
      converted.push_back(e);
    }
  } else {
    std::map<int, int> layer = layer_of(mesh, plan, surface);
    close_layer(mesh, plan, layer, surface, tol);
    std::vector<FaceRef> contact_faces;
    for (const auto& [e, face] : layer) {
      convert_one(mesh, plan, e, orientation_to(plan, e, face), added);
      converted.push_back(e);
      contact_faces.push_back({e, plan.how.contact_face});
    }
    mesh.surfaces[to_upper(surface)] = contact_faces;
  }
  record_faces(mesh, plan);
  mesh.remove_unused_nodes();
  return converted;
}

std::vector<std::string> conversions_from(const ElementRegistry& registry,
                                          const std::string& base) {
  std::vector<std::string> out;
  for (const std::string& name : registry.names()) {
    const std::optional<ElementConversion> how = registry.find(name)->conversion();
    if (how && to_upper(how->base) == to_upper(base)) out.push_back(name);
  }
  return out;
}

bool converts_a_layer(const ElementRegistry& registry, const std::string& type) {
  const TElement* element = registry.find(type);
  if (!element) return false;
  const std::optional<ElementConversion> how = element->conversion();
  return how && how->contact_face >= 0;
}

}  // namespace styk::mesher
