#include "image_compare.hpp"

#include <algorithm>
#include <cstdlib>

#include "styk/render/font.hpp"

namespace styk::render_test {

CompareResult compare_images(const render::Image& actual, const render::Image& expected,
                             int channel_threshold) {
  CompareResult result;
  result.same_size = actual.width == expected.width && actual.height == expected.height;
  if (!result.same_size) return result;
  result.difference = render::Image(actual.width, actual.height);
  for (int y = 0; y < actual.height; ++y)
    for (int x = 0; x < actual.width; ++x) {
      const auto* a = actual.pixel(x, y);
      const auto* e = expected.pixel(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(e[c])));
      auto* d = result.difference.pixel(x, y);
      if (worst > channel_threshold) {
        ++result.differing;
        d[0] = 255, d[1] = 0, d[2] = 0;
      } else {
        for (int c = 0; c < 3; ++c) d[c] = static_cast<std::uint8_t>(191 + a[c] / 4);
      }
      d[3] = 255;
    }
  result.fraction = double(result.differing) / (double(actual.width) * actual.height);
  return result;
}

std::string read_text(const render::Image& image, int x, int y, int scale, int max_chars) {
  std::string text;
  for (int cell = 0; cell < max_chars; ++cell) {
    std::array<std::uint8_t, render::kGlyphHeight> rows{};
    const int x0 = x + cell * render::kGlyphAdvance * scale;
    bool any = false;
    for (int r = 0; r < render::kGlyphHeight; ++r)
      for (int c = 0; c < render::kGlyphWidth; ++c) {
        const int px = x0 + c * scale + scale / 2, py = y + r * scale + scale / 2;
        if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
        const auto* p = image.pixel(px, py);
        if (p[0] < 128 && p[1] < 128 && p[2] < 128) rows[r] |= 0x10 >> c, any = true;
      }
    if (!any) break;
    char found = '?';
    for (int ch = 33; ch <= 126; ++ch)
      if (render::glyph(static_cast<char>(ch)) == rows) {
        found = static_cast<char>(ch);
        break;
      }
    text.push_back(found);
  }
  return text;
}

}  // namespace styk::render_test
