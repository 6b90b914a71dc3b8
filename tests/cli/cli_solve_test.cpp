// The `styk` command line: sub-commands, help, outputs and their atomicity.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace styk::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSample = std::string(STYK_SOURCE_DIR) + "/samples/cantilever-c3d20.inp";

TEST(Cli, HelpForEverySubcommand) {
  const std::string dir = scratch_dir("cli_help");
  for (const char* sub : {"", "solve", "info", "export", "elements"}) {
    const CommandResult r = run_command(styk_executable() + " " + sub + " --help", dir);
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub << ": " << r.out;
  }
}

TEST(Cli, NoSubcommandIsBadInput) {
  const CommandResult r = run_command(styk_executable(), scratch_dir("cli_nosub"));
  EXPECT_EQ(r.exit_code, 1);
}

TEST(Cli, SolveWritesResultsAndReportAndNothingElse) {
  const std::string dir = scratch_dir("cli_solve");
  const CommandResult r = run_command(styk_executable() + " solve '" + kSample + "' -o out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/out/cantilever-c3d20.styk.h5"));
  EXPECT_TRUE(fs::exists(dir + "/out/cantilever-c3d20.dat"));
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir + "/out")) {
    ++files;
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
  EXPECT_EQ(files, 2);
  EXPECT_NE(r.out.find("cantilever-c3d20.styk.h5"), std::string::npos) << r.out;
  // Progress lines with timings for the long phases go to stderr.
  for (const char* phase : {"read", "assemble", "factorise", "recover", "write"})
    EXPECT_NE(r.err.find(phase), std::string::npos) << phase << " missing in:\n" << r.err;
}

// Resource limits (docs/cli.md, exit code 5): the direct solver's factor is estimated from the
// symbolic analysis before factorising. Under a 10 kB limit the cantilever's factor (about 1 MB)
// does not fit: a forced direct solve stops with the estimate and writes nothing; the automatic
// choice switches to the iterative solver and solves.
TEST(Cli, MemoryLimitStopsTheDirectSolverBeforeFactorising) {
  const std::string dir = scratch_dir("cli_memory_limit");
  const CommandResult forced = run_command(
      styk_executable() + " solve '" + kSample + "' --solver cholmod --memory-limit 1e-5 -o out",
      dir);
  EXPECT_EQ(forced.exit_code, 5) << forced.err;
  EXPECT_NE(forced.err.find("resource limit: the Cholesky factor of this model needs"),
            std::string::npos)
      << forced.err;
  EXPECT_NE(forced.err.find("more than the memory limit of 1e-05 GB (--memory-limit)"),
            std::string::npos)
      << forced.err;
  EXPECT_NE(forced.err.find("SOLVER=ITERATIVE"), std::string::npos) << forced.err;
  EXPECT_FALSE(fs::exists(dir + "/out/cantilever-c3d20.styk.h5"));
  EXPECT_FALSE(fs::exists(dir + "/out/cantilever-c3d20.dat"));

  const CommandResult automatic =
      run_command(styk_executable() + " solve '" + kSample + "' --memory-limit 1e-5 -o auto", dir);
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  EXPECT_NE(automatic.err.find("switching to the iterative solver"), std::string::npos)
      << automatic.err;
  EXPECT_TRUE(fs::exists(dir + "/auto/cantilever-c3d20.styk.h5"));
}

TEST(Cli, InfoCountsTheModel) {
  const CommandResult r =
      run_command(styk_executable() + " info '" + kSample + "'", scratch_dir("cli_info"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* what : {"nodes:", "elements:", "C3D20", "dofs:", "materials:", "steps:"})
    EXPECT_NE(r.out.find(what), std::string::npos) << what << " missing in:\n" << r.out;
}

TEST(Cli, ElementsListsTheBuiltIns) {
  const CommandResult r = run_command(styk_executable() + " elements", scratch_dir("cli_elements"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("C3D8"), std::string::npos);
  EXPECT_NE(r.out.find("C3D20"), std::string::npos);
  EXPECT_NE(r.out.find("built-in"), std::string::npos);
  // The tetrahedra, wedges and rings, each with its form and CalculiX's rules.
  for (const char* line :
       {"C3D4         4  solid         1-point tetrahedron",
        "C3D10       10  solid         4-point tetrahedron",
        "C3D6         6  solid         1x2 wedge", "C3D15       15  solid         3x3 wedge",
        "CAX8R        8  axisymmetric  2x2 Gauss", "CPS8R        8  planar        2x2 Gauss"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
}

TEST(Cli, ExportVtuFromResultsAndFromDeck) {
  const std::string dir = scratch_dir("cli_export");
  ASSERT_EQ(run_command(styk_executable() + " solve -q '" + kSample + "' -o .", dir).exit_code, 0);
  const CommandResult from_results =
      run_command(styk_executable() + " export cantilever-c3d20.styk.h5 --vtu -o r.vtu", dir);
  EXPECT_EQ(from_results.exit_code, 0) << from_results.err;
  EXPECT_NE(read_file(dir + "/r.vtu").find("<VTKFile"), std::string::npos);
  const CommandResult from_deck =
      run_command(styk_executable() + " export '" + kSample + "' --vtu -o m.vtu", dir);
  EXPECT_EQ(from_deck.exit_code, 0) << from_deck.err;
  EXPECT_TRUE(fs::exists(dir + "/m.vtu"));
  const CommandResult bad_step =
      run_command(styk_executable() + " export cantilever-c3d20.styk.h5 --vtu --step 7", dir);
  EXPECT_EQ(bad_step.exit_code, 1);
  EXPECT_NE(bad_step.err.find("available"), std::string::npos) << bad_step.err;
}

}  // namespace
}  // namespace styk::testing
