#include "h5_util.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "h5_integrity.hpp"

namespace styk::io::h5 {

namespace {

herr_t take_innermost(unsigned n, const H5E_error2_t* err, void* client) {
  // Walking upward, n == 0 is the most specific entry: the one that names the real cause.
  if (n == 0 && err->desc != nullptr) *static_cast<std::string*>(client) = err->desc;
  return 0;
}

constexpr std::uint64_t kChunkBytes = 1u << 20;
constexpr unsigned kMaxCompactLinks = 65535;  // HDF5's limit for links kept in the header

}  // namespace

void fail(const std::string& what) {
  std::string cause;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_innermost, &cause);
  H5Eclear2(H5E_DEFAULT);
  throw Error(cause.empty() ? what : what + ": " + cause);
}

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &old_func_, &old_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, old_func_, old_data_); }

Handle::Handle(hid_t id, Closer close, const std::string& what) : id_(id), close_(close) {
  if (id_ < 0) fail(what);
}

Handle::Handle(Handle&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    close_ = other.close_;
  }
  return *this;
}

void Handle::reset() noexcept {
  if (id_ >= 0 && close_ != nullptr) close_(id_);
  id_ = H5I_INVALID_HID;
}

void Handle::close(const std::string& what) {
  const hid_t id = std::exchange(id_, H5I_INVALID_HID);
  if (id >= 0 && close_ != nullptr) check(close_(id), what);
}

Handle create_group(hid_t parent, const std::string& name) {
  Handle props(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "cannot create property list");
  // Links stay in the group's object header, which HDF5 checksums, instead of moving to the
  // "dense" fractal heap beyond 8 links, whose blocks carry no checksum in HDF5 1.10: a flipped
  // byte there goes unnoticed or crashes the HDF5 library while it walks the group.
  if (file_has_checksums(parent))
    check(H5Pset_link_phase_change(props.get(), kMaxCompactLinks, kMaxCompactLinks),
          "cannot keep the links of " + name + " compact");
  return Handle(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, props.get(), H5P_DEFAULT), H5Gclose,
                "cannot create group " + name);
}

Handle open_group(hid_t parent, const std::string& name) {
  return Handle(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, "cannot open group " + name);
}

bool has_link(hid_t parent, const std::string& name) {
  const htri_t exists = H5Lexists(parent, name.c_str(), H5P_DEFAULT);
  if (exists < 0) fail("cannot look up " + name);
  return exists > 0;
}

std::vector<std::string> link_names(hid_t group) {
  H5G_info_t info;
  check(H5Gget_info(group, &info), "cannot list a group");
  std::vector<std::string> names;
  names.reserve(info.nlinks);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length =
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (length < 0) fail("cannot read a link name");
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    if (H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                           H5P_DEFAULT) < 0)
      fail("cannot read a link name");
    name.resize(static_cast<std::size_t>(length));
    names.push_back(std::move(name));
  }
  return names;
}

void write_dataset(hid_t parent, const std::string& name, hid_t file_type, hid_t mem_type,
                   const void* data, std::uint64_t rows, std::uint64_t cols) {
  // A file with checksums (docs/results.md) holds finite numbers only, every stored chunk carries
  // Fletcher-32 and every dataset the CRC-32 of its values: for all datasets, whatever they hold.
  const bool checksums = file_has_checksums(parent);
  if (checksums && H5Tequal(mem_type, H5T_NATIVE_DOUBLE) > 0)
    require_finite(path_of(parent) + "/" + name, static_cast<const double*>(data), rows, cols);
  const int rank = cols == 0 ? 1 : 2;
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose, "cannot create dataspace");
  Handle create_props(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "cannot create property list");
  const std::uint64_t row_bytes = H5Tget_size(file_type) * std::max<std::uint64_t>(cols, 1);
  if (rows > 0) {
    const hsize_t chunk[2] = {std::clamp<std::uint64_t>(kChunkBytes / row_bytes, 1, rows),
                              std::max<std::uint64_t>(cols, 1)};
    check(H5Pset_chunk(create_props.get(), rank, chunk), "cannot set chunking for " + name);
    if (checksums)
      check(H5Pset_fletcher32(create_props.get()), "cannot set the checksum filter of " + name);
  }
  Handle dataset(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                            create_props.get(), H5P_DEFAULT),
                 H5Dclose, "cannot create dataset " + name);
  if (rows > 0)
    check(H5Dwrite(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "cannot write dataset " + name);
  if (checksums)
    write_attribute(dataset.get(), kCrcAttribute,
                    static_cast<std::int64_t>(crc32_of(data, rows * row_bytes)));
  dataset.close("cannot close dataset " + name);
}

