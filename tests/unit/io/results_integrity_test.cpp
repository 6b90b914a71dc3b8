// Results files that cannot lie (docs/results.md, "Integrity"): what the writer stores (Fletcher-32
// on every stored chunk, the crc32 of every dataset, the digest over them all, recomputed here from
// the documented recipe), and what read_results_file does with byte flips, truncation, zeroed
// blocks, values rewritten behind the checksums, NaN and infinities, and files written before
// checksums existed. Every refusal is an InputError naming the file and the dataset.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io_test_support.hpp"
#include "results_damage.hpp"
#include "styk/io/results_file.hpp"

namespace styk {
namespace {

const std::string kFixtures = std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/";
const std::string kU = "/steps/step_2/increment_1/U";

// The message read_results_file must throw, whole: "file: what".
std::string refusal(const std::string& path) {
  try {
    read_results_file(path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, path);
    return e.what();
  }
  ADD_FAILURE() << path << " was read without complaint";
  return "";
}

struct DatasetFacts {
  std::string path;
  std::vector<hsize_t> dims;
  std::vector<unsigned char> bytes;
  bool fletcher32 = false;
  bool has_crc = false;
  long long crc = -1;
};

herr_t collect(hid_t root, const char* name, const H5O_info_t* info, void* client) {
  if (info->type != H5O_TYPE_DATASET) return 0;
  DatasetFacts facts;
  facts.path = std::string("/") + name;
  const hid_t d = H5Dopen2(root, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  facts.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, facts.dims.data(), nullptr);
  const hid_t type = H5Dget_type(d);
  hsize_t n = 1;
  for (const hsize_t v : facts.dims) n *= v;
  facts.bytes.resize(n * H5Tget_size(type));
  if (n > 0) H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, facts.bytes.data());
  const hid_t props = H5Dget_create_plist(d);
  for (int i = 0; i < H5Pget_nfilters(props); ++i) {
    unsigned flags = 0, config = 0;
    std::size_t count = 0;
    if (H5Pget_filter2(props, static_cast<unsigned>(i), &flags, &count, nullptr, 0, nullptr,
                       &config) == H5Z_FILTER_FLETCHER32)
      facts.fletcher32 = true;
  }
  facts.has_crc = H5Aexists(d, "crc32") > 0;
  if (facts.has_crc) {
    const hid_t a = H5Aopen(d, "crc32", H5P_DEFAULT);
    H5Aread(a, H5T_NATIVE_LLONG, &facts.crc);
    H5Aclose(a);
  }
  H5Pclose(props);
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(d);
  static_cast<std::vector<DatasetFacts>*>(client)->push_back(std::move(facts));
  return 0;
}

std::string root_string_attribute(hid_t file, const char* name) {
  const hid_t a = H5Aopen(file, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(a);
  std::string value(H5Tget_size(type), '\0');
  H5Aread(a, type, value.data());
  H5Tclose(type);
  H5Aclose(a);
  return value.substr(0, value.find('\0'));
}

class ResultsIntegrity : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = io_test::fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    good_ = damage::write_cube_results(dir_ + "/good.styk.h5");
  }
  std::string copy(const std::string& name) {
    const std::string path = dir_ + "/" + name;
    damage::copy_file(good_, path);
    return path;
  }
  std::string dir_, good_;
};

// docs/results.md "Integrity": every dataset written carries a crc32 attribute equal to zlib's
// CRC-32 of its values, every stored chunk the Fletcher-32 filter, and the root digest is the
// CRC-32 of the manifest lines "<path> <shape> <crc32 hex>\n" in path order.
TEST_F(ResultsIntegrity, EveryDatasetIsChecksummedAsDocumented) {
  const hid_t file = H5Fopen(good_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  std::vector<DatasetFacts> datasets;
  ASSERT_GE(H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, collect, &datasets, H5O_INFO_BASIC), 0);
  EXPECT_EQ(root_string_attribute(file, "checksums"), "fletcher32+crc32");
  const std::string digest = root_string_attribute(file, "digest");
  H5Fclose(file);

  ASSERT_GE(datasets.size(), 40u);  // mesh, sets, 2 increments of 14 fields + 16 contact each
  std::sort(datasets.begin(), datasets.end(),
            [](const DatasetFacts& a, const DatasetFacts& b) { return a.path < b.path; });
  std::string manifest;
  for (const DatasetFacts& d : datasets) {
    SCOPED_TRACE(d.path);
    ASSERT_TRUE(d.has_crc);
    const uLong expected = crc32_z(0L, d.bytes.data(), d.bytes.size());
    EXPECT_EQ(d.crc, static_cast<long long>(expected));
    if (!d.bytes.empty()) {
      EXPECT_TRUE(d.fletcher32) << "stored chunks without Fletcher-32";
    }
    std::string shape;
    for (std::size_t i = 0; i < d.dims.size(); ++i)
      shape += (i ? "x" : "") + std::to_string(d.dims[i]);
    char crc[12];
    std::snprintf(crc, sizeof crc, "%08lx", static_cast<unsigned long>(expected));
    manifest += d.path + " " + shape + " " + crc + "\n";
  }
  char expected_digest[20];
  std::snprintf(expected_digest, sizeof expected_digest, "crc32:%08lx",
                static_cast<unsigned long>(
                    crc32_z(0L, reinterpret_cast<const Bytef*>(manifest.data()), manifest.size())));
  EXPECT_EQ(digest, expected_digest);
  EXPECT_TRUE(read_results_file(good_).verified);
}

