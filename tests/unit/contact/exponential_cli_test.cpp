// The EXPONENTIAL pressure-overclosure law (*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL;
// docs/contact.md, "Penalty laws") through `styk solve`: hand values of two stacked blocks (the
// law's clearance under a known pressure, nothing beyond c0, the refusal below the least force),
// the law named in the log and the .dat, and a cross-check against CalculiX 2.20 on an identical
// deck (needs `ccx` on PATH).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "penalty_dat.hpp"

namespace styk::testing {
namespace {

// tests/inputs/contact/penalty_exponential_blocks.inp: c0 = 1e-3, p0 = 10, E = 1000, unit blocks.
const double kBeta = std::log(100.0) / 1e-3;
const std::string kBlocks = "penalty_exponential_blocks";
const std::string kLoad = "*CLOAD\nTOP, 3, -0.25\n";

// The blocks deck with its load replaced, solved in a scratch directory of its own.
struct Variant {
  CommandResult run;
  std::string dir;
  std::string dat;
};
Variant solve_with_load(const std::string& load, const std::string& scratch) {
  std::string deck = read_file(kDecks + kBlocks + ".inp");
  EXPECT_NE(deck.find(kLoad), std::string::npos);
  deck.replace(deck.find(kLoad), kLoad.size(), load);
  Variant v;
  v.dir = scratch_dir(scratch);
  { std::ofstream(v.dir + "/blocks.inp") << deck; }
  v.run = run_command(styk_executable() + " solve blocks.inp -o out", v.dir);
  std::ifstream dat(v.dir + "/out/blocks.dat");
  if (dat.good()) v.dat = read_file(v.dir + "/out/blocks.dat");
  return v;
}

// Hand value (the deck's header): the unit pressure is p0 / 10, which the law carries at the
// clearance g = ln(10) / beta = c0 / 2 = 5e-4 (CDIS +5e-4, to 1e-10, the .dat's last digit); each
// block shortens by p L / E = 1e-3, so the top moves by -1.5e-3.
TEST(ExponentialCli, BlocksRestAtTheLawsClearance) {
  const Solved s = solve(kBlocks, kBlocks);
  ASSERT_EQ(s.run.exit_code, 0) << s.run.err;
  const auto pressure = dat_block(s.dat, "contact stress");
  const auto gap = dat_block(s.dat, "contact displacement");
  const auto u = dat_block(s.dat, "displacements");
  ASSERT_EQ(pressure.size(), 4u) << s.dat;
  ASSERT_EQ(gap.size(), 4u);
  ASSERT_EQ(u.size(), 4u);
  for (const auto& [id, v] : pressure) EXPECT_NEAR(v[0], 1.0, 1e-6) << id;
  for (const auto& [id, v] : gap) EXPECT_NEAR(v[0], std::log(10.0) / kBeta, 1e-10) << id;
  for (const auto& [id, v] : u) EXPECT_NEAR(v[2], -1.5e-3, 1e-9) << id;
  EXPECT_NE(s.dat.find("       law penalty EXPONENTIAL c0= 1.000000E-03 p0= 1.000000E+01"),
            std::string::npos)
      << s.dat;
  // The load fixes the pressure; the second iteration linearises the law at it (docs/contact.md).
  EXPECT_NE(s.run.err.find("converged in 2 iterations"), std::string::npos) << s.run.err;
  EXPECT_NE(
      s.run.err.find(
          "contact pair UPPER_BOTTOM/LOWER_TOP: normal law penalty EXPONENTIAL c0=0.001 p0=10"),
      std::string::npos)
      << s.run.err;
}

// Pressed with 20 = 2 p0 the blocks overlap: g = -ln(2) / beta = -1.50515e-4, the top at
// -2 * 20 / E + g.
TEST(ExponentialCli, OverclosedBlocksFollowTheLaw) {
  const Variant v = solve_with_load("*CLOAD\nTOP, 3, -5.\n", "exponential_overclosed");
  ASSERT_EQ(v.run.exit_code, 0) << v.run.err;
  for (const auto& [id, p] : dat_block(v.dat, "contact stress")) EXPECT_NEAR(p[0], 20.0, 1e-5);
  const double g = -std::log(2.0) / kBeta;
  const auto gap = dat_block(v.dat, "contact displacement");
  ASSERT_EQ(gap.size(), 4u) << v.dat;
  for (const auto& [id, d] : gap) EXPECT_NEAR(d[0], g, 1e-10) << id;
  for (const auto& [id, d] : dat_block(v.dat, "displacements"))
    EXPECT_NEAR(d[2], -0.04 + g, 1e-8) << id;
}

// The top lifted by 2e-3 = 2 c0 (prescribed): beyond c0 CalculiX generates no spring, so the
// blocks carry nothing, stay unstrained and the clearance is the lift.
TEST(ExponentialCli, BlocksPulledBeyondC0CarryNothing) {
  const Variant v = solve_with_load("*BOUNDARY\nTOP, 3, 3, 2.e-3\n", "exponential_pulled");
  ASSERT_EQ(v.run.exit_code, 0) << v.run.err;
  const auto pressure = dat_block(v.dat, "contact stress");
  const auto gap = dat_block(v.dat, "contact displacement");
  ASSERT_EQ(gap.size(), 4u) << v.dat;
  for (const auto& [id, p] : pressure) EXPECT_EQ(p[0], 0.0) << id;
  for (const auto& [id, d] : gap) EXPECT_NEAR(d[0], 2e-3, 1e-12) << id;
}

// A total load of 0.05, pressure 0.05 < p0 / 100 = 0.1 (the law's least pressure, at c0): the law
// has no equilibrium (CalculiX 2.20 stops with "too many cutbacks"). `styk solve` says so, naming
// the law and the nodes, exits non-zero and writes no results.
TEST(ExponentialCli, LoadBelowTheLeastForceIsRefused) {
  const Variant v = solve_with_load("*CLOAD\nTOP, 3, -0.0125\n", "exponential_too_light");
  EXPECT_EQ(v.run.exit_code, 2);  // not converged
  EXPECT_NE(v.run.err.find("the EXPONENTIAL pressure-overclosure law has no equilibrium"),
            std::string::npos)
      << v.run.err;
  EXPECT_NE(v.run.err.find("nodes below the least force: 11, 12, 13, 14"), std::string::npos)
      << v.run.err;
  EXPECT_TRUE(v.dat.empty());
  EXPECT_FALSE(std::ifstream(v.dir + "/out/blocks.styk.h5").good());
}

// CalculiX 2.20's .dat of `deck` (run in its own scratch directory).
std::string ccx_dat(const std::string& deck, const std::string& scratch) {
  const std::string dir = scratch_dir(scratch);
  { std::ofstream(dir + "/pair.inp") << deck; }
  EXPECT_EQ(run_command("ccx -i pair > ccx.log 2>&1", dir).exit_code, 0)
      << "ccx failed, see " << dir << "/ccx.log";
  return read_file(dir + "/pair.dat");
}

// CalculiX 2.20 on tests/inputs/contact/penalty_exponential_eccentric.inp: the upper block rests
// on three rows of nonlinear springs, overclosed at x = 0 and open at x = 1 and 2. ccx stops its
// Newton iteration at a force residual of 5e-3 of the mean force by default: as the deck stands,
// within 2e-4 of the largest value of each block (measured 3.8e-5 pressures, 1.8e-4 clearances and
// displacements). With *CONTROLS, PARAMETERS=FIELD 1e-9 added to its copy of the deck (Styk's
// iteration always ends at 1e-9) the blocks agree to the printed digits: within 1e-6 (measured 0
// pressures, 0 clearances, 4.7e-7 displacements). E = 1e8 (strains ~4e-8) keeps ccx's
// deformed-geometry springs out of the comparison. Styk converges in 4 iterations.
TEST(ExponentialCli, ExponentialPenaltyAgreesWithCalculix) {
  ASSERT_EQ(std::system("command -v ccx > /dev/null 2>&1"), 0)
      << "ccx (CalculiX) is not on PATH: run scripts/install-deps.sh --test";
  const Solved s = solve("penalty_exponential_eccentric", "penalty_exponential_eccentric");
  ASSERT_EQ(s.run.exit_code, 0) << s.run.err;
  EXPECT_NE(s.run.err.find("converged in 4 iterations"), std::string::npos) << s.run.err;
  std::string deck = read_file(kDecks + "penalty_exponential_eccentric.inp");
  expect_same_contact_blocks(ccx_dat(deck, "exponential_ccx_default"), s.dat, 2e-4);
  const std::string step = "*STATIC\n";
  ASSERT_NE(deck.find(step), std::string::npos);
  deck.insert(deck.find(step), "*CONTROLS, PARAMETERS=FIELD\n1.e-9, 1.e-9\n");
  expect_same_contact_blocks(ccx_dat(deck, "exponential_ccx_tight"), s.dat, 1e-6);
}

// A second step that reverses the eccentric deck's tilt (loads 1 -> 0.2 at x = 0, 0.3 -> 1.5 at
// x = 2): the nodes at x = 0 fall from 3.56 to 0.43, and the Newton step from above their root
// sends two of them open once; they close again at a new linearisation point, which is progress,
// not a cycle (active_set.cpp, revisits_without_progress): 8 iterations (29 when it was damped as
// a cycle). CalculiX (tight *CONTROLS) agrees within 1e-6 of each block's largest value (measured
// 5.3e-7 pressures, 3.0e-7 clearances and displacements).
TEST(ExponentialCli, SecondStepReversingTheTiltAgreesWithCalculix) {
  ASSERT_EQ(std::system("command -v ccx > /dev/null 2>&1"), 0)
      << "ccx (CalculiX) is not on PATH: run scripts/install-deps.sh --test";
  std::string deck = read_file(kDecks + "penalty_exponential_eccentric.inp");
  std::string second = deck.substr(deck.find("*STEP"));
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"21, 3, -1.", "21, 3, -0.2"},
                                 {"24, 3, -1.", "24, 3, -0.2"},
                                 {"23, 3, -0.3", "23, 3, -1.5"},
                                 {"26, 3, -0.3", "26, 3, -1.5"}}) {
    ASSERT_NE(second.find(from), std::string::npos) << from;
    second.replace(second.find(from), from.size(), to);
  }
  deck += second;
  const std::string dir = scratch_dir("exponential_two_steps");
  { std::ofstream(dir + "/two.inp") << deck; }
  const CommandResult ours = run_command(styk_executable() + " solve two.inp -o out", dir);
  ASSERT_EQ(ours.exit_code, 0) << ours.err;
  EXPECT_NE(ours.err.find("contact step 2 increment 1 (t = 1): converged in 8 iterations"),
            std::string::npos)
      << ours.err;
  const std::string step = "*STATIC\n", controls = "*CONTROLS, PARAMETERS=FIELD\n1.e-9, 1.e-9\n";
  for (std::size_t at = deck.find(step); at != std::string::npos;
       at = deck.find(step, at + controls.size() + step.size()))
    deck.insert(at, controls);
  expect_same_contact_blocks(ccx_dat(deck, "exponential_two_steps_ccx"),
                             read_file(dir + "/out/two.dat"), 1e-6);
}

}  // namespace
}  // namespace styk::testing
