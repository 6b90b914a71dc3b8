// The whole-file seal of a results file. Styk creates its results files with a 512-byte HDF5 user
// block (HDF5's superblock follows it) and, once HDF5 has closed the file, writes into its first
// line the CRC-32 and the length of every byte after that line, to the end of the file. Readers
// verify it before HDF5 reads anything: a damaged file is refused at once, without HDF5 parsing
// damaged metadata (which can over-read buffers or allocate gigabytes inside the library).
// Files without a seal (HDF5's superblock at byte 0: written before Styk sealed its files) are
// left to the per-dataset checks. HDF5 stays out of this header.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace styk::io {

// The user block HDF5 reserves ahead of its superblock (its smallest size).
inline constexpr std::uint64_t kSealBlockBytes = 512;

// The seal's line: "styk-results-seal 1 crc32:<8 hex digits> bytes:<20 decimal digits>\n".
struct ResultsSeal {
  std::uint32_t crc32 = 0;  // zlib's CRC-32 of the bytes after the line
  std::uint64_t bytes = 0;  // how many bytes follow the line
};

// "crc32:1a2b3c4d over 75 803 bytes" as `styk check` prints it.
std::string describe_seal(const ResultsSeal& seal);

// Writes the seal of `path`, a file HDF5 created with a kSealBlockBytes user block and has closed.
// Throws std::runtime_error (the cause from errno) when it cannot read or write the file.
void seal_results_file(const std::string& path);

// The seal of `path` once verified against every byte after it; std::nullopt when the file has no
// seal (it starts with HDF5's signature, or is no HDF5 file at all: opening it says which).
// Throws std::runtime_error ending "— the file is damaged" when the seal is broken, the file is
// longer or shorter than its seal says, or the bytes do not give the sealed CRC-32.
std::optional<ResultsSeal> verify_results_seal(const std::string& path);

}  // namespace styk::io
