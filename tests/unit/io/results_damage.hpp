// Damaging results files on purpose, for the integrity tests of every reader (styk_io, the
// command line, the GUI session): byte flips, truncation, zeroed blocks, values overwritten
// through HDF5 itself. Also a small checksummed results file with every kind of dataset.
// A sealed file (styk/io/results_seal.hpp) refuses any damage at its seal, before HDF5 reads it.
// To reach the checks beneath the seal (HDF5's, the per-dataset checksums, the digest, finite
// values), the helpers by default seal the damaged file again, as if the damage had come before
// the file was sealed; Seal::Break leaves the seal as it was (the seal's own tests).
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

// Reseal: a sealed file is sealed again after the damage (when HDF5's superblock is still where
// the seal expects it); Break: the seal stays as it was, and no longer matches.
enum class Seal { Reseal, Break };

void copy_file(const std::string& from, const std::string& to);
std::uint64_t file_size(const std::string& file);
// Inverts every bit of the byte at `offset`.
void flip_byte(const std::string& file, std::uint64_t offset, Seal seal = Seal::Reseal);
void truncate_file(const std::string& file, std::uint64_t size, Seal seal = Seal::Reseal);
void zero_bytes(const std::string& file, std::uint64_t offset, std::uint64_t size,
                Seal seal = Seal::Reseal);
// Writes `value` at (row, column) of a real dataset through HDF5: the chunk's Fletcher-32 is
// recomputed by HDF5 as it writes, the dataset's crc32 attribute and the digest are not.
void set_value(const std::string& file, const std::string& dataset, std::uint64_t row,
               std::uint64_t column, double value, Seal seal = Seal::Reseal);
// Seals a file that was sealed again, after it was changed through HDF5 by the test itself.
void reseal(const std::string& file);

// A unit-cube results file (one C3D8, 8 nodes, node ids 1-8, element id 1) with two steps of one
// increment each, every kind of increment dataset filled with finite values: U, RF, S, E at 8
// integration points, the recovered fields, contact output at nodes 5-8. Written with checksums
// by write_results_file; returns `path`.
std::string write_cube_results(const std::string& path);

}  // namespace styk::damage
