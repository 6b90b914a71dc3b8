#include "image_compare.hpp"

#include <algorithm>
#include <cstdlib>

#include "styk/render/font.hpp"
#include "styk/render/overlay.hpp"

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

std::string read_text(const render::Image& image, render::Typeface& typeface,
                      const render::TextItem& item, int max_chars) {
  const int px = item.pixels;
  const int ascent = typeface.ascent(px), line = typeface.line_height(px);
  const int baseline = item.y + ascent;
  const auto darkness = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return 0.0;
    const auto* p = image.pixel(x, y);
    return 1.0 - std::min({p[0], p[1], p[2]}) / 255.0;
  };
  std::string text;
  int pen = item.x;
  for (int k = 0; k < max_chars; ++k) {
    // The cell of the next character: from the pen, one em wide, the line's height.
    double ink = 0.0;
    for (int y = item.y; y < item.y + line; ++y)
      for (int x = pen; x < pen + px / 2; ++x) ink += darkness(x, y);
    if (ink < 0.5) break;  // blank: the end of the text
    double best = 1e300;
    char found = '?';
    int advance = px / 2;
    for (int c = 33; c <= 126; ++c) {
      const render::GlyphBox box = typeface.glyph(char32_t(c), px);
      const std::shared_ptr<const render::AlphaImage> atlas = typeface.atlas();
      // Squared difference over the glyph's cell between the picture's darkness and the glyph's
      // coverage placed at the pen.
      const int x0 = std::min(pen, pen + box.left),
                x1 = std::max(pen + box.advance, pen + box.left + box.width);
      double score = 0.0;
      for (int y = item.y; y < item.y + line; ++y)
        for (int x = x0; x < x1; ++x) {
          const int gx = x - (pen + box.left), gy = y - (baseline - box.top);
          const double expected = gx >= 0 && gy >= 0 && gx < box.width && gy < box.height
                                      ? atlas->at(box.atlas_x + gx, box.atlas_y + gy) / 255.0
                                      : 0.0;
          const double d = darkness(x, y) - expected;
          score += d * d;
        }
      if (score < best) best = score, found = static_cast<char>(c), advance = box.advance;
    }
    text.push_back(found);
    pen += advance;
  }
  return text;
}

}  // namespace styk::render_test
