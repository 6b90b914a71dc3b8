// Image comparison with a tolerance (STYLE practice 12): a pixel differs when one channel differs
// by more than `channel_threshold`; two pictures match when at most `allowed_fraction` of the
// pixels differ. On a mismatch the caller writes the actual picture and a difference picture.
#pragma once

#include <string>

#include "styk/render/font.hpp"
#include "styk/render/image.hpp"
#include "styk/render/overlay.hpp"

namespace styk::render_test {

struct CompareResult {
  bool same_size = false;
  long differing = 0;
  double fraction = 1.0;
  render::Image difference;  // differing pixels red over a faded copy of the actual picture
};

CompareResult compare_images(const render::Image& actual, const render::Image& expected,
                             int channel_threshold);

// Reads back the text a TextItem shows in the picture (dark ink on light paper): from the item's
// pen position, the printable ASCII character whose glyph (the renderer's typeface, same size)
// best matches the picture's darkness over its cell, then the next at that glyph's advance; stops
// at the first blank cell or after `max_chars`.
std::string read_text(const render::Image& image, render::Typeface& typeface,
                      const render::TextItem& item, int max_chars = 24);

}  // namespace styk::render_test
