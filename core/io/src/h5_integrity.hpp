// The integrity rules every dataset of a results file goes through, written or read, whatever its
// name: values must be finite numbers, stored chunks carry HDF5's Fletcher-32 checksum, and the
// dataset's attribute `crc32` holds the CRC-32 of its values. Nothing here knows a field by name,
// so a dataset added to the schema later is covered without being listed anywhere.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace styk::io::h5 {

// Root attribute of a file written with checksums, and its only value so far.
inline constexpr const char* kChecksumsAttribute = "checksums";
inline constexpr const char* kChecksumsScheme = "fletcher32+crc32";
// Per-dataset attribute: CRC-32 of the dataset's values (int64 holding 0 .. 2^32 - 1).
inline constexpr const char* kCrcAttribute = "crc32";

// zlib's CRC-32 (the ISO-HDLC polynomial; what Python's zlib.crc32 computes) of `bytes` bytes.
// On a little-endian host the bytes in memory are those of the file (little-endian int64 and
// float64, fixed-length strings), so the value is the same the file holds.
std::uint32_t crc32_of(const void* data, std::uint64_t bytes);

// The first NaN or infinity of a rows x max(cols, 1) array of doubles, and how many there are.
struct NonFiniteValue {
  std::uint64_t rows = 0, cols = 0;  // the array's shape (cols 0: one-dimensional)
  std::uint64_t count = 0;           // 0: every value is finite
  std::uint64_t row = 0;
  std::uint64_t column = 0;
  double value = 0.0;
};
NonFiniteValue find_non_finite(const double* values, std::uint64_t rows, std::uint64_t cols);

// A dataset (or attribute) holds values that are not numbers. `object` is the HDF5 path of the
// dataset, or of the object holding the attribute with "@name" appended.
class NonFiniteError : public std::runtime_error {
 public:
  NonFiniteError(std::string object, const NonFiniteValue& first);
  const std::string& object() const { return object_; }
  const NonFiniteValue& first() const { return first_; }

 private:
  std::string object_;
  NonFiniteValue first_;
};

// The stored bytes are not what was written: a checksum does not match, or HDF5 found its own
// metadata checksums broken. The message names the object and ends "— the file is damaged".
class DamagedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "dataset <path>: checksum mismatch — the file is damaged"
std::string checksum_mismatch(const std::string& dataset_path);

// Throws NonFiniteError when `values` holds a NaN or an infinity.
void require_finite(const std::string& object, const double* values, std::uint64_t rows,
                    std::uint64_t cols);

// True when the file `object` belongs to was written with checksums (root attribute checksums).
bool file_has_checksums(hid_t object);

// The HDF5 path of an open object ("/steps/step_1/increment_1/U").
std::string path_of(hid_t object);

// After a failed H5Dread of `dataset_path`: a Fletcher-32 failure (HDF5's filter pipeline) is a
// checksum mismatch; anything else is reported with HDF5's own cause. Throws DamagedError.
[[noreturn]] void fail_read(const std::string& dataset_path);

// Compares the CRC-32 of the values just read with the dataset's crc32 attribute, when it has
// one (files written before checksums have none: the file-level check says whether one must be
// there). Throws DamagedError on a mismatch.
void verify_crc(hid_t dataset, const std::string& dataset_path, const void* data,
                std::uint64_t bytes);

}  // namespace styk::io::h5
