// Private: which scene labels (node and element numbers, values at points) are drawn, and where.
// The anchor is projected with the view's camera; the label is drawn when the anchor is not behind
// the drawn picture at its pixel or one of the 8 around it (the depth the renderer read back),
// and when its box covers no label placed before it (first come, first placed).
#pragma once

#include <vector>

#include "styk/render/frame.hpp"

namespace styk::render {

struct PlacedLabels {
  std::vector<OverlayVertex> markers;  // the anchors' squares (labels with `marker`)
  std::vector<TextVertex> glyphs;      // the text, each glyph over a paper-coloured halo
  int placed = 0;                      // labels drawn
};

// `depth`: window depth (0 near .. 1 far) of the view's model area, rows bottom-up.
PlacedLabels place_labels(const FrameView& view, const std::vector<float>& depth);

}  // namespace styk::render
