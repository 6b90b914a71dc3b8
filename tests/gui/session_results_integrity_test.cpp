// The GUI session's results loading (Document::open_results) on damaged and older results files
// (docs/results.md "Integrity"): a byte flip, a cut, a zeroed chunk, a NaN written behind the
// checksums and an older file holding Inf are refused with the reader's message — file, dataset,
// "the file is damaged" — and the document keeps what it showed; an older sound file opens with
// the notice that it cannot be verified.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "results_damage.hpp"
#include "session/document.hpp"
#include "styk/elements/builtin.hpp"

namespace styk::gui {
namespace {

const std::string kInputs = std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/";
const std::string kU = "/steps/step_2/increment_1/U";

std::string scratch(const std::string& name) {
  // One directory per test: ctest runs the suite's tests as parallel processes.
  const std::string dir = std::string(STYK_BINARY_DIR) + "/tests/gui/scratch_integrity/" +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  return dir + "/" + name;
}

class SessionResultsIntegrity : public ::testing::Test {
 protected:
  SessionResultsIntegrity() : doc(registry) {
    register_builtin_elements(registry);
    good = damage::write_cube_results(scratch("good.styk.h5"));
    doc.open_results(good);
  }
  // Opening `path` must throw with `message` in what() and leave the document as it was.
  void expect_refused(const std::string& path, const std::string& message) {
    const long revision = doc.revision();
    try {
      doc.open_results(path);
      ADD_FAILURE() << path << " opened";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, path);
      EXPECT_NE(std::string(e.what()).find(path + ": " + message), std::string::npos) << e.what();
    }
    EXPECT_EQ(doc.revision(), revision);
    EXPECT_EQ(doc.path(), good);
    EXPECT_EQ(doc.results_path(), good);
    ASSERT_NE(doc.results(), nullptr);
    EXPECT_EQ(doc.results()->increments.size(), 2u);
    EXPECT_DOUBLE_EQ(doc.results()->increments[1].U[5][2], 5e-4 * 2 * 1.0);  // node 6 at z = 1
    EXPECT_TRUE(doc.results_notice().empty());
  }
  std::string copy(const std::string& name) {
    const std::string path = scratch(name);
    damage::copy_file(good, path);
    return path;
  }
  ElementRegistry registry;
  Document doc;
  std::string good;
};

TEST_F(SessionResultsIntegrity, WholeFileOpensVerified) {
  EXPECT_EQ(doc.path(), good);
  EXPECT_TRUE(doc.results_notice().empty());
  EXPECT_EQ(doc.model().node_count(), 8);
}

TEST_F(SessionResultsIntegrity, DamagedFilesAreRefusedAndTheDocumentKept) {
  const std::string mismatch = "dataset " + kU + ": checksum mismatch \u2014 the file is damaged";
  std::string path = copy("flipped.styk.h5");
  damage::flip_byte(path, damage::first_chunk(path, kU).offset + 7);
  expect_refused(path, mismatch);

  path = copy("zeroed.styk.h5");
  const damage::StoredBytes chunk = damage::first_chunk(path, kU);
  damage::zero_bytes(path, chunk.offset, chunk.size);
  expect_refused(path, mismatch);

  path = copy("cut.styk.h5");
  damage::truncate_file(path, damage::file_size(path) * 2 / 3);
  expect_refused(path, "HDF5 cannot open it: truncated file");

  path = copy("nan.styk.h5");
  damage::set_value(path, kU, 0, 0, std::nan(""));
  expect_refused(path, mismatch);

  expect_refused(kInputs + "legacy-overflow.styk.h5",
                 "dataset /steps/step_1/increment_1/S: element 1, integration point 1, component 3 "
                 "is +Inf");
}

TEST_F(SessionResultsIntegrity, OlderFileOpensWithItsNoticeUntilTheNextOpen) {
  const std::string legacy = kInputs + "legacy-cube.styk.h5";
  doc.open_results(legacy);
  EXPECT_EQ(doc.results_notice(),
            legacy +
                ": notice: written before Styk results files carried checksums; what it "
                "holds cannot be verified");
  ASSERT_NE(doc.results(), nullptr);
  EXPECT_EQ(doc.results()->increments.size(), 2u);
  doc.open_results(good);
  EXPECT_TRUE(doc.results_notice().empty());
  doc.open_results(legacy);
  doc.open_inp(kInputs + "cube.inp");
  EXPECT_TRUE(doc.results_notice().empty());
}

}  // namespace
}  // namespace styk::gui
