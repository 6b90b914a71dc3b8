// BMP through stb_image_write / stb_image (Debian's libstb), and the choice of format by extension.
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "styk/render/image.hpp"

namespace styk::render {

void write_bmp(const std::string& path, const Image& image) {
  std::vector<unsigned char> rgb(std::size_t(image.width) * image.height * 3);
  for (std::size_t p = 0, n = std::size_t(image.width) * image.height; p < n; ++p)
    for (int c = 0; c < 3; ++c) rgb[3 * p + c] = image.rgba[4 * p + c];
  if (!stbi_write_bmp(path.c_str(), image.width, image.height, 3, rgb.data()))
    throw std::runtime_error("cannot write BMP " + path);
}

Image read_bmp(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (!data) throw std::runtime_error("cannot read BMP " + path + ": " + stbi_failure_reason());
  Image image(width, height);
  std::copy_n(data, image.rgba.size(), image.rgba.begin());
  stbi_image_free(data);
  return image;
}

std::string picture_format(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return {};
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == "png" || ext == "bmp" ? ext : std::string();
}

void write_picture(const std::string& path, const Image& image) {
  const std::string format = picture_format(path);
  if (format == "png")
    write_png(path, image);
  else if (format == "bmp")
    write_bmp(path, image);
  else
    throw std::invalid_argument("picture " + path + ": write .png or .bmp");
}

}  // namespace styk::render
