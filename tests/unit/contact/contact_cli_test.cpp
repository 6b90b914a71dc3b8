// Contact decks through the `styk` program: a two-step frictionless stack (results file, .dat
// report with *CONTACT PRINT, increments) and a model the contact cannot hold, which must end with
// exit code 2 (did not converge) and a report naming the reason and the nodes (docs/contact.md).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace styk::testing {
namespace {

const std::string kDecks = std::string(STYK_SOURCE_DIR) + "/tests/inputs/contact/";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ContactCli, TwoStepStackPrintsContactOutputPerIncrement) {
  const std::string dir = scratch_dir("contact_cli_stack");
  const CommandResult r =
      run_command(styk_executable() + " solve '" + kDecks + "stacked_c3d8.inp' -o out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/stacked_c3d8.styk.h5"));
  const std::string dat = read_file(dir + "/out/stacked_c3d8.dat");
  // Step 1 in one increment, step 2 in two fixed-size halves (automatic increments keep 0.5).
  EXPECT_EQ(count(dat, "contact stress (slave node,press,tang1,tang2)"), 3) << dat;
  EXPECT_EQ(count(dat, "contact status"), 3);
  EXPECT_EQ(count(dat, "relative residual"), 3);
  // C3D8 nodal area 1/4 of the unit face: pressure 1 after step 1 (4 x 0.25), 2 at its end.
  EXPECT_NE(dat.find("        11  1.000000E+00  0.000000E+00  0.000000E+00"), std::string::npos)
      << dat;
  EXPECT_NE(dat.find("        11  2.000000E+00  0.000000E+00  0.000000E+00"), std::string::npos);
  EXPECT_NE(dat.find("        11   2\n"), std::string::npos);  // closed, frictionless: slip
  // The iteration is logged on stderr.
  EXPECT_NE(r.err.find("contact step 2 increment 2"), std::string::npos) << r.err;
  // The upper block is held in x, y and about z by its supports; z and the two tilts are left.
  EXPECT_NE(r.err.find("3 rigid motions held only by contact"), std::string::npos) << r.err;
}

TEST(ContactCli, BodyContactCannotHoldEndsWithExitCode2) {
  const std::string dir = scratch_dir("contact_cli_floating");
  const CommandResult r = run_command(
      styk_executable() + " solve '" + kDecks + "floating_frictionless.inp' -o out", dir);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("did not converge"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("singular contact system"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/floating_frictionless.styk.h5"));
}

}  // namespace
}  // namespace styk::testing