void write_int64(hid_t parent, const std::string& name, const std::vector<std::int64_t>& v) {
  write_dataset(parent, name, H5T_STD_I64LE, H5T_NATIVE_INT64, v.data(), v.size(), 0);
}

namespace {

Handle fixed_string_type(std::size_t width) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create a string type");
  check(H5Tset_size(type.get(), std::max<std::size_t>(width, 1)), "cannot size a string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "cannot pad a string type");
  return type;
}

// Shape check shared by the readers: returns rows.
std::uint64_t checked_rows(hid_t dataset, const std::string& name, std::uint64_t cols) {
  Handle space(H5Dget_space(dataset), H5Sclose, "cannot read the shape of " + name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  hsize_t dims[2] = {0, 0};
  const int expected_rank = cols == 0 ? 1 : 2;
  if (rank != expected_rank || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0 ||
      (cols != 0 && dims[1] != cols))
    throw std::runtime_error("dataset " + name + " does not have the expected shape (" +
                             (cols == 0 ? "n" : "n x " + std::to_string(cols)) + ")");
  return dims[0];
}

// A damaged layout message can send HDF5's read of a compact or contiguous dataset outside its
// data (a compact buffer of 0 bytes, an address beyond the end of the file), where the library's
// copy crashes instead of failing (found by fuzzing, docs/fuzzing.md): such a dataset must hold
// its `bytes`, and a contiguous one lie inside the file. Chunked datasets (what Styk writes) are
// read chunk by chunk through HDF5's index, each chunk checked by its Fletcher-32.
void check_unchunked_storage(hid_t dataset, const std::string& name, std::uint64_t bytes) {
  if (bytes == 0) return;
  Handle plist(H5Dget_create_plist(dataset), H5Pclose, "cannot read the layout of " + name);
  const H5D_layout_t layout = H5Pget_layout(plist.get());
  if (layout == H5D_CHUNKED || layout == H5D_VIRTUAL) return;
  const std::string damaged = "dataset " + name + ": its data lies outside its storage";
  if (layout != H5D_COMPACT && layout != H5D_CONTIGUOUS) throw Error(damaged);
  if (H5Dget_storage_size(dataset) < bytes) throw Error(damaged);
  if (layout == H5D_COMPACT) return;
  const haddr_t offset = H5Dget_offset(dataset);
  Handle file(H5Iget_file_id(dataset), H5Fclose, "cannot find the file of " + name);
  hsize_t file_size = 0;
  if (H5Fget_filesize(file.get(), &file_size) < 0 || offset == HADDR_UNDEF || offset > file_size ||
      bytes > file_size - offset)
    throw Error(damaged);
}

template <typename T>
std::uint64_t read_array(hid_t parent, const std::string& name, hid_t mem_type, std::uint64_t cols,
                         std::vector<T>& out) {
  Handle dataset(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose,
                 "cannot open dataset " + name);
  const std::uint64_t rows = checked_rows(dataset.get(), name, cols);
  out.resize(rows * std::max<std::uint64_t>(cols, 1));
  check_unchunked_storage(dataset.get(), name, out.size() * sizeof(T));
  const std::string path = path_of(dataset.get());
  if (rows > 0 && H5Dread(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail_read(path);
  verify_crc(dataset.get(), path, out.data(), out.size() * sizeof(T));
  if constexpr (std::is_same_v<T, double>) require_finite(path, out.data(), rows, cols);
  return rows;
}

std::string trim_padding(const char* text, std::size_t width) {
  std::size_t n = 0;
  while (n < width && text[n] != '\0') ++n;
  return std::string(text, n);
}

}  // namespace

void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& v) {
  std::size_t width = 1;
  for (const std::string& s : v) width = std::max(width, s.size());
  std::string packed(v.size() * width, '\0');
  for (std::size_t i = 0; i < v.size(); ++i) packed.replace(i * width, v[i].size(), v[i]);
  const Handle type = fixed_string_type(width);
  write_dataset(parent, name, type.get(), type.get(), packed.data(), v.size(), 0);
}

std::uint64_t read_doubles(hid_t parent, const std::string& name, std::uint64_t cols,
                           std::vector<double>& out) {
  return read_array(parent, name, H5T_NATIVE_DOUBLE, cols, out);
}

std::uint64_t read_int64(hid_t parent, const std::string& name, std::vector<std::int64_t>& out) {
  return read_array(parent, name, H5T_NATIVE_INT64, 0, out);
}

std::vector<std::string> read_strings(hid_t parent, const std::string& name) {
  Handle dataset(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose,
                 "cannot open dataset " + name);
  Handle file_type(H5Dget_type(dataset.get()), H5Tclose, "cannot read the type of " + name);
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) != 0)
    throw std::runtime_error("dataset " + name + " is not made of fixed-length strings");
  const std::size_t width = H5Tget_size(file_type.get());
  const std::uint64_t rows = checked_rows(dataset.get(), name, 0);
  std::string packed(rows * width, '\0');
  check_unchunked_storage(dataset.get(), name, packed.size());
  const Handle mem_type = fixed_string_type(width);
  const std::string path = path_of(dataset.get());
  if (rows > 0 &&
      H5Dread(dataset.get(), mem_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data()) < 0)
    fail_read(path);
  verify_crc(dataset.get(), path, packed.data(), packed.size());
  std::vector<std::string> out;
  out.reserve(rows);
  for (std::uint64_t i = 0; i < rows; ++i) out.push_back(trim_padding(&packed[i * width], width));
  return out;
}

