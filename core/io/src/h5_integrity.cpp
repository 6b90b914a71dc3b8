#include "h5_integrity.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace styk::io::h5 {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "crc32 attributes are over the file's little-endian bytes; a big-endian host would "
              "need to swap before summing");

namespace {

struct StackSummary {
  bool filter_failed = false;  // an entry of HDF5's filter pipeline (Fletcher-32 on our files)
  std::string innermost;       // the most specific description: the real cause
};

herr_t summarise(unsigned n, const H5E_error2_t* err, void* client) {
  auto* summary = static_cast<StackSummary*>(client);
  if (err->maj_num == H5E_PLINE) summary->filter_failed = true;
  if (n == 0 && err->desc != nullptr) summary->innermost = err->desc;
  return 0;
}

}  // namespace

std::uint32_t crc32_of(const void* data, std::uint64_t bytes) {
  uLong crc = crc32_z(0L, Z_NULL, 0);
  const auto* p = static_cast<const Bytef*>(data);
  // crc32_z takes a z_size_t; feed very large arrays in pieces anyway to stay portable.
  constexpr std::uint64_t kPiece = std::uint64_t{1} << 30;
  while (bytes > 0) {
    const std::uint64_t n = std::min(bytes, kPiece);
    crc = crc32_z(crc, p, static_cast<z_size_t>(n));
    p += n;
    bytes -= n;
  }
  return static_cast<std::uint32_t>(crc);
}

NonFiniteValue find_non_finite(const double* values, std::uint64_t rows, std::uint64_t cols) {
  NonFiniteValue found;
  found.rows = rows;
  found.cols = cols;
  const std::uint64_t width = std::max<std::uint64_t>(cols, 1);
  const std::uint64_t n = rows * width;
  for (std::uint64_t i = 0; i < n; ++i) {
    if (std::isfinite(values[i])) continue;
    if (found.count++ == 0) {
      found.row = i / width;
      found.column = i % width;
      found.value = values[i];
    }
  }
  return found;
}

NonFiniteError::NonFiniteError(std::string object, const NonFiniteValue& first)
    : std::runtime_error(object + " holds " + std::to_string(first.count) +
                         " value(s) that are not finite numbers"),
      object_(std::move(object)),
      first_(first) {}

std::string checksum_mismatch(const std::string& dataset_path) {
  return "dataset " + dataset_path + ": checksum mismatch \u2014 the file is damaged";
}

void require_finite(const std::string& object, const double* values, std::uint64_t rows,
                    std::uint64_t cols) {
  const NonFiniteValue found = find_non_finite(values, rows, cols);
  if (found.count > 0) throw NonFiniteError(object, found);
}

bool file_has_checksums(hid_t object) {
  const hid_t file = H5Iget_file_id(object);
  if (file < 0) return false;
  const htri_t has = H5Aexists_by_name(file, "/", kChecksumsAttribute, H5P_DEFAULT);
  H5Fclose(file);  // H5Iget_file_id opened a new file identifier
  return has > 0;
}

std::string path_of(hid_t object) {
  const ssize_t length = H5Iget_name(object, nullptr, 0);
  if (length <= 0) return "?";
  std::string name(static_cast<std::size_t>(length) + 1, '\0');
  H5Iget_name(object, name.data(), name.size());
  name.resize(static_cast<std::size_t>(length));
  return name;
}

void fail_read(const std::string& dataset_path) {
  StackSummary summary;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, summarise, &summary);
  H5Eclear2(H5E_DEFAULT);
  if (summary.filter_failed) throw DamagedError(checksum_mismatch(dataset_path));
  throw DamagedError(
      "dataset " + dataset_path + ": cannot be read (" +
      (summary.innermost.empty() ? std::string("HDF5 gives no cause") : summary.innermost) +
      ") \u2014 the file is damaged");
}

void verify_crc(hid_t dataset, const std::string& dataset_path, const void* data,
                std::uint64_t bytes) {
  const htri_t has = H5Aexists(dataset, kCrcAttribute);
  if (has < 0) fail_read(dataset_path);
  if (has == 0) return;
  const hid_t attribute = H5Aopen(dataset, kCrcAttribute, H5P_DEFAULT);
  if (attribute < 0) fail_read(dataset_path);
  std::int64_t stored = -1;
  const herr_t status = H5Aread(attribute, H5T_NATIVE_INT64, &stored);
  H5Aclose(attribute);
  if (status < 0) fail_read(dataset_path);
  if (stored != static_cast<std::int64_t>(crc32_of(data, bytes)))
    throw DamagedError(checksum_mismatch(dataset_path));
}

}  // namespace styk::io::h5
