#include "styk/core/cyclic_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// Rotation by `angle` about the unit `axis` (Rodrigues).
Matrix3 rotation_about(const Vec3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  Matrix3 Q;
  Q[0] = {c + t * k[0] * k[0], t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1]};
  Q[1] = {t * k[1] * k[0] + s * k[2], c + t * k[1] * k[1], t * k[1] * k[2] - s * k[0]};
  Q[2] = {t * k[2] * k[0] - s * k[1], t * k[2] * k[1] + s * k[0], c + t * k[2] * k[2]};
  return Q;
}

double model_size(const Model& model) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const Vec3& x : model.coords)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[d]);
      hi[d] = std::max(hi[d], x[d]);
    }
  return model.node_count() > 0 ? norm(minus(hi, lo)) : 1.0;
}

// Nodes sorted by x for nearest-node queries within a tolerance.
class Locator {
 public:
  Locator(const Model& model, const std::vector<int>& nodes) : model_(model) {
    for (int n : nodes) by_x_.emplace_back(model.coords[n][0], n);
    std::sort(by_x_.begin(), by_x_.end());
  }
  // The nearest node within `tolerance` of x, preferring nodes of body `body` (coincident nodes
  // of two bodies in contact lie on a sector boundary together), or -1; `distance` gets its
  // distance.
  int nearest(const Vec3& x, double tolerance, double& distance, const std::vector<int>& body_of,
              int body) const {
    int best = -1;
    bool best_same = false;
    distance = INFINITY;
    auto it = std::lower_bound(by_x_.begin(), by_x_.end(),
                               std::make_pair(x[0] - tolerance, std::numeric_limits<int>::min()));
    for (; it != by_x_.end() && it->first <= x[0] + tolerance; ++it) {
      const double d = norm(minus(model_.coords[it->second], x));
      if (d > tolerance) continue;
      const bool same = body_of[it->second] == body;
      if (best < 0 || (same && !best_same) || (same == best_same && d < distance)) {
        distance = d;
        best = it->second;
        best_same = same;
      }
    }
    return best;
  }
  // The nearest node at any distance (for messages).
  double nearest_distance(const Vec3& x) const {
    double best = INFINITY;
    for (const auto& entry : by_x_)
      best = std::min(best, norm(minus(model_.coords[entry.second], x)));
    return best;
  }

 private:
  const Model& model_;
  std::vector<std::pair<double, int>> by_x_;
};

// The connected part of the mesh (through shared element nodes) each node belongs to.
std::vector<int> bodies(const Model& model) {
  std::vector<int> parent(model.node_count());
  for (int n = 0; n < model.node_count(); ++n) parent[n] = n;
  const auto root = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    for (int k = 1; k < model.elements[e].node_count; ++k) parent[root(nodes[k])] = root(nodes[0]);
  }
  for (int n = 0; n < model.node_count(); ++n) parent[n] = root(n);
  return parent;
}

std::string node_name(const Model& model, int node) {
  return "node " + std::to_string(model.node_ids[node]);
}

// The tie's axis, its surfaces' nodes split into those on the axis (within `tolerance`) and the
// off-axis slave nodes the tie pairs.
struct TieNodes {
  std::vector<int> off_axis_slaves, masters;
};

TieNodes split_axis_nodes(const Model& model, const ElementRegistry& registry,
                          const CyclicSymmetry& tie, double tolerance,
                          ResolvedCyclicSymmetry& out) {
  const auto surface = [&](const std::string& name) -> const Surface& {
    const auto it = model.surfaces.find(name);
    if (it == model.surfaces.end())
      throw InputError(tie.where, "*TIE names surface " + name + ", which is not defined");
    return it->second;
  };
  const std::vector<int> slaves = surface_node_list(model, registry, surface(tie.slave));
  TieNodes nodes;
  nodes.masters = surface_node_list(model, registry, surface(tie.master));
  if (slaves.empty() || nodes.masters.empty())
    throw InputError(tie.where, "cyclic *TIE " + tie.tie + ": a surface has no nodes");
  const auto on_axis = [&](int node) {
    const Vec3 r = minus(model.coords[node], out.point);
    const double along = dot(r, out.axis);
    return norm(minus(r, Vec3{along * out.axis[0], along * out.axis[1], along * out.axis[2]})) <=
           tolerance;
  };
  for (int node : slaves) (on_axis(node) ? out.axis_nodes : nodes.off_axis_slaves).push_back(node);
  for (int node : nodes.masters)
    if (on_axis(node)) out.axis_nodes.push_back(node);
  std::sort(out.axis_nodes.begin(), out.axis_nodes.end());
  out.axis_nodes.erase(std::unique(out.axis_nodes.begin(), out.axis_nodes.end()),
                       out.axis_nodes.end());
  if (nodes.off_axis_slaves.empty())
    throw InputError(tie.where, "cyclic *TIE " + tie.tie + ": every slave node lies on the axis");
  return nodes;
}

Vec3 image(const Model& model, const ResolvedCyclicSymmetry& out, const Matrix3& Q, int node) {
  return plus(out.point, rotate(Q, minus(model.coords[node], out.point)));
}

