// `styk check`: reads every dataset and every real attribute of a results file, whatever its name,
// and reports all it finds wrong rather than stopping at the first problem.
#include "styk/io/results_check.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "h5_integrity.hpp"
#include "h5_util.hpp"
#include "results_check_structure.hpp"
#include "results_integrity.hpp"
#include "results_open.hpp"
#include "results_rows.hpp"
#include "results_schema.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/results_seal.hpp"

namespace styk {
namespace {

namespace h5 = io::h5;

// Phase 1: the root attributes that say what the file is. False: nothing more can be read.
bool identify(hid_t file, ResultsCheck& report) {
  try {
    if (H5Aexists(file, "format") <= 0 ||
        h5::read_string_attribute(file, "format") != io::schema::kFormat) {
      report.problems.push_back("not a Styk results file (root attribute format is not \"" +
                                std::string(io::schema::kFormat) + "\")");
      return false;
    }
    report.schema_version = static_cast<int>(h5::read_int_attribute(file, "schema_version"));
    if (report.schema_version < 1 || report.schema_version > io::schema::kSchemaVersion) {
      report.problems.push_back("schema version " + std::to_string(report.schema_version) +
                                " is not one this build reads (1.." +
                                std::to_string(io::schema::kSchemaVersion) + ")");
      return false;
    }
    report.styk_version = h5::read_string_attribute(file, "styk_version");
    return true;
  } catch (const std::runtime_error& e) {
    report.problems.push_back(std::string("the root attributes cannot be read: ") + e.what() +
                              " \u2014 the file is damaged");
    return false;
  }
}

// Phase 2: the digest over every dataset's checksum. Also says whether checksums are expected.
io::FileIntegrity verify_file_digest(hid_t file, ResultsCheck& report) {
  try {
    const io::FileIntegrity integrity = io::verify_digest(file);
    if (integrity == io::FileIntegrity::Checksummed)
      report.digest = h5::read_string_attribute(file, io::kDigestAttribute);
    return integrity;
  } catch (const h5::Error& e) {
    report.problems.push_back(std::string(e.what()) + " \u2014 the file is damaged");
  } catch (const std::runtime_error& e) {
    report.problems.push_back(e.what());
  }
  return io::FileIntegrity::Checksummed;  // it claims checksums: hold every dataset to them
}

// Phase 3, per dataset: Fletcher-32 (HDF5 checks it while reading), CRC-32, finite values.
void scan_dataset(hid_t file, const io::DatasetEntry& d, bool checksummed, ResultsCheck& report) {
  if (checksummed && d.value_bytes > 0 && !d.fletcher32)
    report.problems.push_back("dataset " + d.path +
                              " is stored without the Fletcher-32 checksum of its chunks");
  const h5::Handle dataset(H5Dopen2(file, d.path.c_str(), H5P_DEFAULT), H5Dclose,
                           "cannot open dataset " + d.path);
  const h5::Handle file_type(H5Dget_type(dataset.get()), H5Tclose, "cannot read a type");
  // Reals are read as native doubles, anything else in its own (native) layout: on a
  // little-endian host either is a byte-for-byte copy of what the file stores.
  const h5::Handle memory_type(
      d.is_float ? H5Tcopy(H5T_NATIVE_DOUBLE) : H5Tget_native_type(file_type.get(), H5T_DIR_ASCEND),
      H5Tclose, "cannot read a type");
  std::uint64_t elements = 1;
  for (const std::uint64_t n : d.shape) elements *= n;
  std::vector<unsigned char> bytes(elements * H5Tget_size(memory_type.get()));
  if (!bytes.empty() &&
      H5Dread(dataset.get(), memory_type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) < 0)
    h5::fail_read(d.path);
  try {  // a mismatch is reported, and the values are still looked at
    h5::verify_crc(dataset.get(), d.path, bytes.data(), bytes.size());
  } catch (const h5::DamagedError& e) {
    report.problems.push_back(e.what());
  }
  ++report.datasets;
  report.value_bytes += bytes.size();
  if (!d.is_float) return;
  const std::uint64_t rows = d.shape.empty() ? 1 : d.shape[0];
  const std::uint64_t cols = d.shape.size() > 1 ? elements / std::max<std::uint64_t>(rows, 1) : 0;
  const h5::NonFiniteValue first =
      h5::find_non_finite(reinterpret_cast<const double*>(bytes.data()), rows, cols);
  if (first.count > 0)
    report.problems.push_back(io::describe_non_finite(file, h5::NonFiniteError(d.path, first)));
}

void scan_datasets(hid_t file, bool checksummed, ResultsCheck& report) {
  std::vector<io::DatasetEntry> datasets;
  try {
    datasets = io::list_datasets(file);
  } catch (const std::runtime_error& e) {
    report.problems.push_back(std::string("the file cannot be walked: ") + e.what() +
                              " \u2014 the file is damaged");
    return;
  }
  for (const io::DatasetEntry& d : datasets) {
    try {
      scan_dataset(file, d, checksummed, report);
    } catch (const h5::Error& e) {
      report.problems.push_back(std::string(e.what()) + " \u2014 the file is damaged");
    } catch (const std::runtime_error& e) {
      report.problems.push_back(e.what());
    }
  }
}

// Phase 4: every real-valued attribute of every group and dataset (times, residuals, ...).
struct AttributeScan {
  hid_t file;
  ResultsCheck* report;
  std::string object;
};

herr_t scan_attribute(hid_t object, const char* name, const H5A_info_t*, void* client) {
  auto* scan = static_cast<AttributeScan*>(client);
  const hid_t attribute = H5Aopen(object, name, H5P_DEFAULT);
  if (attribute < 0) return -1;
  const hid_t type = H5Aget_type(attribute);
  const hid_t space = H5Aget_space(attribute);
  const hssize_t count = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
  herr_t status = 0;
  if (type >= 0 && count > 0 && H5Tget_class(type) == H5T_FLOAT) {
    std::vector<double> values(static_cast<std::size_t>(count));
    status = H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data());
    const h5::NonFiniteValue first = h5::find_non_finite(values.data(), values.size(), 0);
    if (status >= 0 && first.count > 0)
      scan->report->problems.push_back(io::describe_non_finite(
          scan->file, h5::NonFiniteError(scan->object + "@" + name, first)));
  }
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  H5Aclose(attribute);
  return status < 0 || type < 0 || count < 0 ? -1 : 0;
}

herr_t scan_object_attributes(hid_t root, const char* name, const H5O_info_t*, void* client) {
  auto* scan = static_cast<AttributeScan*>(client);
  const hid_t object = H5Oopen(root, name, H5P_DEFAULT);
  if (object < 0) return -1;
  scan->object = std::string(name) == "." ? "/" : std::string("/") + name;
  hsize_t index = 0;
  const herr_t status =
      H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &index, scan_attribute, scan);
  H5Oclose(object);
  return status;
}

