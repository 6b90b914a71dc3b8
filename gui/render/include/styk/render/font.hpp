// Text of the pictures: glyphs rasterised anti-aliased by FreeType from a packaged TrueType font
// (DejaVu Sans, Debian's fonts-dejavu-core) into an 8-bit coverage atlas, laid out on whole
// pixels, and drawn by the GL as textured quads blended over the picture. FreeType's types stay in
// font.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "styk/render/color.hpp"

namespace styk::render {

// 8-bit coverage (0 = paper, 255 = ink), rows top-down: the atlas the text is drawn from.
struct AlphaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> alpha;  // width * height
  std::uint8_t at(int x, int y) const { return alpha[std::size_t(y) * width + x]; }
};

// One character at one pixel size: its coverage box relative to the pen (the pen sits on the
// baseline; the box spans x = pen + left .. + width, y = baseline - top .. + height, y down), where
// the box lies in the atlas, and how far the pen moves after it (whole pixels: glyphs are hinted
// and placed on the pixel grid, so equal text gives equal pixels wherever it is drawn).
struct GlyphBox {
  int left = 0, top = 0, width = 0, height = 0;
  int atlas_x = 0, atlas_y = 0;
  int advance = 0;
};

// A corner of a textured text quad: pixel position (top-left origin), atlas position in texels
// (u, v; the atlas may grow after the quad is laid out, so not normalised) and ink colour.
struct TextVertex {
  float x, y;
  float u, v;
  float color[3];
};

// The font file Styk draws with: DejaVuSans.ttf of fonts-dejavu-core, located at configure time.
std::string default_font_file();

class Typeface {
 public:
  // Loads the font. Throws std::runtime_error naming the file when FreeType cannot open it.
  explicit Typeface(const std::string& font_file = default_font_file());
  ~Typeface();
  Typeface(const Typeface&) = delete;
  Typeface& operator=(const Typeface&) = delete;

  // The glyph of Unicode code point `code` at `pixels` (em height in pixels), rasterised into the
  // atlas on first use. A code point the font lacks draws as its replacement box.
  const GlyphBox& glyph(char32_t code, int pixels);
  int ascent(int pixels);       // baseline below the top of a line
  int line_height(int pixels);  // baseline to baseline
  // Width of UTF-8 `text` on one line: the sum of its advances.
  int text_width(const std::string& text, int pixels);
  // Appends two triangles per visible glyph of UTF-8 `text`, its line's top-left corner at (x, y).
  void layout(const std::string& text, int x, int y, int pixels, const Rgb& ink,
              std::vector<TextVertex>& out);
  // The atlas as it is now: an immutable snapshot that pictures keep; glyphs added later go to a
  // copy, so a snapshot never changes under a picture that holds it.
  std::shared_ptr<const AlphaImage> atlas();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The code points of UTF-8 text (a malformed byte reads as U+FFFD).
std::vector<char32_t> decode_utf8(const std::string& text);

}  // namespace styk::render
