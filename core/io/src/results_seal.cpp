#include "styk/io/results_seal.hpp"

#include <zlib.h>

#include <array>
#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace styk::io {
namespace {

constexpr char kMagic[] = "styk-results-seal ";
constexpr int kVersion = 1;
// "styk-results-seal 1 crc32:xxxxxxxx bytes:dddddddddddddddddddd\n": fixed width, so the number
// of bytes it covers does not depend on the digits of that number.
constexpr std::size_t kLineBytes = 62;
static_assert(kLineBytes < kSealBlockBytes, "the seal's line lies inside the user block");
constexpr unsigned char kHdf5Signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File open_file(const std::string& path, const char* mode) {
  File file(std::fopen(path.c_str(), mode), &std::fclose);
  if (!file) throw std::runtime_error(std::string("cannot be opened: ") + std::strerror(errno));
  return file;
}

std::string seal_line(const ResultsSeal& seal) {
  char line[kLineBytes + 1];
  std::snprintf(line, sizeof line, "%s%d crc32:%08" PRIx32 " bytes:%020" PRIu64 "\n", kMagic,
                kVersion, seal.crc32, seal.bytes);
  return line;
}

// CRC-32 and count of the bytes from `offset` to the end of the file.
ResultsSeal sum_from(std::FILE* file, std::uint64_t offset) {
  if (std::fseek(file, static_cast<long>(offset), SEEK_SET) != 0)
    throw std::runtime_error(std::string("cannot be read: ") + std::strerror(errno));
  ResultsSeal sum;
  uLong crc = crc32_z(0L, Z_NULL, 0);
  std::vector<unsigned char> buffer(std::size_t{1} << 20);
  for (;;) {
    const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), file);
    crc = crc32_z(crc, buffer.data(), n);
    sum.bytes += n;
    if (n < buffer.size()) break;
  }
  if (std::ferror(file))
    throw std::runtime_error(std::string("cannot be read: ") + std::strerror(errno));
  sum.crc32 = static_cast<std::uint32_t>(crc);
  return sum;
}

std::string damaged(const std::string& what) { return what + " \u2014 the file is damaged"; }

// The seal a line states; std::nullopt when the line is not one this build writes.
std::optional<ResultsSeal> parse_line(const std::string& line) {
  int version = 0;
  unsigned crc = 0;
  unsigned long long bytes = 0;
  if (std::sscanf(line.c_str(), "styk-results-seal %d crc32:%8x bytes:%20llu", &version, &crc,
                  &bytes) != 3 ||
      version != kVersion)
    return std::nullopt;
  const ResultsSeal seal{static_cast<std::uint32_t>(crc), bytes};
  if (seal_line(seal) != line) return std::nullopt;  // only the exact form this build writes
  return seal;
}

bool has_hdf5_signature_at(std::FILE* file, std::uint64_t offset) {
  unsigned char bytes[sizeof kHdf5Signature] = {};
  return std::fseek(file, static_cast<long>(offset), SEEK_SET) == 0 &&
         std::fread(bytes, 1, sizeof bytes, file) == sizeof bytes &&
         std::memcmp(bytes, kHdf5Signature, sizeof bytes) == 0;
}

}  // namespace

std::string describe_seal(const ResultsSeal& seal) {
  char text[64];
  std::snprintf(text, sizeof text, "crc32:%08" PRIx32 " over %" PRIu64 " bytes", seal.crc32,
                seal.bytes);
  return text;
}

void seal_results_file(const std::string& path) {
  const File file = open_file(path, "r+b");
  if (!has_hdf5_signature_at(file.get(), kSealBlockBytes))
    throw std::runtime_error("cannot seal " + path + ": HDF5's superblock is not at byte " +
                             std::to_string(kSealBlockBytes));
  const std::string line = seal_line(sum_from(file.get(), kLineBytes));
  if (std::fseek(file.get(), 0, SEEK_SET) != 0 ||
      std::fwrite(line.data(), 1, line.size(), file.get()) != line.size() ||
      std::fflush(file.get()) != 0)
    throw std::runtime_error("cannot seal " + path + ": " + std::strerror(errno));
}

std::optional<ResultsSeal> verify_results_seal(const std::string& path) {
  const File file = open_file(path, "rb");
  std::array<char, kLineBytes> head{};
  const std::size_t read = std::fread(head.data(), 1, head.size(), file.get());
  const std::string line(head.data(), read);
  if (line.compare(0, sizeof kMagic - 1, kMagic) != 0) {
    // No seal. A file whose HDF5 superblock sits behind a user block is one Styk sealed (it
    // writes no other), its seal damaged.
    if (has_hdf5_signature_at(file.get(), 0) || !has_hdf5_signature_at(file.get(), kSealBlockBytes))
      return std::nullopt;
    throw std::runtime_error(
        damaged("its seal (the first line, ahead of HDF5's data) is not one Styk writes"));
  }
  const std::optional<ResultsSeal> sealed = parse_line(line);
  if (!sealed)
    throw std::runtime_error(damaged("its seal (the first line) cannot be read: \"" +
                                     line.substr(0, line.find('\n')) + "\""));
  const ResultsSeal actual = sum_from(file.get(), kLineBytes);
  if (actual.bytes != sealed->bytes)
    throw std::runtime_error(damaged("its seal covers " + std::to_string(sealed->bytes) +
                                     " bytes, but " + std::to_string(actual.bytes) +
                                     " follow it (cut short or extended)"));
  if (actual.crc32 != sealed->crc32) {
    char text[96];
    std::snprintf(text, sizeof text,
                  "whole-file checksum mismatch (sealed crc32:%08" PRIx32
                  ", the bytes give "
                  "crc32:%08" PRIx32 ")",
                  sealed->crc32, actual.crc32);
    throw std::runtime_error(damaged(text));
  }
  return sealed;
}

}  // namespace styk::io
