#include "session/picking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "session/highlight.hpp"
#include "styk/render/skin.hpp"

namespace styk::gui {
namespace {

constexpr int kVisibilityReach = 2;  // pixels around a node searched for a face holding it

// Whether the screen bounding box of a face's corners meets `region` grown by the reach (and a
// pixel for the rasteriser's rounding).
bool meets(const std::vector<std::array<double, 3>>& corners, const render::PixelRect& region) {
  const double grow = kVisibilityReach + 1.0;
  double x0 = corners[0][0], x1 = x0, y0 = corners[0][1], y1 = y0;
  for (const auto& c : corners) {
    x0 = std::min(x0, c[0]), x1 = std::max(x1, c[0]);
    y0 = std::min(y0, c[1]), y1 = std::max(y1, c[1]);
  }
  return x1 >= region.x - grow && x0 <= region.x + region.width + grow && y1 >= region.y - grow &&
         y0 <= region.y + region.height + grow;
}

}  // namespace

Picker::Picker(const Scene& scene) : scene_(scene) { build(nullptr); }

Picker::Picker(const Scene& scene, const render::PixelRect& region) : scene_(scene) {
  build(&region);
}

void Picker::build(const render::PixelRect* region) {
  const Scene& scene = scene_;
  if (!scene.skin() || !scene.model()) return;
  const render::Frame& frame = scene.last_frame();
  width_ = frame.width;
  height_ = frame.height;
  ids_.assign(std::size_t(width_) * height_, -1);
  depth_.assign(ids_.size(), std::numeric_limits<float>::max());
  const Model& model = *scene.model();
  std::vector<std::array<double, 3>> corners;
  for (const render::SkinModel::LayerSkin& layer : scene.skin()->layers()) {
    for (const render::SkinFace& face : layer.faces) {
      corners.clear();
      for (int n : face_corner_nodes(scene, face.element, face.face))
        corners.push_back(scene.screen_position(n));
      if (region && !meets(corners, *region)) continue;
      const int id = int(faces_.size());
      // A planar element's area is an element to pick, not a face of it (its faces are edges).
      const bool area =
          face.face >= int(scene.skin()->formulations()[face.element]->faces().size());
      faces_.push_back(area ? render::SkinFace{face.element, kNoFace} : face);
      const FaceDef& def = scene.skin()->face_def(face.element, face.face);
      const int* nodes = model.element_nodes(face.element);
      std::vector<int> all;
      for (int k : def.nodes) all.push_back(nodes[k]);
      face_nodes_.push_back(std::move(all));
      rasterise(id, corners);
    }
    // Line elements (trusses) are drawn as bars: picked along their segments, as elements only.
    for (int element : layer.lines) {
      const std::vector<int> order =
          render::line_node_order(*scene.skin()->formulations()[element]);
      const int* nodes = model.element_nodes(element);
      corners.clear();
      for (int k : order) corners.push_back(scene.screen_position(nodes[k]));
      if (corners.size() < 2 || (region && !meets(corners, *region))) continue;
      const int id = int(faces_.size());
      faces_.push_back({element, kNoFace});
      std::vector<int> all;
      for (int k : order) all.push_back(nodes[k]);
      face_nodes_.push_back(std::move(all));
      for (std::size_t i = 0; i + 1 < corners.size(); ++i)
        rasterise_segment(id, corners[i], corners[i + 1]);
    }
  }
}

void Picker::rasterise(int id, const std::vector<std::array<double, 3>>& corners) {
  for (const auto& c : corners)
    if (!(c[2] >= -1.0 && c[2] <= 1.0)) return;  // outside the depth range: not drawn either
  for (std::size_t i = 1; i + 1 < corners.size(); ++i)
    rasterise_triangle(id, corners[0], corners[i], corners[i + 1]);
}

void Picker::rasterise_segment(int id, const std::array<double, 3>& a,
                               const std::array<double, 3>& b) {
  for (const auto* c : {&a, &b})
    if (!((*c)[2] >= -1.0 && (*c)[2] <= 1.0)) return;  // outside the depth range: not drawn
  // Half the drawn bar's width plus half a pixel, so a click on the bar's edge still hits it.
  const double half = 0.5 * scene_.last_frame().bar_width + 0.5;
  const render::PixelRect& box = scene_.last_frame().overlay.model;
  const int x0 = std::max({0, box.x, int(std::floor(std::min(a[0], b[0]) - half))});
  const int x1 =
      std::min({width_ - 1, box.x + box.width - 1, int(std::ceil(std::max(a[0], b[0]) + half))});
  const int y0 = std::max({0, box.y, int(std::floor(std::min(a[1], b[1]) - half))});
  const int y1 =
      std::min({height_ - 1, box.y + box.height - 1, int(std::ceil(std::max(a[1], b[1]) + half))});
  const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double t = length2 > 1e-18
                           ? std::clamp(((px - a[0]) * dx + (py - a[1]) * dy) / length2, 0.0, 1.0)
                           : 0.0;
      if (std::hypot(a[0] + t * dx - px, a[1] + t * dy - py) > half) continue;
      const float z = float(a[2] + t * (b[2] - a[2]));
      const std::size_t i = std::size_t(y) * width_ + x;
      if (z < depth_[i]) depth_[i] = z, ids_[i] = id;
    }
}

