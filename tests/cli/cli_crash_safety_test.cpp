// Crash safety of `styk solve` (docs/cli.md "Interrupted runs and full disks"): every output is
// written to "<file>.tmp" and renamed onto its name only when complete (io::TempFile), so
//  - a run stopped by SIGINT, SIGTERM or SIGHUP while writing leaves the previous results
//    byte for byte and no temporary (the handlers remove it, then the signal ends the process);
//  - a run killed by SIGKILL while writing leaves the previous results byte for byte (a stale
//    temporary may remain; the next run replaces it and leaves none);
//  - a run whose files do not fit (here the file-size limit `ulimit -f`, which fails a write as a
//    full disk does) stops with exit 5 and "resource limit: cannot write ...", the previous
//    results unchanged and no temporary left.
// The model: a 40 x 5 x 5 C3D8 cantilever (4.6k nodes) printing U, S and E to the .dat, so the
// write phase lasts long enough (~0.1-0.2 s) for a signal sent when a temporary appears to land
// inside it; the "previous" results come from the same deck with half the tip load, so they
// differ from the interrupted run's.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_runner.hpp"

namespace styk::testing {
namespace {

namespace fs = std::filesystem;

// The cantilever deck with tip load `load` (docs: file comment).
std::string beam_deck(double load) {
  constexpr int nx = 40, ny = 5, nz = 5;
  const auto id = [](int i, int j, int k) {
    return k * (nx + 1) * (ny + 1) + j * (nx + 1) + i + 1;
  };
  std::ostringstream out;
  out << "*NODE, NSET=NALL\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        out << id(i, j, k) << ", " << i << ", " << j << ", " << k << "\n";
  out << "*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
  int e = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        out << e++ << ", " << id(i, j, k) << ", " << id(i + 1, j, k) << ", " << id(i + 1, j + 1, k)
            << ", " << id(i, j + 1, k) << ", " << id(i, j, k + 1) << ", " << id(i + 1, j, k + 1)
            << ", " << id(i + 1, j + 1, k + 1) << ", " << id(i, j + 1, k + 1) << "\n";
  out << "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
      << "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*BOUNDARY\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j) out << id(0, j, k) << ", 1, 3\n";
  out << "*STEP\n*STATIC\n*CLOAD\n"
      << id(nx, ny, nz) << ", 3, " << load << "\n"
      << "*NODE PRINT, NSET=NALL\nU\n*EL PRINT, ELSET=EALL\nS, E\n*END STEP\n";
  return out.str();
}

std::vector<std::string> temporaries(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".tmp") out.push_back(entry.path().filename().string());
  return out;
}

class CliCrashSafety : public ::testing::Test {
 protected:
  // A directory holding beam.inp and the previous results (solved with half the load), whose
  // bytes are kept; then beam.inp is rewritten with the full load for the run under test.
  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = scratch_dir("crash_safety_" + name);
    std::ofstream(dir_ + "/beam.inp") << beam_deck(-50.0);
    const CommandResult first = run_command(solve_command(), dir_);
    ASSERT_EQ(first.exit_code, 0) << first.err;
    previous_h5_ = read_file(h5());
    previous_dat_ = read_file(dat());
    ASSERT_GT(previous_h5_.size(), 100000u);
    std::ofstream(dir_ + "/beam.inp") << beam_deck(-100.0);
  }

  std::string solve_command() const {
    return styk_executable() + " solve -q '" + dir_ + "/beam.inp' -o '" + dir_ + "'";
  }
  std::string h5() const { return dir_ + "/beam.styk.h5"; }
  std::string dat() const { return dir_ + "/beam.dat"; }

  // The previous results are there, byte for byte, and `styk check` finds them sound.
  void expect_previous_results() const {
    EXPECT_TRUE(read_file(h5()) == previous_h5_) << "the previous results file changed";
    EXPECT_TRUE(read_file(dat()) == previous_dat_) << "the previous .dat changed";
    const CommandResult check = run_command(styk_executable() + " check '" + h5() + "'", dir_);
    EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  }