// The sense of rotation: the one under which the first off-axis slave node finds its master.
void choose_sense(const Model& model, const CyclicSymmetry& tie, const Locator& locator,
                  const std::vector<int>& body_of, int first, double tolerance,
                  ResolvedCyclicSymmetry& out) {
  const double sector = 2.0 * kPi / tie.sectors;
  double distance = 0.0;
  const Matrix3 forward = rotation_about(out.axis, sector);
  const Matrix3 backward = rotation_about(out.axis, -sector);
  const int body = body_of[first];
  if (locator.nearest(image(model, out, forward, first), tolerance, distance, body_of, body) >= 0) {
    out.angle = sector;
    out.rotation = forward;
  } else if (locator.nearest(image(model, out, backward, first), tolerance, distance, body_of,
                             body) >= 0) {
    out.angle = -sector;
    out.rotation = backward;
  } else {
    throw InputError(
        tie.where,
        "cyclic *TIE " + tie.tie + ": slave " + node_name(model, first) +
            " turned by the sector angle 360/" + std::to_string(tie.sectors) +
            " (either way) about the axis meets no node of master surface " + tie.master +
            " within the position tolerance " + std::to_string(tolerance) + " (nearest at " +
            std::to_string(locator.nearest_distance(image(model, out, forward, first))) +
            "): is N the number of sectors of the geometry, and do the meshes of the two "
            "boundaries match? (Styk ties matching meshes only)");
  }
}

// Every off-axis slave node with the master node at its image, each master claimed once.
void pair_nodes(const Model& model, const CyclicSymmetry& tie, const Locator& locator,
                const std::vector<int>& body_of, const std::vector<int>& off, double tolerance,
                ResolvedCyclicSymmetry& out) {
  double distance = 0.0;
  std::map<int, int> claimed;  // master -> slave
  for (int node : off) {
    const Vec3 target = image(model, out, out.rotation, node);
    const int master = locator.nearest(target, tolerance, distance, body_of, body_of[node]);
    if (master < 0)
      throw InputError(tie.where, "cyclic *TIE " + tie.tie + ": slave " + node_name(model, node) +
                                      " has no node of master surface " + tie.master +
                                      " within the position tolerance " +
                                      std::to_string(tolerance) + " of its image (nearest at " +
                                      std::to_string(locator.nearest_distance(target)) +
                                      "); Styk ties matching meshes only");
    if (master == node)
      throw InputError(tie.where, "cyclic *TIE " + tie.tie + ": " + node_name(model, node) +
                                      " belongs to both surfaces but is not on the axis");
    const auto [it, fresh] = claimed.emplace(master, node);
    if (!fresh)
      throw InputError(tie.where, "cyclic *TIE " + tie.tie + ": master " +
                                      node_name(model, master) + " is the image of both slave " +
                                      node_name(model, it->second) + " and " +
                                      node_name(model, node));
    out.pairs.push_back({node, master});
  }
}

ResolvedCyclicSymmetry resolve_one(const Model& model, const ElementRegistry& registry,
                                   const CyclicSymmetry& tie, double size,
                                   const std::vector<int>& body_of) {
  ResolvedCyclicSymmetry out;
  out.definition = &tie;
  out.point = tie.a;
  const Vec3 direction = minus(tie.b, tie.a);
  const double length = norm(direction);
  out.axis = {direction[0] / length, direction[1] / length, direction[2] / length};
  const double tolerance = tie.position_tolerance.value_or(1e-6 * size);
  const TieNodes nodes = split_axis_nodes(model, registry, tie, tolerance, out);
  const Locator locator(model, nodes.masters);
  choose_sense(model, tie, locator, body_of, nodes.off_axis_slaves.front(), tolerance, out);
  pair_nodes(model, tie, locator, body_of, nodes.off_axis_slaves, tolerance, out);
  return out;
}

}  // namespace

Vec3 rotate(const Matrix3& Q, const Vec3& v) { return {dot(Q[0], v), dot(Q[1], v), dot(Q[2], v)}; }

std::vector<int> surface_node_list(const Model& model, const ElementRegistry& registry,
                                   const Surface& surface) {
  std::vector<int> nodes = surface.nodes;
  for (const SurfaceFace& f : surface.faces) {
    const TElement* formulation = registry.find(model.elements[f.element].type);
    if (formulation == nullptr)
      throw InputError(surface.where, "surface " + surface.name + " lies on element " +
                                          std::to_string(model.elements[f.element].id) +
                                          " of type " + model.elements[f.element].type +
                                          ", which no element provides");
    const int* element_nodes = model.element_nodes(f.element);
    for (int local : formulation->faces().at(f.face - 1).nodes)
      nodes.push_back(element_nodes[local]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<ResolvedCyclicSymmetry> resolve_cyclic_symmetries(const Model& model,
                                                              const ElementRegistry& registry) {
  std::vector<ResolvedCyclicSymmetry> out;
  if (model.cyclic_symmetries.empty()) return out;
  const double size = model_size(model);
  const std::vector<int> body_of = bodies(model);
  for (const CyclicSymmetry& tie : model.cyclic_symmetries) {
    if (tie.sectors < 2)
      throw InputError(
          tie.where, "cyclic *TIE " + tie.tie + " has no *CYCLIC SYMMETRY MODEL (N= and the axis)");
    out.push_back(resolve_one(model, registry, tie, size, body_of));
  }
  // A node tied by two ties would be eliminated twice.
  std::map<int, const CyclicSymmetry*> dependent;
  for (const ResolvedCyclicSymmetry& r : out)
    for (const CyclicNodePair& p : r.pairs) {
      const auto [it, fresh] = dependent.emplace(p.slave, r.definition);
      if (!fresh)
        throw InputError(r.definition->where, node_name(model, p.slave) +
                                                  " is a slave node of cyclic *TIE " +
                                                  it->second->tie + " already");
    }
  return out;
}

}  // namespace styk
