// The 2D overlay drawn over the model: the contour legend (band colours and the numbers at the
// band limits) and the title block (model, step, increment, field, averaging, scale factor), as
// coloured triangles in pixel coordinates, with text from the embedded bitmap font.
#pragma once

#include <string>
#include <vector>

#include "styk/render/color.hpp"
#include "styk/render/color_scale.hpp"

namespace styk::render {

struct OverlayVertex {
  float x, y;  // pixels, origin at the top-left corner of the picture
  float color[3];
};

struct TextItem {
  std::string text;
  int x = 0, y = 0;  // top-left pixel of the first glyph
  int scale = 1;     // pixels per font pixel
};

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;  // top-left origin
};

struct Overlay {
  std::vector<OverlayVertex> triangles;  // 3 per triangle
  std::vector<TextItem> texts;           // every text drawn (already part of `triangles`)
  std::vector<TextItem> legend_labels;   // the band-limit numbers, top (max) to bottom (min);
                                         // for a discrete scale the band names, top to bottom
  PixelRect legend;                      // area of the legend (empty without a field)
  PixelRect title;                       // area of the title block
  PixelRect model;                       // what is left for the model
};

struct OverlayContent {
  std::vector<std::string> title_lines;  // drawn bottom-left, first line on top
  const ColorScale* colors = nullptr;    // legend when set
  std::string legend_heading;            // e.g. "S.mises (II)"
};

// Magnification of the font for a picture of this height (3 at 1200 rows).
int text_scale_for(int height);

Overlay build_overlay(const OverlayContent& content, int width, int height);

}  // namespace styk::render