// The issue's message, exactly: "file: dataset /steps/2/U: checksum mismatch — the file is
// damaged".
TEST_F(ResultsIntegrity, FlippedByteInAChunkIsAChecksumMismatchNamingTheDataset) {
  const std::string path = copy("flipped.styk.h5");
  const damage::StoredBytes chunk = damage::first_chunk(path, kU);
  damage::flip_byte(path, chunk.offset + chunk.size / 2);
  EXPECT_EQ(refusal(path),
            path + ": dataset " + kU + ": checksum mismatch \u2014 the file is damaged");
}

// Generic over datasets: one flipped byte in the stored values of any dataset, whatever its name
// (ids, strings, connectivity, sets, fields, contact rows), is caught and that dataset named.
TEST_F(ResultsIntegrity, AFlipInAnyDatasetIsCaughtAndNamed) {
  const hid_t file = H5Fopen(good_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::vector<DatasetFacts> datasets;
  H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, collect, &datasets, H5O_INFO_BASIC);
  H5Fclose(file);
  int flipped = 0;
  for (const DatasetFacts& d : datasets) {
    if (d.bytes.empty()) continue;
    SCOPED_TRACE(d.path);
    const std::string path = copy("any.styk.h5");
    const damage::StoredBytes chunk = damage::first_chunk(path, d.path);
    damage::flip_byte(path, chunk.offset);
    EXPECT_EQ(refusal(path),
              path + ": dataset " + d.path + ": checksum mismatch \u2014 the file is damaged");
    ++flipped;
  }
  EXPECT_GE(flipped, 40);
}

// A block of zeros over a whole stored chunk, its Fletcher-32 included, passes HDF5's filter
// (Fletcher-32 of zeros is zero): the dataset's CRC-32 is what catches it.
TEST_F(ResultsIntegrity, ZeroedChunkPassesFletcherButNotTheCrc) {
  const std::string path = copy("zeroed.styk.h5");
  const damage::StoredBytes chunk = damage::first_chunk(path, kU);
  damage::zero_bytes(path, chunk.offset, chunk.size);
  {  // HDF5 alone reads it back as zeros without complaint
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t d = H5Dopen2(file, kU.c_str(), H5P_DEFAULT);
    std::vector<double> u(24, 1.0);
    EXPECT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, u.data()), 0);
    EXPECT_EQ(u, std::vector<double>(24, 0.0));
    H5Dclose(d);
    H5Fclose(file);
  }
  EXPECT_EQ(refusal(path),
            path + ": dataset " + kU + ": checksum mismatch \u2014 the file is damaged");
}

// Damage that does not hit values: a zeroed 4 KiB block at the start (the superblock and the root
// group's header) and one in the middle of the file.
TEST_F(ResultsIntegrity, ZeroedBlocksAnywhereAreRefused) {
  const std::uint64_t size = damage::file_size(good_);
  for (const std::uint64_t offset : {std::uint64_t{0}, size / 2 / 4096 * 4096, size - 4096}) {
    SCOPED_TRACE(offset);
    const std::string path = copy("zero_block.styk.h5");
    damage::zero_bytes(path, offset, 4096);
    const std::string message = refusal(path);
    EXPECT_TRUE(message.find("the file is damaged") != std::string::npos ||
                message.find("is not an HDF5 file") != std::string::npos)
        << message;
  }
}

// A partial copy: cut at several lengths, down to nothing.
TEST_F(ResultsIntegrity, TruncatedFilesAreRefused) {
  const std::uint64_t size = damage::file_size(good_);
  for (const std::uint64_t keep : {size - 1, size / 2, std::uint64_t{1000}, std::uint64_t{0}}) {
    SCOPED_TRACE(keep);
    const std::string path = copy("cut.styk.h5");
    damage::truncate_file(path, keep);
    const std::string message = refusal(path);
    if (keep >= 1000)
      EXPECT_NE(message.find("the file is damaged"), std::string::npos) << message;
    else
      EXPECT_NE(message.find("is not an HDF5 file (0 bytes"), std::string::npos) << message;
  }
}

