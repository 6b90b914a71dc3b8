// A tiny embedded bitmap font: 5x7 glyphs for printable ASCII (32..126), drawn as solid pixel
// blocks. Written for Styk; no font dependency, and deterministic on every rasteriser.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace styk::render {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6;  // columns per character, incl. one of spacing
constexpr int kLineAdvance = 10;  // rows per text line, incl. spacing

// Rows top to bottom; bit 4 of each row is the leftmost column. Characters outside 32..126 map
// to '?'.
const std::array<std::uint8_t, kGlyphHeight>& glyph(char c);

// Width and height in pixels of `text` on one line at integer magnification `scale`.
int text_width(const std::string& text, int scale);
inline int text_height(int scale) { return kGlyphHeight * scale; }

}  // namespace styk::render
