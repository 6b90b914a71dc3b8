// File-level integrity of a results file: the list of every dataset it holds (found by walking the
// file, not from a list of field names), the digest over that list that the writer stores as the
// root attribute `digest`, and its verification by readers. The per-dataset rules (finite values,
// Fletcher-32, crc32) are in h5_integrity.hpp.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "h5_util.hpp"

namespace styk::io {

inline constexpr const char* kDigestAttribute = "digest";

// One dataset of the file, as the digest sees it.
struct DatasetEntry {
  std::string path;                  // "/steps/step_1/increment_1/U"
  std::vector<std::uint64_t> shape;  // dimensions
  bool has_crc = false;
  std::uint32_t crc = 0;          // its crc32 attribute
  bool fletcher32 = false;        // chunks carry HDF5's Fletcher-32 filter
  bool is_float = false;          // class H5T_FLOAT
  std::uint64_t value_bytes = 0;  // elements x element size
};

// Every dataset under the root, sorted by path. Throws (h5::fail) when HDF5 cannot walk the file.
std::vector<DatasetEntry> list_datasets(hid_t file);

// The digest of a listing: CRC-32 of one text line per dataset, "<path> <d0>x<d1> <crc32 as 8
// lower-case hex digits>\n", in path order, written "crc32:<8 hex digits>" (docs/results.md shows
// how to recompute it with h5py and zlib).
std::string digest_of(const std::vector<DatasetEntry>& datasets);

// Creates a results file with checksums: HDF5 1.10 file format (its metadata carries HDF5's own
// checksums, which 1.8's does not) and the root attribute `checksums` that tells the dataset
// helpers to checksum everything written to it. With `seal_block`, HDF5 reserves the user block
// the whole-file seal is written into once the file is closed (styk/io/results_seal.hpp).
h5::Handle create_checksummed_file(const std::string& path, bool seal_block);

// Writes the root attribute `digest` over every dataset written. Call last, before closing.
void write_digest(hid_t file);

// What a reader learns about the file's integrity layer.
enum class FileIntegrity {
  Checksummed,  // the digest matches every dataset's crc32: each read then verifies its dataset
  Legacy,       // written before checksums: nothing to verify against
};

// Verifies the digest against the datasets' crc32 attributes (which each read then compares with
// the values). Throws h5::DamagedError when a dataset lacks its checksum or the digest does not
// match (a dataset added, lost, renamed or replaced), std::runtime_error for an unknown scheme.
FileIntegrity verify_digest(hid_t file);

}  // namespace styk::io
