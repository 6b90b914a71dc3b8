// FreeType behind the Typeface: one FT_Library and FT_Face per Typeface (no global state), glyphs
// rendered as 8-bit anti-aliased coverage with light hinting (vertical only: the shapes stay
// faithful, the advances are whole pixels), packed into a shelf atlas that grows downwards.
#include "styk/render/font.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace styk::render {
namespace {

constexpr int kAtlasWidth = 512;
constexpr int kPadding = 1;  // empty texels around each glyph: linear sampling never bleeds

}  // namespace

std::string default_font_file() { return STYK_FONT_FILE; }

std::vector<char32_t> decode_utf8(const std::string& text) {
  std::vector<char32_t> codes;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const int extra = byte < 0x80           ? 0
                      : (byte >> 5) == 0x6  ? 1
                      : (byte >> 4) == 0xE  ? 2
                      : (byte >> 3) == 0x1E ? 3
                                            : -1;
    bool ok = extra >= 0 && i + std::size_t(extra) < text.size();
    char32_t code = extra <= 0 ? byte : byte & (0x3F >> extra);
    for (int k = 1; ok && k <= extra; ++k) {
      const auto next = static_cast<unsigned char>(text[i + std::size_t(k)]);
      ok = (next >> 6) == 0x2;
      code = (code << 6) | (next & 0x3F);
    }
    codes.push_back(ok ? code : char32_t(0xFFFD));
    i += ok ? std::size_t(extra) + 1 : 1;
  }
  return codes;
}

struct Typeface::Impl {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  int face_pixels = 0;  // the size FT_Set_Pixel_Sizes was last called with
  std::map<std::pair<char32_t, int>, GlyphBox> glyphs;
  std::map<int, std::pair<int, int>> metrics;  // pixels -> ascent, line height
  std::shared_ptr<AlphaImage> atlas = std::make_shared<AlphaImage>();
  int shelf_x = 0, shelf_y = 0, shelf_height = 0;

  ~Impl() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }

  void set_size(int pixels) {
    if (pixels == face_pixels) return;
    if (FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixels)) != 0)
      throw std::runtime_error("font: cannot set a size of " + std::to_string(pixels) + " pixels");
    face_pixels = pixels;
  }

  // A snapshot held by a picture is never written: copy it first.
  AlphaImage& writable_atlas() {
    if (atlas.use_count() > 1) atlas = std::make_shared<AlphaImage>(*atlas);
    return *atlas;
  }

  // Reserves a width x height box on the shelves; grows the atlas downwards when needed.
  std::pair<int, int> reserve(int width, int height) {
    if (shelf_x + width + kPadding > kAtlasWidth) {
      shelf_y += shelf_height + kPadding;
      shelf_x = 0, shelf_height = 0;
    }
    const int x = shelf_x + kPadding, y = shelf_y + kPadding;
    shelf_x = x + width;
    shelf_height = std::max(shelf_height, height + kPadding);
    AlphaImage& image = writable_atlas();
    if (image.width == 0) image.width = kAtlasWidth;
    int rows = std::max(image.height, 64);
    while (rows < y + height + kPadding) rows *= 2;
    if (rows != image.height)
      image.alpha.resize(std::size_t(image.width) * rows, 0), image.height = rows;
    return {x, y};
  }

  GlyphBox rasterise(char32_t code, int pixels) {
    set_size(pixels);
    FT_UInt index = FT_Get_Char_Index(face, code);
    if (FT_Load_Glyph(face, index, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) != 0)
      throw std::runtime_error("font: cannot render code point " + std::to_string(code));
    const FT_GlyphSlot slot = face->glyph;
    const FT_Bitmap& bitmap = slot->bitmap;
    GlyphBox box;
    box.left = slot->bitmap_left;
    box.top = slot->bitmap_top;
    box.width = static_cast<int>(bitmap.width);
    box.height = static_cast<int>(bitmap.rows);
    box.advance = static_cast<int>((slot->advance.x + 32) >> 6);
    if (box.width > 0 && box.height > 0) {
      const auto [x, y] = reserve(box.width, box.height);
      box.atlas_x = x, box.atlas_y = y;
      AlphaImage& image = writable_atlas();
      for (int r = 0; r < box.height; ++r)
        std::copy_n(bitmap.buffer + std::ptrdiff_t(r) * bitmap.pitch, box.width,
                    image.alpha.begin() + std::ptrdiff_t(y + r) * image.width + x);
    }
    return box;
  }
};

Typeface::Typeface(const std::string& font_file) : impl_(std::make_unique<Impl>()) {
  if (FT_Init_FreeType(&impl_->library) != 0)
    throw std::runtime_error("font: FreeType does not start");
  if (FT_New_Face(impl_->library, font_file.c_str(), 0, &impl_->face) != 0)
    throw std::runtime_error("font: cannot read " + font_file +
                             " (Debian package fonts-dejavu-core, scripts/install-deps.sh)");
}

Typeface::~Typeface() = default;

const GlyphBox& Typeface::glyph(char32_t code, int pixels) {
  const auto key = std::make_pair(code, pixels);
  auto it = impl_->glyphs.find(key);
  if (it == impl_->glyphs.end())
    it = impl_->glyphs.emplace(key, impl_->rasterise(code, pixels)).first;
  return it->second;
}

int Typeface::ascent(int pixels) {
  auto it = impl_->metrics.find(pixels);
  if (it == impl_->metrics.end()) {
    impl_->set_size(pixels);
    const FT_Size_Metrics& m = impl_->face->size->metrics;
    it =
        impl_->metrics
            .emplace(pixels, std::make_pair(int((m.ascender + 63) >> 6), int((m.height + 63) >> 6)))
            .first;
  }
  return it->second.first;
}

int Typeface::line_height(int pixels) {
  ascent(pixels);
  return impl_->metrics.at(pixels).second;
}

int Typeface::text_width(const std::string& text, int pixels) {
  int width = 0;
  for (char32_t code : decode_utf8(text)) width += glyph(code, pixels).advance;
  return width;
}

void Typeface::layout(const std::string& text, int x, int y, int pixels, const Rgb& ink,
                      std::vector<TextVertex>& out) {
  const int baseline = y + ascent(pixels);
  int pen = x;
  for (char32_t code : decode_utf8(text)) {
    const GlyphBox box = glyph(code, pixels);  // a copy: the map may grow below
    if (box.width > 0 && box.height > 0) {
      const float x0 = float(pen + box.left), y0 = float(baseline - box.top);
      const float x1 = x0 + float(box.width), y1 = y0 + float(box.height);
      // Atlas coordinates in texels (the shader divides by the atlas size, which may still grow).
      const float u0 = float(box.atlas_x), v0 = float(box.atlas_y);
      const float u1 = u0 + float(box.width), v1 = v0 + float(box.height);
      const TextVertex a{x0, y0, u0, v0, {ink.r, ink.g, ink.b}},
          b{x1, y0, u1, v0, {ink.r, ink.g, ink.b}}, c{x1, y1, u1, v1, {ink.r, ink.g, ink.b}},
          d{x0, y1, u0, v1, {ink.r, ink.g, ink.b}};
      out.insert(out.end(), {a, b, c, a, c, d});
    }
    pen += box.advance;
  }
}

std::shared_ptr<const AlphaImage> Typeface::atlas() { return impl_->atlas; }

}  // namespace styk::render
