// Penalty contact laws (*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR / TIED; docs/contact.md,
// "Penalty laws"; EXPONENTIAL: exponential_cli_test.cpp) through `styk solve`: hand values of two
// stacked blocks, the law named in the log and the .dat, and a cross-check against CalculiX on an
// identical deck (needs `ccx` on PATH).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "penalty_dat.hpp"

namespace styk::testing {
namespace {

// SPEC-free hand value (tests/inputs/contact/penalty_linear_blocks.inp): uniform uniaxial stress
// -1 in both unit blocks (E = 1000), penalty K = 1e4: pressure 1, overclosure p / K = 1e-4, top
// displacement -(2 p L / E + p / K) = -2.1e-3, i.e. the series stiffness 1 / (2 / E + 1 / K).
TEST(PenaltyCli, LinearPenaltyBlocksGiveTheSeriesStiffness) {
  const Solved s = solve("penalty_linear_blocks", "penalty_linear_blocks");
  ASSERT_EQ(s.run.exit_code, 0) << s.run.err;
  const auto pressure = dat_block(s.dat, "contact stress");
  const auto gap = dat_block(s.dat, "contact displacement");
  const auto u = dat_block(s.dat, "displacements");
  ASSERT_EQ(pressure.size(), 4u) << s.dat;
  ASSERT_EQ(gap.size(), 4u);
  ASSERT_EQ(u.size(), 4u);
  for (const auto& [id, v] : pressure) EXPECT_NEAR(v[0], 1.0, 1e-6) << id;
  for (const auto& [id, v] : gap) EXPECT_NEAR(v[0], -1e-4, 1e-10) << id;  // penetration < 0
  for (const auto& [id, v] : u) EXPECT_NEAR(v[2], -2.1e-3, 1e-9) << id;
  EXPECT_NE(s.dat.find("       law penalty LINEAR K= 1.000000E+04"), std::string::npos) << s.dat;
  EXPECT_NE(
      s.run.err.find("contact pair UPPER_BOTTOM/LOWER_TOP: normal law penalty LINEAR K=10000"),
      std::string::npos)
      << s.run.err;
}

// tests/inputs/contact/penalty_tied_blocks.inp: the TIED springs carry a unit tension (pressure
// -1), open by p / K = 1e-4 and hold the unsupported upper block: top at +2.1e-3, no shear.
TEST(PenaltyCli, TiedPenaltyCarriesTension) {
  const Solved s = solve("penalty_tied_blocks", "penalty_tied_blocks");
  ASSERT_EQ(s.run.exit_code, 0) << s.run.err;
  const auto pressure = dat_block(s.dat, "contact stress");
  const auto gap = dat_block(s.dat, "contact displacement");
  const auto u = dat_block(s.dat, "displacements");
  ASSERT_EQ(pressure.size(), 4u) << s.dat;
  for (const auto& [id, v] : pressure) {
    EXPECT_NEAR(v[0], -1.0, 1e-6) << id;
    EXPECT_NEAR(v[1], 0.0, 1e-9) << id;
    EXPECT_NEAR(v[2], 0.0, 1e-9) << id;
  }
  for (const auto& [id, v] : gap) EXPECT_NEAR(v[0], 1e-4, 1e-10) << id;
  ASSERT_EQ(u.size(), 4u);
  for (const auto& [id, v] : u) EXPECT_NEAR(v[2], 2.1e-3, 1e-9) << id;
  EXPECT_NE(s.dat.find("       law penalty TIED K= 1.000000E+04"), std::string::npos) << s.dat;
}

// TIED with *FRICTION makes no sense: `styk solve` stops at the card (file:line, exit code 1) and
// writes nothing.
TEST(PenaltyCli, LawsNotSolvedAreRefusedByName) {
  const std::string linear = read_file(kDecks + "penalty_linear_blocks.inp");
  const std::string card = "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1.e4, 1.e-8\n";
  ASSERT_NE(linear.find(card), std::string::npos);
  const std::pair<std::string, std::string> cases[] = {
      {"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n1.e4\n*FRICTION\n0.2\n",
       "*FRICTION does not apply to it"}};
  int k = 0;
  for (const auto& [replacement, message] : cases) {
    const std::string dir = scratch_dir("penalty_refused_" + std::to_string(k++));
    std::string deck = linear;
    deck.replace(deck.find(card), card.size(), replacement);
    { std::ofstream(dir + "/refused.inp") << deck; }
    const CommandResult r = run_command(styk_executable() + " solve refused.inp -o out", dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    const std::string keyword = replacement.find("*FRICTION") != std::string::npos
                                    ? std::string("*FRICTION\n")
                                    : replacement.substr(0, replacement.find('\n') + 1);
    int line = 1;
    for (std::size_t i = 0; i < deck.find(keyword); ++i) line += deck[i] == '\n';
    EXPECT_NE(r.err.find("refused.inp:" + std::to_string(line) + ":"), std::string::npos) << r.err;
    EXPECT_FALSE(std::ifstream(dir + "/out/refused.dat").good());
    EXPECT_FALSE(std::ifstream(dir + "/out/refused.styk.h5").good());
  }
}

// CalculiX 2.20 solves tests/inputs/contact/penalty_linear_eccentric.inp unchanged (node-to-face
// penalty contact, LINEAR). Its springs live on the deformed geometry (area and normal), Styk's on
// the undeformed one (small displacements), a difference of the order of the strains: with E = 1e8
// (strains ~4e-8) the blocks agree to the printed digits, within 1e-6 of the largest value of
// each block (measured 2.8e-7 pressures, 5.7e-8 overclosures, 1.0e-7 displacements; with E = 1e5
// the difference grows to 4.1e-5, 4.2e-5, 9.5e-5: docs/contact.md, "Penalty laws").
// sigma_inf = 1e-8 makes CalculiX's tension branch negligible.
TEST(PenaltyCli, LinearPenaltyAgreesWithCalculix) {
  ASSERT_EQ(std::system("command -v ccx > /dev/null 2>&1"), 0)
      << "ccx (CalculiX) is not on PATH: run scripts/install-deps.sh --test";
  const std::string dir = scratch_dir("penalty_ccx");
  { std::ofstream(dir + "/pair.inp") << read_file(kDecks + "penalty_linear_eccentric.inp"); }
  ASSERT_EQ(run_command("ccx -i pair > ccx.log 2>&1", dir).exit_code, 0)
      << "ccx failed, see " << dir << "/ccx.log";
  const std::string ccx = read_file(dir + "/pair.dat");
  const Solved s = solve("penalty_linear_eccentric", "penalty_linear_eccentric");
  ASSERT_EQ(s.run.exit_code, 0) << s.run.err;
  expect_same_contact_blocks(ccx, s.dat, 1e-6);
}

}  // namespace
}  // namespace styk::testing
