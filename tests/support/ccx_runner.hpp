// Runs CalculiX (`ccx`, the peer of the cross-check suites) on a deck in a directory.
#pragma once

#include <filesystem>
#include <string>

namespace styk::test {

// What to tell the developer when ccx is missing.
inline constexpr const char* kCcxMissing =
    "ccx (CalculiX) is not on PATH: scripts/install-deps.sh --test installs calculix-ccx";

bool ccx_on_path();

struct CcxRun {
  int exit_code = -1;  // the shell's status: 0 when ccx finished
  std::string log;     // ccx's stdout and stderr, also kept in <dir>/<job>.log
};

// `ccx -i job` in `dir` (job.inp there) after removing a job.dat of an earlier run, on one thread
// (OMP_NUM_THREADS=1: the peer's numbers do not depend on the machine's cores). With
// timeout_seconds > 0 the run is stopped after that long (exit code 124).
CcxRun run_ccx(const std::filesystem::path& dir, const std::string& job, int timeout_seconds = 0);

}  // namespace styk::test
