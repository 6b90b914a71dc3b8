// An RGBA8 picture, rows top-down, and its file forms: PNG (libpng) and 24-bit BMP
// (stb_image_write; the thesis' picture format). No GL, no windowing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace styk::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, first row = top of the picture

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (std::size_t(y) * width + x) * 4;
  }
  std::uint8_t* pixel(int x, int y) { return rgba.data() + (std::size_t(y) * width + x) * 4; }
};

// Throw std::runtime_error naming the file on failure.
void write_png(const std::string& path, const Image& image);
Image read_png(const std::string& path);
// 24 bits per pixel, uncompressed (alpha is dropped: pictures are opaque).
void write_bmp(const std::string& path, const Image& image);
Image read_bmp(const std::string& path);

// The picture formats by file extension: ".png" or ".bmp" (case-insensitive); empty for another.
std::string picture_format(const std::string& path);
// Writes PNG or BMP by the extension; std::invalid_argument for another extension.
void write_picture(const std::string& path, const Image& image);

}  // namespace styk::render
