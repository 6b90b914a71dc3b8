// Results files that cannot lie, on the command line (docs/results.md "Integrity", docs/cli.md):
// `styk render`, `styk export --vtu` and `styk check` on a results file solved from
// tests/inputs/results/cube.inp and then damaged — a byte flipped in a stored chunk, the file cut
// short, a zeroed block, a NaN written behind the checksums — and on the files of an older Styk.
// Each damaged file: exit 1, "file: dataset ...: ... — the file is damaged" on stderr, no output
// left behind. And `styk solve` refuses to write results that overflowed to Inf/NaN (exit 2).
#include <gtest/gtest.h>
#include <cctype>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "results_damage.hpp"

namespace styk::testing {
namespace {

namespace fs = std::filesystem;

const std::string kInputs = std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/";
const std::string kU = "/steps/step_2/increment_1/U";
const std::string kDash = "\u2014";

struct Damage {
  std::string name;
  std::function<void(const std::string&)> apply;
  std::string message;  // expected on stderr after "<file>: "
};

class CliResultsIntegrity : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each test of the suite as its own process, in parallel: each gets its own
    // directory (named after the gtest filter ctest passes), so no two solves share a file.
    std::string name = ::testing::GTEST_FLAG(filter);
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    dir_ = scratch_dir("results_integrity_" + name);
    const CommandResult solved = run_command(
        styk_executable() + " solve -q '" + kInputs + "cube.inp' -o '" + dir_ + "'", dir_);
    ASSERT_EQ(solved.exit_code, 0) << solved.err;
  }
  static std::string good() { return dir_ + "/cube.styk.h5"; }

  // A fresh copy of the solved file with one kind of damage.
  static std::string damaged(const Damage& d) {
    const std::string path = dir_ + "/" + d.name + ".styk.h5";
    damage::copy_file(good(), path);
    d.apply(path);
    return path;
  }

  static std::vector<Damage> damages() {
    const std::string mismatch =
        "dataset " + kU + ": checksum mismatch " + kDash + " the file is damaged";
    return {
        {"flipped",
         [](const std::string& p) {
           const damage::StoredBytes chunk = damage::first_chunk(p, kU);
           damage::flip_byte(p, chunk.offset + 5);
         },
         mismatch},
        {"zeroed_chunk",
         [](const std::string& p) {
           const damage::StoredBytes chunk = damage::first_chunk(p, kU);
           damage::zero_bytes(p, chunk.offset, chunk.size);
         },
         mismatch},
        {"zeroed_block", [](const std::string& p) { damage::zero_bytes(p, 0, 4096); },
         "is not an HDF5 file ("},
        {"truncated",
         [](const std::string& p) { damage::truncate_file(p, damage::file_size(p) / 2); },
         "HDF5 cannot open it: truncated file"},
        {"nan", [](const std::string& p) { damage::set_value(p, kU, 5, 2, std::nan("")); },
         mismatch},
    };
  }

  static std::string dir_;
};

std::string CliResultsIntegrity::dir_;

