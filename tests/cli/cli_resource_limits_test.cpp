// Resource limits that must be refused at once with a clear message, never a hang, a crash or a
// misleading "out of memory" after minutes (docs/input.md "Ids", docs/mesher.md "Limits"):
// a GENERATE range over every 32-bit id is matched against the model's nodes instead of walked
// id by id, and a mesher block that cannot be indexed with 32-bit ints, or that needs more memory
// than the machine has, is refused before anything is allocated; headings and set names beyond
// HDF5's 64 KiB header messages are written whole. Ids beyond 32 bits in a deck are in
// tests/inputs/bad/ (cli_bad_input_test.cpp).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "support/test_scratch.hpp"

namespace styk::testing {
namespace {

namespace fs = std::filesystem;

const std::string kCube = std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/cube.inp";

// The unit cube of tests/inputs/results with `extra` inserted before *MATERIAL.
std::string cube_with(const std::string& extra) {
  std::string deck = read_file(kCube);
  deck.insert(deck.find("*MATERIAL"), extra);
  return deck;
}

// *NSET, GENERATE over 1 .. 2147483647 (the largest id): before, the reader looked up each of the
// 2.1 billion ids (tens of seconds; with 64-bit ids a range 1, 9223372036854775807 never ended).
// Now it takes the model's 8 nodes; 10 s is far above that and far below the walk.
TEST(ResourceLimits, GenerateOverEveryIdTakesTheModelsNodes) {
  const fs::path dir = test::test_scratch_dir("resource_limits");
  // ODD is printed, so its members are checked, not only the time.
  std::string deck = cube_with(
      "*NSET, NSET=EVERY, GENERATE\n1, 2147483647\n*NSET, NSET=ODD, GENERATE\n1, 2147483647, 2\n"
      "*ELSET, ELSET=EVERYE, GENERATE\n1, 2147483647\n");
  for (std::size_t at; (at = deck.find("*NODE PRINT, NSET=TOP")) != std::string::npos;)
    deck.replace(at, 21, "*NODE PRINT, NSET=ODD");
  std::ofstream(dir / "generate.inp") << deck;
  const auto start = std::chrono::steady_clock::now();
  const CommandResult run =
      run_command(styk_executable() + " solve -q generate.inp -o out", dir.string());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LT(seconds, 10.0);
  // ODD: nodes 1, 3, 5, 7 in both steps' blocks, never an even node.
  const std::string dat = read_file((dir / "out" / "generate.dat").string());
  for (const char* row : {"\n         1 ", "\n         3 ", "\n         5 ", "\n         7 "})
    EXPECT_NE(dat.find(row), std::string::npos) << row << "\n" << dat;
  for (const char* row : {"\n         2 ", "\n         4 ", "\n         6 ", "\n         8 "})
    EXPECT_EQ(dat.find(row), std::string::npos) << row << "\n" << dat;
}

// `styk mesh` with divisions whose grid has more points than 32-bit ints index: refused at once
// (before, 1500000000 x 2 grew past 10 GB in 30 s on its way to the system's OOM killer).
TEST(ResourceLimits, MeshBeyondThirtyTwoBitCountsIsRefusedAtOnce) {
  const fs::path dir = test::test_scratch_dir("resource_limits");
  const CommandResult run = run_command(
      styk_executable() + " mesh cantilever --mesh 1500000000x2 -o big.inp", dir.string());
  EXPECT_EQ(run.exit_code, 5) << run.err;
  EXPECT_NE(run.err.find("the 1500000000 x 1 x 2 C3D8 block has 9000000006 grid points and "
                         "3000000000 elements; a Styk model holds at most 2147483647 of each"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "big.inp"));
}

// Within 32-bit counts but far beyond the memory of any machine this runs on (2.0e9 grid points,
// about 200 GB; CI machines have 24 GB): refused before allocating, naming both sizes.
TEST(ResourceLimits, MeshBeyondTheMachinesMemoryIsRefusedAtOnce) {
  const fs::path dir = test::test_scratch_dir("resource_limits");
  const CommandResult run = run_command(
      styk_executable() + " mesh cantilever --mesh 500000000x1 -o big.inp", dir.string());
  EXPECT_EQ(run.exit_code, 5) << run.err;
  EXPECT_NE(run.err.find("the 500000000 x 1 x 1 C3D8 block has 2000000004 grid points and "
                         "500000000 elements, which need about "),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("of memory: use fewer divisions"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "big.inp"));
}

// HDF5's limits on what one object header holds (64 KiB messages): the results file keeps the
// heading and set names as attributes and fixed-length strings, so a 100 000-character *HEADING
// and a 70 000-character set name must be written, sealed and read back whole (HDF5 moves large
// attributes to dense storage), not fail inside HDF5 half-way through writing.
TEST(ResourceLimits, HugeHeadingAndSetNameAreWrittenWhole) {
  const fs::path dir = test::test_scratch_dir("resource_limits");
  std::string deck = cube_with("*NSET, NSET=" + std::string(70000, 'S') + "\n1\n");
  const std::size_t heading = deck.find('\n') + 1;
  deck.replace(heading, deck.find('\n', heading) - heading, std::string(100000, 'H'));
  std::ofstream(dir / "long.inp") << deck;
  const CommandResult solve =
      run_command(styk_executable() + " solve -q long.inp -o out", dir.string());
  ASSERT_EQ(solve.exit_code, 0) << solve.err.substr(0, 2000);
  const CommandResult check =
      run_command(styk_executable() + " check out/long.styk.h5", dir.string());
  EXPECT_EQ(check.exit_code, 0) << check.out.substr(0, 2000) << check.err.substr(0, 2000);
  EXPECT_NE(check.out.find("whole"), std::string::npos) << check.out.substr(0, 2000);
}

}  // namespace
}  // namespace styk::testing
