#include "session/apng.hpp"

#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace styk::gui {
namespace {

using Bytes = std::vector<std::uint8_t>;

void put32(Bytes& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}
void put16(Bytes& out, std::uint16_t v) {
  out.push_back(std::uint8_t(v >> 8));
  out.push_back(std::uint8_t(v));
}

// A chunk: length, type, data, CRC-32 of type and data (PNG spec §5.3).
void chunk(std::ofstream& out, const char (&type)[5], const Bytes& data) {
  Bytes head;
  put32(head, std::uint32_t(data.size()));
  const Bytes type_bytes(type, type + 4);
  head.insert(head.end(), type_bytes.begin(), type_bytes.end());
  uLong crc = crc32(0L, Z_NULL, 0);
  crc = crc32(crc, type_bytes.data(), 4);
  if (!data.empty()) crc = crc32(crc, data.data(), uInt(data.size()));
  Bytes tail;
  put32(tail, std::uint32_t(crc));
  out.write(reinterpret_cast<const char*>(head.data()), std::streamsize(head.size()));
  out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
  out.write(reinterpret_cast<const char*>(tail.data()), std::streamsize(tail.size()));
}

// The zlib stream of an image: each row as filter type 0 (none) followed by its RGBA bytes.
Bytes compressed_rows(const render::Image& image) {
  const std::size_t row = std::size_t(image.width) * 4;
  Bytes raw;
  raw.reserve((row + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), image.pixel(0, y), image.pixel(0, y) + row);
  }
  uLongf size = compressBound(uLong(raw.size()));
  Bytes packed(size);
  if (compress2(packed.data(), &size, raw.data(), uLong(raw.size()), 6) != Z_OK)
    throw std::runtime_error("zlib could not compress an animation frame");
  packed.resize(size);
  return packed;
}

Bytes frame_control(std::uint32_t sequence, const render::Image& image, int delay_ms) {
  Bytes d;
  put32(d, sequence);
  put32(d, std::uint32_t(image.width));
  put32(d, std::uint32_t(image.height));
  put32(d, 0);  // x offset
  put32(d, 0);  // y offset
  put16(d, std::uint16_t(delay_ms));
  put16(d, 1000);  // delay = delay_ms / 1000 s
  d.push_back(0);  // dispose: none (every frame covers the whole picture)
  d.push_back(0);  // blend: source (replace)
  return d;
}

}  // namespace

void write_apng(const std::string& path, const std::vector<render::Image>& frames, int delay_ms) {
  if (frames.empty()) throw std::invalid_argument("an animation needs at least one frame");
  for (const render::Image& f : frames)
    if (f.width != frames[0].width || f.height != frames[0].height || f.width <= 0 ||
        f.height <= 0 || f.rgba.size() != std::size_t(f.width) * f.height * 4)
      throw std::invalid_argument("animation frames must all have the same, non-zero size");
  if (delay_ms < 1 || delay_ms > 65535) throw std::invalid_argument("frame delay out of range");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path);
  const std::uint8_t signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  out.write(reinterpret_cast<const char*>(signature), 8);
  Bytes header;
  put32(header, std::uint32_t(frames[0].width));
  put32(header, std::uint32_t(frames[0].height));
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, filter 0, no interlace
  chunk(out, "IHDR", header);
  Bytes control;
  put32(control, std::uint32_t(frames.size()));
  put32(control, 0);  // loop forever
  chunk(out, "acTL", control);
  std::uint32_t sequence = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    chunk(out, "fcTL", frame_control(sequence++, frames[i], delay_ms));
    const Bytes data = compressed_rows(frames[i]);
    if (i == 0) {
      chunk(out, "IDAT", data);  // the first frame is the default image
    } else {
      Bytes frame_data;
      put32(frame_data, sequence++);
      frame_data.insert(frame_data.end(), data.begin(), data.end());
      chunk(out, "fdAT", frame_data);
    }
  }
  chunk(out, "IEND", {});
  out.flush();
  if (!out) throw std::runtime_error("error while writing " + path);
}

}  // namespace styk::gui