namespace {

void write_scalar_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t mem_type,
                            const void* value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "cannot create dataspace");
  Handle attribute(
      H5Acreate2(object, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
      "cannot create attribute " + name);
  check(H5Awrite(attribute.get(), mem_type, value), "cannot write attribute " + name);
}

Handle open_attribute(hid_t object, const std::string& name) {
  return Handle(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose,
                "cannot open attribute " + name);
}

}  // namespace

void write_attribute(hid_t object, const std::string& name, const std::string& value) {
  const Handle type = fixed_string_type(value.size());
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  write_scalar_attribute(object, name, type.get(), type.get(), padded.data());
}

void write_attribute(hid_t object, const std::string& name, std::int64_t value) {
  write_scalar_attribute(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void write_attribute(hid_t object, const std::string& name, double value) {
  if (file_has_checksums(object)) require_finite(path_of(object) + "@" + name, &value, 1, 0);
  write_scalar_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

std::string read_string_attribute(hid_t object, const std::string& name) {
  const Handle attribute = open_attribute(object, name);
  Handle file_type(H5Aget_type(attribute.get()), H5Tclose, "cannot read the type of " + name);
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) != 0)
    throw std::runtime_error("attribute " + name + " is not a fixed-length string");
  const std::size_t width = H5Tget_size(file_type.get());
  std::string buffer(width, '\0');
  const Handle mem_type = fixed_string_type(width);
  check(H5Aread(attribute.get(), mem_type.get(), buffer.data()), "cannot read attribute " + name);
  return trim_padding(buffer.data(), width);
}

std::int64_t read_int_attribute(hid_t object, const std::string& name) {
  const Handle attribute = open_attribute(object, name);
  std::int64_t value = 0;
  check(H5Aread(attribute.get(), H5T_NATIVE_INT64, &value), "cannot read attribute " + name);
  return value;
}

double read_double_attribute(hid_t object, const std::string& name) {
  const Handle attribute = open_attribute(object, name);
  double value = 0.0;
  check(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value), "cannot read attribute " + name);
  require_finite(path_of(object) + "@" + name, &value, 1, 0);
  return value;
}

std::string escape_name(const std::string& name) {
  if (name == ".") return "%2E";
  std::string out;
  for (const char c : name) {
    if (c == '%')
      out += "%25";
    else if (c == '/')
      out += "%2F";
    else
      out += c;
  }
  return out;
}

std::string unescape_name(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (name[i] == '%' && i + 2 < name.size()) {
      const std::string code = name.substr(i + 1, 2);
      if (code == "25" || code == "2F" || code == "2E") {
        out += code == "25" ? '%' : code == "2F" ? '/' : '.';
        i += 2;
        continue;
      }
    }
    out += name[i];
  }
  return out;
}

}  // namespace styk::io::h5