// A value rewritten through HDF5 (so its chunk's Fletcher-32 is right) is still not what the
// solver wrote: the CRC-32 refuses it, NaN or not.
TEST_F(ResultsIntegrity, ValueRewrittenBehindTheChecksumsIsRefused) {
  for (const double value : {std::nan(""), 0.125}) {
    const std::string path = copy("rewritten.styk.h5");
    damage::set_value(path, kU, 3, 1, value);
    EXPECT_EQ(refusal(path),
              path + ": dataset " + kU + ": checksum mismatch \u2014 the file is damaged");
  }
}

// A dataset lost or added (a partial or mixed copy whose datasets are each intact) is caught by
// the digest (the files sealed again: the seal would refuse them first).
TEST_F(ResultsIntegrity, LostOrAddedDatasetBreaksTheDigest) {
  const std::string lost = copy("lost.styk.h5");
  {
    const hid_t file = H5Fopen(lost.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(H5Ldelete(file, "/steps/step_2/increment_1/S_centroid", H5P_DEFAULT), 0);
    H5Fclose(file);
    damage::reseal(lost);
  }
  const std::string message = refusal(lost);
  EXPECT_NE(message.find("the file digest crc32:"), std::string::npos) << message;
  EXPECT_NE(message.find("does not match its datasets"), std::string::npos) << message;
  const std::string moved = copy("moved.styk.h5");
  {
    const hid_t file = H5Fopen(moved.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(H5Lmove(file, "/steps/step_2/increment_1/S_centroid", file,
                      "/steps/step_2/increment_1/E_centroid_copy", H5P_DEFAULT, H5P_DEFAULT),
              0);
    H5Fclose(file);
    damage::reseal(moved);
  }
  EXPECT_NE(refusal(moved).find("does not match its datasets"), std::string::npos);
}

bool same_contents(const ResultsFileContents& a, const ResultsFileContents& b) {
  if (a.model.node_ids != b.model.node_ids || a.model.coords != b.model.coords ||
      a.model.connectivity != b.model.connectivity || a.model.source != b.model.source ||
      a.model.heading != b.model.heading || a.styk_version != b.styk_version ||
      a.model.elements.size() != b.model.elements.size() ||
      a.results.increments.size() != b.results.increments.size())
    return false;
  for (std::size_t e = 0; e < a.model.elements.size(); ++e)
    if (a.model.elements[e].type != b.model.elements[e].type ||
        a.model.elements[e].id != b.model.elements[e].id)
      return false;
  for (std::size_t i = 0; i < a.results.increments.size(); ++i) {
    const IncrementResult& x = a.results.increments[i];
    const IncrementResult& y = b.results.increments[i];
    if (x.step != y.step || x.increment != y.increment || x.total_time != y.total_time ||
        x.step_time != y.step_time || x.U != y.U || x.RF != y.RF || x.S != y.S || x.E != y.E ||
        x.ip_offset != y.ip_offset || x.S_nodal_I != y.S_nodal_I || x.S_centroid != y.S_centroid ||
        x.S_element_nodes != y.S_element_nodes || x.contact.size() != y.contact.size() ||
        x.contact_pairs.size() != y.contact_pairs.size())
      return false;
    for (std::size_t c = 0; c < x.contact.size(); ++c)
      if (x.contact[c].pressure != y.contact[c].pressure ||
          x.contact[c].node != y.contact[c].node || x.contact[c].force != y.contact[c].force)
        return false;
  }
  return true;
}

// The experiment on a small file: random byte flips anywhere in the file, one per copy.
// The reader may refuse the copy, or read it, but then it must read exactly what was written:
// it never returns different numbers. (Flips that land in bytes HDF5 never reads, such as unused
// space, leave the contents intact.)
TEST_F(ResultsIntegrity, RandomByteFlipsAreRefusedOrChangeNothing) {
  const ResultsFileContents original = read_results_file(good_);
  const std::uint64_t size = damage::file_size(good_);
  std::mt19937_64 random(20);  // fixed seed: the same 200 offsets on every run
  std::uniform_int_distribution<std::uint64_t> offset(0, size - 1);
  int refused = 0, intact = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const std::uint64_t at = offset(random);
    const std::string path = copy("random.styk.h5");
    damage::flip_byte(path, at);
    try {
      const ResultsFileContents read = read_results_file(path);
      EXPECT_TRUE(same_contents(read, original))
          << "a flip at byte " << at << " changed the contents";
      ++intact;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, path);
      ++refused;
    }
  }
  std::printf("200 random flips in a %llu-byte file: %d refused, %d read back unchanged\n",
              static_cast<unsigned long long>(size), refused, intact);
  EXPECT_EQ(refused + intact, 200);
  EXPECT_GE(refused, 100);  // most bytes of a small file are metadata or values, all checksummed
}

