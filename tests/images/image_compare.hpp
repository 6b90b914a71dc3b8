// Image comparison with a tolerance (STYLE practice 12): a pixel differs when one channel differs
// by more than `channel_threshold`; two pictures match when at most `allowed_fraction` of the
// pixels differ. On a mismatch the caller writes the actual picture and a difference picture.
#pragma once

#include <string>

#include "styk/render/image.hpp"

namespace styk::render_test {

struct CompareResult {
  bool same_size = false;
  long differing = 0;
  double fraction = 1.0;
  render::Image difference;  // differing pixels red over a faded copy of the actual picture
};

CompareResult compare_images(const render::Image& actual, const render::Image& expected,
                             int channel_threshold);

// Reads the text a TextItem-like label shows: cells of 6 x 7 font pixels at magnification
// `scale` from (x, y), each matched against the glyph table; stops at the first blank cell or
// after `max_chars`. Unmatched cells read '?'.
std::string read_text(const render::Image& image, int x, int y, int scale, int max_chars = 24);

}  // namespace styk::render_test
