// The 2D overlay drawn over the model: the contour legend (band colours and the numbers at the
// band limits), the title block (model, step, increment, field, averaging, scale factor, notes),
// optional plot axes (the unrolled contact map), and numbers anchored at points of the model
// (node and element labels, placed by the renderer where their point is seen). Shapes are
// coloured triangles in pixel coordinates; text is anti-aliased glyph quads from a Typeface atlas.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "styk/render/color.hpp"
#include "styk/render/color_scale.hpp"
#include "styk/render/font.hpp"

namespace styk::render {

struct OverlayVertex {
  float x, y;  // pixels, origin at the top-left corner of the picture
  float color[3];
};

struct TextItem {
  std::string text;
  int x = 0, y = 0;  // top-left corner of its line, pixels
  int pixels = 12;   // font size: em height in pixels
};

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;  // top-left origin
};

// A number (or short text) anchored at a point of the model: a node or element label, or an
// integration-point value. The renderer draws it only where the point is not hidden by a face
// (depth test against the drawn picture) and where it does not cover a label drawn before it.
struct SceneLabel {
  std::array<float, 3> position{};  // relative to FrameGeometry::origin, as drawn
  std::string text;                 // printable ASCII
  Rgb color;
  bool marker = false;  // a small square at the anchor (nodes)
};

struct Overlay {
  std::vector<OverlayVertex> triangles;  // 3 per triangle
  std::vector<TextVertex> glyphs;        // text quads (6 vertices per glyph), drawn after triangles
  std::shared_ptr<const AlphaImage> atlas;  // the coverage the glyph quads (and labels) sample
  std::vector<TextItem> texts;              // every text drawn (already part of `glyphs`)
  std::vector<TextItem> legend_labels;      // the band-limit numbers, top (max) to bottom (min);
                                            // for a discrete scale the band names, top to bottom
  PixelRect legend;                         // area of the legend (empty without a field)
  PixelRect title;                          // area of the title block
  PixelRect model;                          // what is left for the model
  // Scene labels and the printable-ASCII glyphs they are drawn with (in `atlas`).
  std::vector<SceneLabel> labels;
  int label_pixels = 0;
  std::array<GlyphBox, 95> label_glyphs{};  // characters 32..126
};

struct OverlayContent {
  std::vector<std::string> title_lines;  // drawn bottom-left, first line on top
  const ColorScale* colors = nullptr;    // legend when set
  std::string legend_heading;            // e.g. "S.mises (II)"
  bool label_glyphs = false;             // fill Overlay::label_glyphs (scene labels follow)
};

// Font size of the overlay's text for a picture of this height (24 pixels at 1200 rows, at least
// 11).
int text_pixels_for(int height);
// The unit of drawn points and bars for a picture of this height: 1 up to 599 rows, 3 at 1200.
int pixel_scale_for(int height);

Overlay build_overlay(const OverlayContent& content, int width, int height, Typeface& typeface);

// Appends `text` to the overlay's glyphs (after build_overlay, e.g. axis labels) and records it in
// `texts`; call refresh_atlas() when done.
void add_overlay_text(Overlay& overlay, Typeface& typeface, const TextItem& item, const Rgb& ink);
void refresh_atlas(Overlay& overlay, Typeface& typeface);

}  // namespace styk::render
