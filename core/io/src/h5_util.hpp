// Private HDF5 helpers for the results file: an owning handle, error reporting that turns HDF5's
// error stack into one readable exception, and whole-array dataset and attribute I/O.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace styk::io::h5 {

// HDF5 refused an operation. While reading a file that opened, this means its structure is
// broken (HDF5 checks its own metadata checksums): readers report it as damage.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws Error("<what>: <innermost HDF5 error description>").
[[noreturn]] void fail(const std::string& what);
inline void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

// Turns HDF5's automatic error-stack printing off for its lifetime (we report errors ourselves)
// and restores the previous handler afterwards.
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t old_func_ = nullptr;
  void* old_data_ = nullptr;
};

// Owns one HDF5 identifier and closes it with the matching H5?close function.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  // Throws (via fail(what)) when `id` is negative, i.e. the call that produced it failed.
  Handle(hid_t id, Closer close, const std::string& what);
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept;
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  // Closes now and reports a failure (closing a file flushes it, so this can fail).
  void close(const std::string& what);

 private:
  void reset() noexcept;
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

Handle create_group(hid_t parent, const std::string& name);
Handle open_group(hid_t parent, const std::string& name);
bool has_link(hid_t parent, const std::string& name);
// Names of the links directly under `group`, in HDF5's name order.
std::vector<std::string> link_names(hid_t group);

// Writes a rows x cols array (cols == 0: a 1-D array of `rows`) in one call. Non-empty arrays are
// chunked (about 1 MiB per chunk) and uncompressed: writing speed matters more than file size.
void write_dataset(hid_t parent, const std::string& name, hid_t file_type, hid_t mem_type,
                   const void* data, std::uint64_t rows, std::uint64_t cols);
void write_int64(hid_t parent, const std::string& name, const std::vector<std::int64_t>& v);
// Fixed-length, null-padded strings as wide as the longest one.
void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& v);

// Reads a whole dataset whose shape must be (rows) when cols == 0 or (rows, cols) otherwise.
// Returns rows; `out` is resized to rows * max(cols, 1) elements.
std::uint64_t read_doubles(hid_t parent, const std::string& name, std::uint64_t cols,
                           std::vector<double>& out);
std::uint64_t read_int64(hid_t parent, const std::string& name, std::vector<std::int64_t>& out);
std::vector<std::string> read_strings(hid_t parent, const std::string& name);

void write_attribute(hid_t object, const std::string& name, const std::string& value);
void write_attribute(hid_t object, const std::string& name, std::int64_t value);
void write_attribute(hid_t object, const std::string& name, double value);
std::string read_string_attribute(hid_t object, const std::string& name);
std::int64_t read_int_attribute(hid_t object, const std::string& name);
double read_double_attribute(hid_t object, const std::string& name);

// Link names cannot hold '/' and cannot be "."; set names are escaped ('%' -> %25, '/' -> %2F,
// a lone "." -> %2E) and unescaped on reading.
std::string escape_name(const std::string& name);
std::string unescape_name(const std::string& name);

}  // namespace styk::io::h5
