#include "results_integrity.hpp"

#include "styk/io/results_seal.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <stdexcept>

#include "h5_integrity.hpp"

namespace styk::io {
namespace {

bool has_fletcher32(hid_t dataset) {
  const h5::Handle props(H5Dget_create_plist(dataset), H5Pclose, "cannot read a dataset's layout");
  const int filters = H5Pget_nfilters(props.get());
  for (int i = 0; i < filters; ++i) {
    unsigned flags = 0;
    std::size_t count = 0;
    unsigned config = 0;
    if (H5Pget_filter2(props.get(), static_cast<unsigned>(i), &flags, &count, nullptr, 0, nullptr,
                       &config) == H5Z_FILTER_FLETCHER32)
      return true;
  }
  return false;
}

DatasetEntry describe(hid_t file, const std::string& path) {
  DatasetEntry entry;
  entry.path = path;
  const h5::Handle dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose,
                           "cannot open dataset " + path);
  const h5::Handle space(H5Dget_space(dataset.get()), H5Sclose, "cannot read the shape of " + path);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) h5::fail("cannot read the shape of " + path);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    h5::fail("cannot read the shape of " + path);
  entry.shape.assign(dims.begin(), dims.end());
  const h5::Handle type(H5Dget_type(dataset.get()), H5Tclose, "cannot read the type of " + path);
  entry.is_float = H5Tget_class(type.get()) == H5T_FLOAT;
  std::uint64_t elements = 1;
  for (const std::uint64_t d : entry.shape) elements *= d;
  entry.value_bytes = elements * H5Tget_size(type.get());
  entry.fletcher32 = has_fletcher32(dataset.get());
  const htri_t has_crc = H5Aexists(dataset.get(), h5::kCrcAttribute);
  if (has_crc < 0) h5::fail("cannot read the attributes of " + path);
  if (has_crc > 0) {
    const std::int64_t crc = h5::read_int_attribute(dataset.get(), h5::kCrcAttribute);
    entry.has_crc = crc >= 0 && crc <= 0xffffffffLL;
    entry.crc = static_cast<std::uint32_t>(crc);
  }
  return entry;
}

herr_t collect_dataset_path(hid_t, const char* name, const H5O_info_t* info, void* client) {
  if (info->type == H5O_TYPE_DATASET)
    static_cast<std::vector<std::string>*>(client)->push_back(std::string("/") + name);
  return 0;
}

}  // namespace

std::vector<DatasetEntry> list_datasets(hid_t file) {
  std::vector<std::string> paths;
  h5::check(
      H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, collect_dataset_path, &paths, H5O_INFO_BASIC),
      "cannot walk the file");
  std::sort(paths.begin(), paths.end());
  std::vector<DatasetEntry> datasets;
  datasets.reserve(paths.size());
  for (const std::string& path : paths) datasets.push_back(describe(file, path));
  return datasets;
}

std::string digest_of(const std::vector<DatasetEntry>& datasets) {
  std::string manifest;
  for (const DatasetEntry& d : datasets) {
    manifest += d.path;
    manifest += ' ';
    for (std::size_t i = 0; i < d.shape.size(); ++i)
      manifest += (i > 0 ? "x" : "") + std::to_string(d.shape[i]);
    char crc[16];
    std::snprintf(crc, sizeof crc, " %08" PRIx32 "\n", d.crc);
    manifest += crc;
  }
  char text[24];
  std::snprintf(text, sizeof text, "crc32:%08" PRIx32,
                h5::crc32_of(manifest.data(), manifest.size()));
  return text;
}

h5::Handle create_checksummed_file(const std::string& path, bool seal_block) {
  const h5::Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create property list");
  h5::check(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V110, H5F_LIBVER_V110),
            "cannot select the HDF5 1.10 file format");
  const h5::Handle creation(H5Pcreate(H5P_FILE_CREATE), H5Pclose, "cannot create property list");
  if (seal_block)
    h5::check(H5Pset_userblock(creation.get(), kSealBlockBytes), "cannot reserve the user block");
  h5::Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, creation.get(), access.get()), H5Fclose,
                  "cannot create " + path);
  h5::write_attribute(file.get(), h5::kChecksumsAttribute, std::string(h5::kChecksumsScheme));
  return file;
}

void write_digest(hid_t file) {
  h5::write_attribute(file, kDigestAttribute, digest_of(list_datasets(file)));
}

FileIntegrity verify_digest(hid_t file) {
  const htri_t checksummed = H5Aexists(file, h5::kChecksumsAttribute);
  if (checksummed < 0) h5::fail("cannot read the root attributes");
  if (checksummed == 0) return FileIntegrity::Legacy;
  const std::string scheme = h5::read_string_attribute(file, h5::kChecksumsAttribute);
  if (scheme != h5::kChecksumsScheme)
    throw std::runtime_error("checksums of kind '" + scheme + "' are not known to this build (" +
                             h5::kChecksumsScheme + ")");
  const htri_t has_digest = H5Aexists(file, kDigestAttribute);
  if (has_digest < 0) h5::fail("cannot read the root attributes");
  if (has_digest == 0)
    throw h5::DamagedError("the root attribute digest is missing \u2014 the file is damaged");
  const std::vector<DatasetEntry> datasets = list_datasets(file);
  for (const DatasetEntry& d : datasets)
    if (!d.has_crc)
      throw h5::DamagedError("dataset " + d.path + " has no checksum \u2014 the file is damaged");
  const std::string stored = h5::read_string_attribute(file, kDigestAttribute);
  if (digest_of(datasets) != stored)
    throw h5::DamagedError("the file digest " + stored +
                           " does not match its datasets (one was added, lost, renamed or "
                           "replaced) \u2014 the file is damaged");
  return FileIntegrity::Checksummed;
}

}  // namespace styk::io
