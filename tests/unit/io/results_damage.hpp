// Damaging results files on purpose, for the integrity tests of every reader (styk_io, the
// command line, the GUI session): byte flips, truncation, zeroed blocks, values overwritten
// through HDF5 itself. Also a small checksummed results file with every kind of dataset.
#pragma once

#include <cstdint>
#include <string>

namespace styk::damage {

// Where the stored (filtered) bytes of a dataset's first chunk lie in the file.
struct StoredBytes {
  std::uint64_t offset = 0;
  std::uint64_t size = 0;
};
StoredBytes first_chunk(const std::string& file, const std::string& dataset);

void copy_file(const std::string& from, const std::string& to);
std::uint64_t file_size(const std::string& file);
// Inverts every bit of the byte at `offset`.
void flip_byte(const std::string& file, std::uint64_t offset);
void truncate_file(const std::string& file, std::uint64_t size);
void zero_bytes(const std::string& file, std::uint64_t offset, std::uint64_t size);
// Writes `value` at (row, column) of a real dataset through HDF5: the chunk's Fletcher-32 is
// recomputed by HDF5 as it writes, the dataset's crc32 attribute and the digest are not.
void set_value(const std::string& file, const std::string& dataset, std::uint64_t row,
               std::uint64_t column, double value);

// A unit-cube results file (one C3D8, 8 nodes, node ids 1-8, element id 1) with two steps of one
// increment each, every kind of increment dataset filled with finite values: U, RF, S, E at 8
// integration points, the recovered fields, contact output at nodes 5-8. Written with checksums
// by write_results_file; returns `path`.
std::string write_cube_results(const std::string& path);

}  // namespace styk::damage