// The writer refuses non-finite values in any dataset or real attribute, naming the dataset and
// the node / element and integration point (or beam station), and writes nothing (an older file
// stays in place).
TEST_F(ResultsIntegrity, WriterRefusesNonFiniteValuesNamingTheEntity) {
  const ResultsFileContents contents = read_results_file(good_);
  const std::string path = dir_ + "/nan.styk.h5";
  damage::copy_file(good_, path);
  struct Case {
    std::function<void(Results&)> spoil;
    std::string message;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Case> cases = {
      {[&](Results& r) { r.increments[1].U[3][1] = nan; },
       "dataset /steps/step_2/increment_1/U: node 4, component 2 is NaN, not a finite number"},
      {[&](Results& r) { r.increments[0].S[2][5] = -inf; },
       "dataset /steps/step_1/increment_1/S: element 1, integration point 3, component 6 is -Inf"},
      {[&](Results& r) {
         r.increments[0].S_nodal_I[7][0] = inf;
         r.increments[0].S_nodal_I[6][0] = inf;
       },
       "dataset /steps/step_1/increment_1/S_nodal_I: node 7, component 1 is +Inf (2 values of "
       "the dataset are not finite numbers)"},
      {[&](Results& r) {  // rotations of a model with beams: per node
         IncrementResult& inc = r.increments[1];
         inc.UR.assign(inc.U.size(), Vec3{0.0, 0.0, 0.0});
         inc.UR[3][0] = nan;
       },
       "dataset /steps/step_2/increment_1/UR: node 4, component 1 is NaN, not a finite number"},
      {[&](Results& r) {  // section forces: per element by station_offsets (element 1: 2 stations)
         IncrementResult& inc = r.increments[0];
         inc.station_offset.assign(contents.model.elements.size() + 1, 2);
         inc.station_offset[0] = 0;
         inc.SF.assign(2, Vec3{0.0, 0.0, 0.0});
         inc.SF[1][2] = -inf;
       },
       "dataset /steps/step_1/increment_1/SF: element 1, station 2, component 3 is -Inf"},
      {[&](Results& r) { r.increments[1].contact[2].pressure = nan; },
       "dataset /steps/step_2/increment_1/contact/pressure: contact slave node 7 is NaN"},
      {[&](Results& r) { r.increments[1].total_time = nan; },
       "attribute total_time of /steps/step_2/increment_1 is NaN, not a finite number"},
  };
  for (const Case& c : cases) {
    Results results = contents.results;
    c.spoil(results);
    try {
      write_results_file(path, contents.model, results);
      ADD_FAILURE() << "written: " << c.message;
    } catch (const NonFiniteResultsError& e) {
      EXPECT_NE(std::string(e.what()).find("cannot write results file " + path + ": " + c.message),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("nothing was written"), std::string::npos);
    }
    EXPECT_FALSE(io_test::file_exists(path + ".tmp"));
    EXPECT_TRUE(same_contents(read_results_file(path), contents)) << "the older file was touched";
  }
}

// Files written before checksums (tests/inputs/results/README.md): they open, not verified.
TEST(ResultsIntegrityLegacy, OlderFileOpensUnverifiedWithANotice) {
  const std::string path = kFixtures + "legacy-cube.styk.h5";
  const ResultsFileContents contents = read_results_file(path);
  EXPECT_FALSE(contents.verified);
  EXPECT_EQ(contents.styk_version, "0.1.0");
  ASSERT_EQ(contents.results.increments.size(), 2u);
  EXPECT_EQ(contents.model.node_count(), 8);
  for (int n = 0; n < 4; ++n) EXPECT_EQ(contents.results.increments[0].U[n], (Vec3{0, 0, 0}));
  for (int n = 4; n < 8; ++n) EXPECT_GT(contents.results.increments[0].U[n][2], 0.0);  // pulled up
  EXPECT_EQ(unverified_notice(path),
            path +
                ": notice: written before Styk results files carried checksums; what it holds "
                "cannot be verified");
}

// ... and one from a failed solve, holding Inf and NaN, is refused with dataset and entity named.
TEST(ResultsIntegrityLegacy, OlderFileWithNonFiniteStressesIsRefused) {
  const std::string path = kFixtures + "legacy-overflow.styk.h5";
  const std::string message = refusal(path);
  EXPECT_EQ(message.rfind(
                path + ": dataset /steps/step_1/increment_1/S: element 1, integration point ", 0),
            0u)
      << message;
  EXPECT_NE(message.find(" \u2014 a results file holds finite numbers only"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace styk