  // Runs the solve, waits until `temporary` (a file name in the directory) appears, sends
  // `signal_number` and returns the wait status. Fails the test when the solve ends before the
  // temporary was seen.
  int solve_and_signal_when(const std::string& temporary, int signal_number) const {
    const std::string executable = styk_executable();
    const std::string deck = dir_ + "/beam.inp";
    const pid_t pid = fork();
    if (pid == 0) {
      std::freopen("/dev/null", "w", stdout);
      std::freopen("/dev/null", "w", stderr);
      execl(executable.c_str(), executable.c_str(), "solve", deck.c_str(), "-o", dir_.c_str(),
            static_cast<char*>(nullptr));
      _exit(127);
    }
    const fs::path watched = fs::path(dir_) / temporary;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline) {
      std::error_code ec;
      if (fs::exists(watched, ec)) {
        kill(pid, signal_number);
        waitpid(pid, &status, 0);
        return status;
      }
      if (waitpid(pid, &status, WNOHANG) == pid) {
        ADD_FAILURE() << "the solve ended before " << temporary << " was seen";
        return status;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    ADD_FAILURE() << temporary << " never appeared";
    return status;
  }

  std::string dir_;
  std::string previous_h5_, previous_dat_;
};

// SIGTERM / SIGINT / SIGHUP while the .dat or the results file is being written: the process
// dies of the signal, no temporary remains, the previous results are intact.
TEST_F(CliCrashSafety, AnInterruptedWriteLeavesThePreviousResultsAndNoTemporary) {
  const struct {
    const char* temporary;
    int signal_number;
  } cases[] = {{"beam.dat.tmp", SIGTERM},
               {"beam.styk.h5.tmp", SIGTERM},
               {"beam.styk.h5.tmp", SIGINT},
               {"beam.dat.tmp", SIGHUP}};
  for (const auto& c : cases) {
    const int status = solve_and_signal_when(c.temporary, c.signal_number);
    ASSERT_TRUE(WIFSIGNALED(status)) << c.temporary << ": exit status " << status;
    EXPECT_EQ(WTERMSIG(status), c.signal_number) << c.temporary;
    EXPECT_TRUE(temporaries(dir_).empty()) << c.temporary << ": " << temporaries(dir_).front();
    expect_previous_results();
  }
}

// SIGKILL (no handler can run) while writing: the previous results are intact; the next run
// completes, replaces the stale temporary and leaves none.
TEST_F(CliCrashSafety, AKilledWriteLeavesThePreviousResults) {
  for (const char* temporary : {"beam.dat.tmp", "beam.styk.h5.tmp"}) {
    const int status = solve_and_signal_when(temporary, SIGKILL);
    ASSERT_TRUE(WIFSIGNALED(status)) << temporary;
    EXPECT_EQ(WTERMSIG(status), SIGKILL) << temporary;
    expect_previous_results();
  }
  const CommandResult rerun = run_command(solve_command(), dir_);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_TRUE(temporaries(dir_).empty());
  EXPECT_FALSE(read_file(h5()) == previous_h5_);  // the new load's results
  const CommandResult check = run_command(styk_executable() + " check '" + h5() + "'", dir_);
  EXPECT_EQ(check.exit_code, 0) << check.err;
}

// A file-size limit of 64 KiB (the results need ~2 MB): exit 5, a message naming the file and
// the cause, the previous results unchanged, no temporary. styk ignores SIGXFSZ, so the limit
// fails the write instead of killing the process, as a full disk would.
TEST_F(CliCrashSafety, AFullDiskStopsWithExitFiveAndKeepsThePreviousResults) {
  const CommandResult run =
      run_command("bash -c \"ulimit -f 64; exec " + solve_command() + "\"", dir_);
  EXPECT_EQ(run.exit_code, 5) << run.err;
  EXPECT_NE(run.err.find("resource limit: cannot write"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("size limit of this process"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("is unchanged"), std::string::npos) << run.err;
  EXPECT_TRUE(temporaries(dir_).empty());
  expect_previous_results();
}

}  // namespace
}  // namespace styk::testing