void Picker::rasterise_triangle(int id, const std::array<double, 3>& a,
                                const std::array<double, 3>& b, const std::array<double, 3>& c) {
  const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  if (std::abs(area) < 1e-9) return;  // seen edge-on
  const render::PixelRect& box = scene_.last_frame().overlay.model;
  const int x0 = std::max(box.x, int(std::floor(std::min({a[0], b[0], c[0]}))));
  const int x1 = std::min(box.x + box.width - 1, int(std::ceil(std::max({a[0], b[0], c[0]}))));
  const int y0 = std::max(box.y, int(std::floor(std::min({a[1], b[1], c[1]}))));
  const int y1 = std::min(box.y + box.height - 1, int(std::ceil(std::max({a[1], b[1], c[1]}))));
  for (int y = std::max(0, y0); y <= std::min(height_ - 1, y1); ++y)
    for (int x = std::max(0, x0); x <= std::min(width_ - 1, x1); ++x) {
      const double px = x + 0.5, py = y + 0.5;
      // Barycentric weights from the edge functions; both windings count (two-sided faces).
      const double wa = ((b[0] - px) * (c[1] - py) - (b[1] - py) * (c[0] - px)) / area;
      const double wb = ((c[0] - px) * (a[1] - py) - (c[1] - py) * (a[0] - px)) / area;
      const double wc = 1.0 - wa - wb;
      constexpr double kEdge = -1e-9;
      if (wa < kEdge || wb < kEdge || wc < kEdge) continue;
      const float z = float(wa * a[2] + wb * b[2] + wc * c[2]);
      const std::size_t i = std::size_t(y) * width_ + x;
      if (z < depth_[i]) depth_[i] = z, ids_[i] = id;
    }
}

int Picker::id_at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return -1;
  return ids_[std::size_t(y) * width_ + x];
}

std::optional<render::SkinFace> Picker::face_at(int x, int y) const {
  const int id = id_at(x, y);
  if (id < 0) return std::nullopt;
  return faces_[id];
}

bool Picker::node_visible(int node) const {
  const std::array<double, 3> p = scene_.screen_position(node);
  const int cx = int(std::floor(p[0])), cy = int(std::floor(p[1]));
  for (int y = cy - kVisibilityReach; y <= cy + kVisibilityReach; ++y)
    for (int x = cx - kVisibilityReach; x <= cx + kVisibilityReach; ++x) {
      const int id = id_at(x, y);
      if (id < 0) continue;
      const std::vector<int>& nodes = face_nodes_[id];
      if (std::find(nodes.begin(), nodes.end(), node) != nodes.end()) return true;
    }
  return false;
}

bool Picker::edge_point_visible(double px, double py, int a, int b) const {
  const int cx = int(std::floor(px)), cy = int(std::floor(py));
  for (int y = cy - kVisibilityReach; y <= cy + kVisibilityReach; ++y)
    for (int x = cx - kVisibilityReach; x <= cx + kVisibilityReach; ++x) {
      const int id = id_at(x, y);
      if (id < 0) continue;
      const std::vector<int>& nodes = face_nodes_[id];
      if (std::find(nodes.begin(), nodes.end(), a) != nodes.end() &&
          std::find(nodes.begin(), nodes.end(), b) != nodes.end())
        return true;
    }
  return false;
}

std::optional<PickedItem> Picker::pick(int x, int y, PickKind kind, int radius) const {
  if (kind != PickKind::Node) {
    const std::optional<render::SkinFace> face = face_at(x, y);
    if (!face || (kind == PickKind::Face && face->face == kNoFace)) return std::nullopt;
    PickedItem item;
    item.kind = kind;
    item.element = face->element;
    if (kind == PickKind::Face) item.face = face->face + 1;
    return item;
  }
  // Nodes of the faces seen around the cursor, the nearest one on screen that is visible.
  std::vector<int> candidates;
  for (int v = y - radius; v <= y + radius; ++v)
    for (int u = x - radius; u <= x + radius; ++u)
      if (const int id = id_at(u, v); id >= 0)
        candidates.insert(candidates.end(), face_nodes_[id].begin(), face_nodes_[id].end());
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  int best = -1;
  double best_distance = std::numeric_limits<double>::max();
  for (int n : candidates) {
    const std::array<double, 3> p = scene_.screen_position(n);
    const double d = std::hypot(p[0] - (x + 0.5), p[1] - (y + 0.5));
    if (d > radius + 0.5 || d >= best_distance || !node_visible(n)) continue;
    best = n, best_distance = d;
  }
  if (best < 0) return std::nullopt;
  PickedItem item;
  item.kind = PickKind::Node;
  item.node = best;
  return item;
}

std::vector<PickedItem> Picker::pick_box(int x0, int y0, int x1, int y1, PickKind kind) const {
  if (x0 > x1) std::swap(x0, x1);
  if (y0 > y1) std::swap(y0, y1);
  std::vector<int> ids;
  const int reach = kind == PickKind::Node ? kVisibilityReach : 0;
  for (int y = y0 - reach; y <= y1 + reach; ++y)
    for (int x = x0 - reach; x <= x1 + reach; ++x)
      if (const int id = id_at(x, y); id >= 0) ids.push_back(id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<PickedItem> items;
  if (kind == PickKind::Node) {
    std::vector<int> nodes;
    for (int id : ids) nodes.insert(nodes.end(), face_nodes_[id].begin(), face_nodes_[id].end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (int n : nodes) {
      const std::array<double, 3> p = scene_.screen_position(n);
      if (p[0] < x0 || p[0] > x1 + 1 || p[1] < y0 || p[1] > y1 + 1 || !node_visible(n)) continue;
      PickedItem item;
      item.node = n;
      items.push_back(item);
    }
    return items;
  }
  for (int id : ids) {
    if (kind == PickKind::Face && faces_[id].face == kNoFace) continue;  // a bar has no face
    PickedItem item;
    item.kind = kind;
    item.element = faces_[id].element;
    if (kind == PickKind::Face) item.face = faces_[id].face + 1;
    items.push_back(item);
  }
  return items;  // Selection::apply sorts and removes the repeated elements
}

}  // namespace styk::gui