void expect_refused(const CommandResult& r, const std::string& file, const std::string& message,
                    const std::string& output) {
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(file + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << "expected: " << message << "\n" << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  if (!output.empty()) {
    EXPECT_FALSE(fs::exists(output)) << output << " was written";
  }
}

TEST_F(CliResultsIntegrity, WholeFileRendersExportsAndChecks) {
  const std::string png = dir_ + "/good.png", vtu = dir_ + "/good.vtu";
  CommandResult r = run_command(styk_executable() + " render '" + good() +
                                    "' --field S.mises --size 320x240 -o '" + png + "'",
                                dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(png));
  EXPECT_EQ(r.err.find("notice"), std::string::npos) << r.err;
  r = run_command(styk_executable() + " export '" + good() + "' --vtu -o '" + vtu + "'", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(vtu));
  r = run_command(styk_executable() + " check '" + good() + "'", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind(good() + ": whole " + kDash + " schema 1, Styk ", 0), 0u) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST_F(CliResultsIntegrity, RenderRefusesEveryDamage) {
  for (const Damage& d : damages()) {
    SCOPED_TRACE(d.name);
    const std::string file = damaged(d), png = dir_ + "/" + d.name + ".png";
    expect_refused(
        run_command(styk_executable() + " render '" + file + "' --field U -o '" + png + "'", dir_),
        file, d.message, png);
  }
}

TEST_F(CliResultsIntegrity, ExportRefusesEveryDamage) {
  for (const Damage& d : damages()) {
    SCOPED_TRACE(d.name);
    const std::string file = damaged(d), vtu = dir_ + "/" + d.name + ".vtu";
    expect_refused(
        run_command(styk_executable() + " export '" + file + "' --vtu -o '" + vtu + "'", dir_),
        file, d.message, vtu);
  }
}

TEST_F(CliResultsIntegrity, CheckFindsEveryDamage) {
  for (const Damage& d : damages()) {
    SCOPED_TRACE(d.name);
    const std::string file = damaged(d);
    const CommandResult r = run_command(styk_executable() + " check '" + file + "'", dir_);
    expect_refused(r, file, d.message, "");
    EXPECT_EQ(r.out.rfind(file + ": damaged " + kDash + " ", 0), 0u) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one verdict line: " << r.out;
  }
}

// Files of an older Styk (tests/inputs/results/README.md).
TEST_F(CliResultsIntegrity, OlderFilesOpenWithANoticeOrAreRefusedWhenNotFinite) {
  const std::string legacy = kInputs + "legacy-cube.styk.h5";
  const std::string notice = legacy +
                             ": notice: written before Styk results files carried checksums; what "
                             "it holds cannot be verified\n";
  CommandResult r = run_command(
      styk_executable() + " render '" + legacy + "' -o '" + dir_ + "/legacy.png' --size 320x240",
      dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, notice);
  r = run_command(styk_executable() + " export '" + legacy + "' --vtu -o '" + dir_ + "/legacy.vtu'",
                  dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, notice);
  r = run_command(styk_executable() + " check '" + legacy + "'", dir_);
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(r.out.rfind(legacy + ": cannot be verified " + kDash + " written before", 0), 0u)
      << r.out;

  const std::string overflow = kInputs + "legacy-overflow.styk.h5";
  const std::string nan_message =
      "dataset /steps/step_1/increment_1/S: element 1, integration point 1, component 3 is +Inf "
      "(8 values of the dataset are not finite numbers)";
  expect_refused(run_command(styk_executable() + " render '" + overflow + "' --field S.mises -o '" +
                                 dir_ + "/overflow.png'",
                             dir_),
                 overflow, nan_message, dir_ + "/overflow.png");
  expect_refused(run_command(styk_executable() + " export '" + overflow + "' --vtu -o '" + dir_ +
                                 "/overflow.vtu'",
                             dir_),
                 overflow, nan_message, dir_ + "/overflow.vtu");
  expect_refused(run_command(styk_executable() + " check '" + overflow + "'", dir_), overflow,
                 nan_message, "");
}

// The solve that overflows (E = 1e300 under 5e307 per node): exit 2 with the cause, nothing
// written (neither the results file nor the .dat report).
TEST_F(CliResultsIntegrity, SolveRefusesToWriteNonFiniteResults) {
  const std::string out = dir_ + "/overflow_out";
  const CommandResult r = run_command(
      styk_executable() + " solve -q '" + kInputs + "overflow.inp' -o '" + out + "'", dir_);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("not converged: cannot write results file " + out +
                       "/overflow.styk.h5: dataset /steps/step_1/increment_1/S: element 1, "
                       "integration point 1, component 3 is +Inf"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("nothing was written"), std::string::npos) << r.err;
  EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << "files left in " << out;
}

}  // namespace
}  // namespace styk::testing
