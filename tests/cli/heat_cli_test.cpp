// The command line on a steady heat deck (docs/solver.md §8): `styk mesh cylinder-wall` writes the
// SPEC §6.2 deck, `styk info` counts one unknown per node, `styk solve` writes NT to the report,
// `styk render --field NT` draws the temperature (undeformed: the increment has no U) and
// `styk export --vtu` carries NT.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace styk::testing {
namespace {

TEST(HeatCli, MeshInfoSolveRenderExport) {
  const std::string dir = scratch_dir("heat_cli");
  const std::string styk = styk_executable();
  const CommandResult mesh =
      run_command(styk + " mesh cylinder-wall --element C3D20 --ntheta 12 --nz 1 -o wall.inp", dir);
  ASSERT_EQ(mesh.exit_code, 0) << mesh.err;
  const CommandResult info = run_command(styk + " info wall.inp", dir);
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("(1 per used node: temperature"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("heat transfer (steady)"), std::string::npos) << info.out;
  const CommandResult solve = run_command(styk + " solve -q wall.inp -o out", dir);
  ASSERT_EQ(solve.exit_code, 0) << solve.err;
  const std::string dat = read_file(dir + "/out/wall.dat");
  EXPECT_NE(dat.find(" temperatures for set NALL and time  0.1000000E+01"), std::string::npos);
  const CommandResult render =
      run_command(styk + " render out/wall.styk.h5 --field NT --size 320x240 -o wall.png", dir);
  EXPECT_EQ(render.exit_code, 0) << render.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/wall.png"));
  const CommandResult flux = run_command(
      styk + " render out/wall.styk.h5 --field HFL.mag --size 320x240 -o flux.png", dir);
  EXPECT_EQ(flux.exit_code, 0) << flux.err;
  const CommandResult wrong =
      run_command(styk + " render out/wall.styk.h5 --field EPOT -o epot.png", dir);
  EXPECT_EQ(wrong.exit_code, 1);
  EXPECT_NE(wrong.err.find("holds no EPOT"), std::string::npos) << wrong.err;
  const CommandResult vtu = run_command(styk + " export out/wall.styk.h5 --vtu -o wall.vtu", dir);
  ASSERT_EQ(vtu.exit_code, 0) << vtu.err;
  EXPECT_NE(read_file(dir + "/wall.vtu").find("Name=\"NT\""), std::string::npos);
}

}  // namespace
}  // namespace styk::testing