void scan_attributes(hid_t file, ResultsCheck& report) {
  AttributeScan scan{file, &report, "/"};
  if (H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, scan_object_attributes, &scan, H5O_INFO_BASIC) <
      0) {
    try {
      h5::fail("the attributes of " + scan.object + " cannot be read");
    } catch (const std::runtime_error& e) {
      report.problems.push_back(std::string(e.what()) + " \u2014 the file is damaged");
    }
  }
}

// Phase 5: what the reader checks (shapes, index ranges, offsets, unique ids) and the structure
// of steps and increments (results_check_structure.cpp).
void check_consistency(const std::string& path, hid_t file, ResultsCheck& report) {
  ResultsFileContents contents;
  try {
    contents = read_results_file(path);
  } catch (const InputError& e) {
    report.problems.push_back(e.message());
    return;
  }
  io::check_structure(file, contents, report);
}

std::string size_text(std::uint64_t bytes) {
  char text[32];
  if (bytes < 10000)
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  else if (bytes < 10000000)
    std::snprintf(text, sizeof text, "%.1f kB", static_cast<double>(bytes) / 1e3);
  else
    std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}

void conclude(io::FileIntegrity integrity, ResultsCheck& report) {
  const std::string counts = std::to_string(report.steps) + " step(s), " +
                             std::to_string(report.increments) + " increment(s); " +
                             std::to_string(report.datasets) + " datasets (" +
                             size_text(report.value_bytes) + " of values)";
  if (!report.problems.empty()) {
    report.verdict = ResultsCheck::Verdict::Damaged;
    report.summary = "damaged \u2014 " + std::to_string(report.problems.size()) +
                     " problem(s), the first: " + report.problems.front();
  } else if (integrity == io::FileIntegrity::Legacy) {
    report.verdict = ResultsCheck::Verdict::Unverifiable;
    report.summary =
        "cannot be verified \u2014 written before results files carried checksums "
        "(Styk " +
        report.styk_version + ", schema " + std::to_string(report.schema_version) + "); " + counts +
        " read, every value finite, counts, ids and steps consistent";
  } else {
    report.verdict = ResultsCheck::Verdict::Whole;
    report.summary = "whole \u2014 schema " + std::to_string(report.schema_version) + ", Styk " +
                     report.styk_version + "; " + counts +
                     " match their Fletcher-32 and CRC-32 checksums and the digest " +
                     report.digest + "; every value finite; counts, ids and steps consistent; " +
                     (report.seal.empty() ? "not sealed (written before Styk sealed its files)"
                                          : "sealed: " + report.seal);
  }
}

}  // namespace

ResultsCheck check_results_file(const std::string& path) {
  const h5::QuietErrors quiet;
  ResultsCheck report;
  h5::Handle file;
  std::optional<io::ResultsSeal> seal;
  try {
    file = io::open_results_for_reading(path, &seal);
    if (seal) report.seal = io::describe_seal(*seal);
  } catch (const std::runtime_error& e) {
    report.problems.push_back(e.what());
    conclude(io::FileIntegrity::Checksummed, report);
    return report;
  }
  io::FileIntegrity integrity = io::FileIntegrity::Checksummed;
  if (identify(file.get(), report)) {
    integrity = verify_file_digest(file.get(), report);
    scan_datasets(file.get(), integrity == io::FileIntegrity::Checksummed, report);
    scan_attributes(file.get(), report);
    if (report.problems.empty()) check_consistency(path, file.get(), report);
  }
  conclude(integrity, report);
  return report;
}

}  // namespace styk
