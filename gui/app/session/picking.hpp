// Picking in the 3D view without GL: the visible skin faces of the last frame are rasterised on
// the CPU into a face-id buffer with a depth test (the same camera, the same pixels as the
// picture), so only what is front-most can be picked. A click picks the face under the cursor, its
// element, or the nearest node of a front-most face within a radius; a box picks every visible
// node, element or face inside it.
#pragma once

#include <optional>
#include <vector>

#include "session/scene.hpp"
#include "session/selection.hpp"

namespace styk::gui {

// A picker entry that is a line element (truss bar) or a planar element's area: it has an element
// and nodes, but no face of its own to pick (a planar element's faces are its edges).
constexpr int kNoFace = -1;

class Picker {
 public:
  // Rasterises the scene's last frame(); the scene must stay unchanged while the picker is used.
  explicit Picker(const Scene& scene);
  // Rasterises only the faces whose screen bounding box meets `region` grown by the visibility
  // reach: inside `region` every answer equals the whole picker's, at a fraction of the cost when
  // the region is small (the selection markers' depth test, redone each frame of an orbit).
  Picker(const Scene& scene, const render::PixelRect& region);

  // The entity at pixel (x, y) (top-left origin, framebuffer pixels): the front-most face under
  // the pixel, its element, or the nearest visible node within `radius` pixels.
  std::optional<PickedItem> pick(int x, int y, PickKind kind, int radius = 8) const;
  // Every visible entity of `kind` inside the box [x0, x1] x [y0, y1] (corners in any order).
  std::vector<PickedItem> pick_box(int x0, int y0, int x1, int y1, PickKind kind) const;

  // The skin face (element, 0-based face) drawn front-most at pixel (x, y), if any; for a line
  // element's bar or a planar element's area the face is kNoFace.
  std::optional<render::SkinFace> face_at(int x, int y) const;
  // Whether a node is drawn on a front-most face (a face holding it is visible within 2 pixels).
  bool node_visible(int node) const;
  // Whether the point (x, y) of the edge between nodes a and b is drawn on a front-most face
  // (one holding both nodes is seen within 2 pixels): the selection outlines' depth test.
  bool edge_point_visible(double x, double y, int a, int b) const;
  // How many skin faces were rasterised.
  std::size_t face_count() const { return faces_.size(); }

 private:
  void build(const render::PixelRect* region);
  int id_at(int x, int y) const;  // index into faces_, or -1
  void rasterise(int id, const std::vector<std::array<double, 3>>& corners);
  void rasterise_segment(int id, const std::array<double, 3>& a, const std::array<double, 3>& b);
  void rasterise_triangle(int id, const std::array<double, 3>& a, const std::array<double, 3>& b,
                          const std::array<double, 3>& c);

  const Scene& scene_;
  int width_ = 0, height_ = 0;
  std::vector<render::SkinFace> faces_;       // every visible skin face, indexed by id
  std::vector<std::vector<int>> face_nodes_;  // every node of each face (model indices)
  std::vector<int> ids_;                      // per pixel: face id or -1
  std::vector<float> depth_;                  // per pixel: normalised depth
};

}  // namespace styk::gui
