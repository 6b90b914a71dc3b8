// check_results_file (`styk check`): the verdict and the problems it lists for a whole file, an
// older one, and the damaged kinds of results_integrity_test.cpp; also a dataset this build does
// not know, which the check reads like any other.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "io_test_support.hpp"
#include "results_damage.hpp"
#include "results_file_layout.hpp"
#include "styk/io/results_check.hpp"
#include "styk/io/results_file.hpp"

namespace styk {
namespace {

const std::string kFixtures = std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/";
const std::string kU = "/steps/step_2/increment_1/U";

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

class ResultsCheckTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = io_test::fresh_dir(std::string("check_") +
                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
    good_ = damage::write_cube_results(dir_ + "/good.styk.h5");
  }
  std::string copy(const std::string& name) {
    const std::string path = dir_ + "/" + name;
    damage::copy_file(good_, path);
    return path;
  }
  std::string dir_, good_;
};

TEST_F(ResultsCheckTest, WholeFile) {
  const ResultsCheck report = check_results_file(good_);
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Whole) << joined(report.problems);
  EXPECT_TRUE(report.problems.empty());
  EXPECT_EQ(report.steps, 2);
  EXPECT_EQ(report.increments, 2);
  EXPECT_EQ(report.schema_version, 1);
  EXPECT_EQ(report.digest.rfind("crc32:", 0), 0u);
  EXPECT_GE(report.datasets, 40u);
  EXPECT_EQ(report.summary.rfind("whole \u2014 schema 1, Styk ", 0), 0u) << report.summary;
  EXPECT_NE(report.summary.find("2 step(s), 2 increment(s); "), std::string::npos);
  EXPECT_NE(report.summary.find(" match their Fletcher-32 and CRC-32 checksums and the digest " +
                                report.digest),
            std::string::npos);
}

// Every damaged dataset is listed, not only the first.
TEST_F(ResultsCheckTest, ListsEveryDamagedDataset) {
  const std::string path = copy("two.styk.h5");
  for (const char* dataset : {"/model/nodes/coordinates", "/steps/step_2/increment_1/U"}) {
    const damage::StoredBytes chunk = damage::first_chunk(path, dataset);
    damage::flip_byte(path, chunk.offset + 3);
  }
  const ResultsCheck report = check_results_file(path);
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged);
  ASSERT_EQ(report.problems.size(), 2u) << joined(report.problems);
  EXPECT_EQ(report.problems[0],
            "dataset /model/nodes/coordinates: checksum mismatch \u2014 the file is damaged");
  EXPECT_EQ(report.problems[1], "dataset " + kU + ": checksum mismatch \u2014 the file is damaged");
  EXPECT_EQ(report.summary, "damaged \u2014 2 problem(s), the first: " + report.problems[0]);
}

TEST_F(ResultsCheckTest, ZeroedChunkAndTruncation) {
  const std::string zeroed = copy("zeroed.styk.h5");
  const damage::StoredBytes chunk = damage::first_chunk(zeroed, kU);
  damage::zero_bytes(zeroed, chunk.offset, chunk.size);
  ResultsCheck report = check_results_file(zeroed);
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged);
  EXPECT_EQ(joined(report.problems),
            "dataset " + kU + ": checksum mismatch \u2014 the file is damaged\n");

  const std::string cut = copy("cut.styk.h5");
  damage::truncate_file(cut, damage::file_size(cut) / 2);
  report = check_results_file(cut);
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged);
  ASSERT_EQ(report.problems.size(), 1u);
  EXPECT_NE(report.problems[0].find("truncated"), std::string::npos) << report.problems[0];
  EXPECT_NE(report.problems[0].find("the file is damaged"), std::string::npos);
}

TEST_F(ResultsCheckTest, NanRewrittenBehindTheChecksums) {
  const std::string path = copy("nan.styk.h5");
  damage::set_value(path, kU, 3, 1, std::nan(""));
  const ResultsCheck report = check_results_file(path);
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged);
  // The CRC-32 disagrees, and the value is named too.
  EXPECT_EQ(joined(report.problems), "dataset " + kU +
                                         ": checksum mismatch \u2014 the file is damaged\n"
                                         "dataset " +
                                         kU +
                                         ": node 4, component 2 is NaN, not a finite number\n");
}

TEST(ResultsCheckLegacy, OlderFilesCannotBeVerified) {
  const ResultsCheck good = check_results_file(kFixtures + "legacy-cube.styk.h5");
  EXPECT_EQ(good.verdict, ResultsCheck::Verdict::Unverifiable) << joined(good.problems);
  EXPECT_EQ(good.summary.rfind("cannot be verified \u2014 written before results files carried "
                               "checksums (Styk 0.1.0, schema 1); 2 step(s), 2 increment(s); ",
                               0),
            0u)
      << good.summary;
  const ResultsCheck overflow = check_results_file(kFixtures + "legacy-overflow.styk.h5");
  EXPECT_EQ(overflow.verdict, ResultsCheck::Verdict::Damaged);
  ASSERT_GE(overflow.problems.size(), 2u);  // S and the recovered stresses
  for (const std::string& problem : overflow.problems)
    EXPECT_NE(problem.find(" is "), std::string::npos) << problem;
  EXPECT_NE(joined(overflow.problems).find("dataset /steps/step_1/increment_1/S_nodal_I: node "),
            std::string::npos)
      << joined(overflow.problems);
}

// Datasets this build does not know (future fields, here XN per node and XE per element; UR and
// SF, which this test once used, are known now) are read and their values checked like any other.
// Their rows are named by their count when it fits one entity only (1 = the element), by number
// otherwise (8 = nodes, element nodes and integration points of the cube alike).
TEST_F(ResultsCheckTest, UnknownDatasetsAreScannedToo) {
  const ResultsFileContents contents = read_results_file(good_);
  const std::string path = dir_ + "/older_layout.styk.h5";
  io::write_results_file_as(path, contents.model, contents.results, io::ResultsLayout::PreChecksum);
  auto add = [&](const char* name, hsize_t rows, std::size_t bad) {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hsize_t dims[2] = {rows, 3};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t d =
        H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> values(rows * 3, 0.5);
    values[bad] = std::nan("");
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(d);
    H5Sclose(space);
    H5Fclose(file);
  };
  add("/steps/step_1/increment_1/XN", 8, 3 * 5 + 2);
  add("/steps/step_2/increment_1/XE", 1, 1);
  const ResultsCheck report = check_results_file(path);
  EXPECT_EQ(joined(report.problems),
            "dataset /steps/step_1/increment_1/XN: row 5, component 3 is NaN, not a finite number\n"
            "dataset /steps/step_2/increment_1/XE: element 1, component 2 is NaN, not a finite "
            "number\n");
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged);
}

TEST(ResultsCheckMissing, MissingAndForeignFiles) {
  const std::string dir = io_test::fresh_dir("check_missing");
  ResultsCheck report = check_results_file(dir + "/none.styk.h5");
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged);
  EXPECT_EQ(joined(report.problems), "cannot be opened: No such file or directory\n");
  { std::ofstream(dir + "/text.styk.h5") << "not hdf5 at all"; }
  report = check_results_file(dir + "/text.styk.h5");
  ASSERT_EQ(report.problems.size(), 1u);
  EXPECT_EQ(report.problems[0].rfind("is not an HDF5 file (15 bytes", 0), 0u) << report.problems[0];
}

}  // namespace
}  // namespace styk
