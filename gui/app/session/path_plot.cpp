#include "session/path_plot.hpp"

#include <algorithm>
#include <cmath>

namespace styk::gui {
namespace {

double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The node farthest from `from`.
int farthest(const Model& model, const std::vector<int>& nodes, const Vec3& from) {
  int best = nodes.front();
  double d_best = -1.0;
  for (int n : nodes) {
    const double d = distance(model.coords[n], from);
    if (d > d_best) d_best = d, best = n;
  }
  return best;
}

}  // namespace

std::vector<PathPoint> field_along_node_set(const Scene& scene, const Model& model,
                                            const std::string& nset) {
  const NodeSet* set = model.find_nset(nset);
  if (!set) throw InputError({}, "no node set " + to_upper(nset) + " in the model");
  if (set->nodes.size() < 2)
    throw InputError({}, "node set " + set->name + " has fewer than 2 nodes");
  if (!scene.field()) throw InputError({}, "choose a contour field first");
  // The path's ends: the node farthest from an arbitrary one, and the node farthest from that.
  const int start = farthest(model, set->nodes, model.coords[set->nodes.front()]);
  const int end = farthest(model, set->nodes, model.coords[start]);
  const Vec3& a = model.coords[start];
  const Vec3& b = model.coords[end];
  const double length = distance(a, b);
  std::vector<PathPoint> points;
  for (int n : set->nodes) {
    const std::optional<double> value = scene.value_at_node(n);
    if (!value) continue;
    const Vec3& x = model.coords[n];
    double along = 0.0;
    if (length > 0)
      for (int k = 0; k < 3; ++k) along += (x[k] - a[k]) * (b[k] - a[k]) / length;
    points.push_back({along, *value, model.node_ids[n]});
  }
  std::sort(points.begin(), points.end(), [](const PathPoint& p, const PathPoint& q) {
    return p.distance != q.distance ? p.distance < q.distance : p.node_id < q.node_id;
  });
  return points;
}

}  // namespace styk::gui
