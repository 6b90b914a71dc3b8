#include "label_placement.hpp"

#include <algorithm>
#include <cmath>

namespace styk::render {
namespace {

// An anchor on a drawn face lies at most this far behind it (window depth): the faces are pushed
// back by the polygon offset, the anchors sit on their tessellation's grid points.
constexpr float kDepthTolerance = 1e-3f;

class Occupancy {
 public:
  Occupancy(int width, int height)
      : width_(width), height_(height), used_(std::size_t(width) * height, 0) {}
  bool free(int x0, int y0, int x1, int y1) const {
    for (int y = std::max(0, y0); y < std::min(height_, y1); ++y)
      for (int x = std::max(0, x0); x < std::min(width_, x1); ++x)
        if (used_[std::size_t(y) * width_ + x]) return false;
    return true;
  }
  void take(int x0, int y0, int x1, int y1) {
    for (int y = std::max(0, y0); y < std::min(height_, y1); ++y)
      for (int x = std::max(0, x0); x < std::min(width_, x1); ++x)
        used_[std::size_t(y) * width_ + x] = 1;
  }

 private:
  int width_, height_;
  std::vector<char> used_;
};

void add_glyph_quad(std::vector<TextVertex>& out, const GlyphBox& box, float x0, float y0,
                    const Rgb& c) {
  const float x1 = x0 + float(box.width), y1 = y0 + float(box.height);
  const float u0 = float(box.atlas_x), v0 = float(box.atlas_y);
  const float u1 = u0 + float(box.width), v1 = v0 + float(box.height);
  const TextVertex a{x0, y0, u0, v0, {c.r, c.g, c.b}}, b{x1, y0, u1, v0, {c.r, c.g, c.b}},
      d{x1, y1, u1, v1, {c.r, c.g, c.b}}, e{x0, y1, u0, v1, {c.r, c.g, c.b}};
  out.insert(out.end(), {a, b, d, a, d, e});
}

}  // namespace

PlacedLabels place_labels(const FrameView& view, const std::vector<float>& depth) {
  PlacedLabels out;
  const Overlay& o = view.overlay;
  const PixelRect& area = o.model;
  if (o.labels.empty() || o.label_pixels <= 0 || area.width <= 0 || area.height <= 0) return out;
  const auto depth_at = [&](int x, int y) {  // x, y inside the area, top-left origin
    return depth[std::size_t(area.height - 1 - y) * area.width + x];
  };
  const int ascent = o.label_pixels;  // the glyph boxes' tops lie within one em above the baseline
  const int gap = std::max(2, o.label_pixels / 4);
  Occupancy taken(view.width, view.height);
  for (const SceneLabel& label : o.labels) {
    const std::array<float, 3> ndc = project(view.camera, label.position);
    if (!(std::abs(ndc[0]) <= 1.0f && std::abs(ndc[1]) <= 1.0f && std::abs(ndc[2]) <= 1.0f))
      continue;
    const float sx = (ndc[0] + 1.0f) * 0.5f * float(area.width);
    const float sy = (1.0f - ndc[1]) * 0.5f * float(area.height);
    const int px = std::min(area.width - 1, int(sx)), py = std::min(area.height - 1, int(sy));
    const float anchor = 0.5f * (ndc[2] + 1.0f);
    bool seen = false;
    for (int dy = -1; dy <= 1 && !seen; ++dy)
      for (int dx = -1; dx <= 1 && !seen; ++dx) {
        const int x = px + dx, y = py + dy;
        if (x >= 0 && y >= 0 && x < area.width && y < area.height)
          seen = anchor <= depth_at(x, y) + kDepthTolerance;
      }
    if (!seen) continue;
    // The text sits up and to the right of the anchor, on whole pixels.
    int width = 0;
    for (char c : label.text)
      if (c >= 32 && c <= 126) width += o.label_glyphs[std::size_t(c - 32)].advance;
    const int ax = area.x + int(std::lround(sx)), ay = area.y + int(std::lround(sy));
    const int x0 = ax + gap, baseline = ay - gap;
    const int box_x0 = x0 - 1, box_y0 = baseline - ascent - 1, box_x1 = x0 + width + 1,
              box_y1 = baseline + gap;
    if (!taken.free(box_x0, box_y0, box_x1, box_y1)) continue;
    taken.take(box_x0, box_y0, box_x1, box_y1);
    ++out.placed;
    if (label.marker) {
      const float h = std::max(1.5f, o.label_pixels / 6.0f);
      const Rgb& c = label.color;
      const OverlayVertex a{ax - h, ay - h, {c.r, c.g, c.b}}, b{ax + h, ay - h, {c.r, c.g, c.b}},
          d{ax + h, ay + h, {c.r, c.g, c.b}}, e{ax - h, ay + h, {c.r, c.g, c.b}};
      out.markers.insert(out.markers.end(), {a, b, d, a, d, e});
    }
    // A halo of paper around the glyphs keeps them readable over contour colours.
    for (int pass = 0; pass < 2; ++pass) {
      int pen = x0;
      for (char c : label.text) {
        if (c < 32 || c > 126) continue;
        const GlyphBox& box = o.label_glyphs[std::size_t(c - 32)];
        if (box.width > 0) {
          const float gx = float(pen + box.left), gy = float(baseline - box.top);
          if (pass == 0) {
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx)
                if (dx || dy) add_glyph_quad(out.glyphs, box, gx + dx, gy + dy, kBackground);
          } else {
            add_glyph_quad(out.glyphs, box, gx, gy, label.color);
          }
        }
        pen += box.advance;
      }
    }
  }
  return out;
}

}  // namespace styk::render
