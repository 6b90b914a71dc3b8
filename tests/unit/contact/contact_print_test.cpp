// *CONTACT PRINT in the .dat report (docs/results.md "Contact output", docs/input.md): the block
// layout checked line by line on a deck whose values are known, and the CSTR/CDIS blocks against
// CalculiX's node-to-surface output of the same deck (needs `ccx` on PATH, like tests/unit/io).
//
// Deck tests/inputs/contact/contact_print_single_pair.inp: a C3D8 on a C3D8, face 2 x 1,
// frictionless, pressed by 4 x 0.75 at the top in two fixed increments (times 0.5 and 1.0). Every
// slave node has the area 2 / 4 = 0.5 and carries 0.75 / 2 then 0.75: pressure 0.75 and 1.5
// (force / area, exact in the 7 printed digits), shear 0, gap and slip 0 to round-off, status 2
// (closed frictionless is "slip"). Pair force (0, 0, 3 t); its moment about the origin, from the
// nodes (0,0,1), (2,0,1), (2,1,1), (0,1,1) with 0.75 t each: (1.5 t, -3 t, 0).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "support/ccx_runner.hpp"

namespace styk::testing {
namespace {

const std::string kDeck =
    std::string(STYK_SOURCE_DIR) + "/tests/inputs/contact/contact_print_single_pair.inp";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// A row "label (10 characters) + n values in Fortran 1X,E13.6": returns the values, or fails the
// test (naming the line) when the layout differs.
std::vector<double> row_values(const std::string& line, const std::string& label, int n) {
  static const std::regex e13_6(" ([ -][0-9]\\.[0-9]{6}E[+-][0-9]{2})");
  std::vector<double> values;
  EXPECT_EQ(line.size(), 10u + 14u * static_cast<std::size_t>(n)) << '"' << line << '"';
  if (line.size() != 10u + 14u * static_cast<std::size_t>(n)) return values;
  EXPECT_EQ(line.substr(0, 10), label);
  for (int k = 0; k < n; ++k) {
    const std::string field = line.substr(10 + 14 * k, 14);
    std::smatch m;
    EXPECT_TRUE(std::regex_match(field, m, e13_6)) << '"' << field << "\" in \"" << line << '"';
    values.push_back(std::strtod(field.c_str(), nullptr));
  }
  return values;
}

std::string right10(const std::string& s) { return std::string(10 - s.size(), ' ') + s; }

std::string time_e14_7(double t) { return t == 0.5 ? " 0.5000000E+00" : " 0.1000000E+01"; }

// Checks one increment's contact blocks starting at lines[at]; returns the line after them.
std::size_t expect_increment(const std::vector<std::string>& lines, std::size_t at, double t) {
  auto next = [&]() -> std::string {
    EXPECT_LT(at, lines.size()) << "report ends early";
    return at < lines.size() ? lines[at++] : std::string();
  };
  auto header = [&](const std::string& what) {
    EXPECT_EQ(next(), "");
    EXPECT_EQ(next(), " " + what + " and time" + time_e14_7(t));
    EXPECT_EQ(next(), "");
  };
  const char* slaves[] = {"11", "12", "13", "14"};  // sorted by node id

  header("contact stress (slave node,press,tang1,tang2) for all contact elements");
  for (const char* id : slaves) {
    const std::vector<double> v = row_values(next(), right10(id), 3);
    if (v.size() != 3) continue;
    EXPECT_EQ(v[0], 1.5 * t);  // printed 7.500000E-01 / 1.500000E+00
    EXPECT_LE(std::abs(v[1]) + std::abs(v[2]), 1e-12);
  }
  header("contact displacement (slave node,gap,slip1,slip2) for all contact elements");
  for (const char* id : slaves)
    for (const double v : row_values(next(), right10(id), 3)) EXPECT_LE(std::abs(v), 1e-12);
  header("contact status (slave node,status: 0 open 1 stick 2 slip) for all contact elements");
  for (const char* id : slaves) EXPECT_EQ(next(), right10(id) + "   2");  // I10, 1X, I3

  header(
      "total contact force and moment about the origin on slave UPPER_BOTTOM of pair "
      "UPPER_BOTTOM/LOWER_TOP");
  const std::vector<double> force = row_values(next(), "     force", 3);
  const std::vector<double> moment = row_values(next(), "    moment", 3);
  EXPECT_EQ(next(), "       law exact (hard)");
  const std::vector<double> force_expected = {0.0, 0.0, 3.0 * t};
  const std::vector<double> moment_expected = {1.5 * t, -3.0 * t, 0.0};
  for (std::size_t d = 0; d < force.size() && d < 3; ++d) {
    EXPECT_NEAR(force[d], force_expected[d], 1e-12);
    EXPECT_NEAR(moment[d], moment_expected[d], 1e-12);
  }

  // Equilibrium: applied (0, 0, -3t) + reactions = 0; contact on slave (0, 0, 3t) + master = 0.
  header("equilibrium (applied loads + reactions = 0; contact slave + master = 0)");
  const std::pair<const char*, double> balance[] = {
      {"   applied", -3.0}, {" reactions", 3.0}, {"   c.slave", 3.0}, {"  c.master", -3.0}};
  for (const auto& [label, z] : balance) {
    const std::vector<double> v = row_values(next(), label, 3);
    if (v.size() != 3) continue;
    EXPECT_NEAR(v[0], 0.0, 1e-12) << label;
    EXPECT_NEAR(v[1], 0.0, 1e-12) << label;
    EXPECT_NEAR(v[2], z * t, 1e-12) << label;
  }
  const std::string residual = next();
  EXPECT_EQ(residual.substr(0, 19), "  relative residual");
  if (residual.size() > 19) {
    const std::vector<double> r = row_values(right10("") + residual.substr(19), right10(""), 1);
    EXPECT_TRUE(!r.empty() && r[0] < 1e-8) << residual;
  }
  return at;
}

TEST(ContactPrint, ReportFollowsTheDocumentedLayout) {
  const std::string dir = scratch_dir("contact_print_layout");
  const CommandResult run = run_command(styk_executable() + " solve '" + kDeck + "' -o out", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> lines =
      lines_of(read_file(dir + "/out/contact_print_single_pair.dat"));
  // Nothing but the contact blocks of the two increments (the deck prints nothing else).
  std::size_t at = expect_increment(lines, 0, 0.5);
  at = expect_increment(lines, at, 1.0);
  EXPECT_EQ(at, lines.size()) << "unexpected lines after the second increment";
}

// The block of `what` at time 1.0 from a .dat report: header and rows (up to the blank line).
std::vector<std::string> block(const std::vector<std::string>& lines, const std::string& what) {
  for (std::size_t i = 0; i + 2 < lines.size(); ++i)
    if (lines[i].rfind(" " + what + " ", 0) == 0 &&
        lines[i].find("time 0.1000000E+01") != std::string::npos) {
      std::vector<std::string> out = {lines[i]};
      for (std::size_t j = i + 2; j < lines.size() && !lines[j].empty(); ++j)
        out.push_back(lines[j]);
      return out;
    }
  return {};
}

// CalculiX 2.20 runs the same deck (penalty node-to-surface contact, CSTATUS dropped: ccx does not
// know it and only warns). Where the keywords overlap the layout is the same: the CSTR header is
// identical character for character, rows are node id I10 + 3 x E13.6 for the same slave nodes in
// the same order. CDIS differs in wording only (ccx: "relative contact displacement (slave
// node,normal,tang1,tang2)", Styk: "contact displacement (slave node,gap,slip1,slip2)"; both
// negative for penetration) — docs/results.md lists the differences. ccx's penalty pressure is
// 1.498651 against the exact 1.5: compared within 2e-3.
TEST(ContactPrint, StressBlockHasTheLayoutOfCalculix) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const std::string dir = scratch_dir("contact_print_ccx");
  std::string deck = read_file(kDeck);
  const std::string request = "CSTR, CDIS, CSTATUS\n";
  ASSERT_NE(deck.find(request), std::string::npos);
  deck.replace(deck.find(request), request.size(), "CSTR, CDIS\n");
  { std::ofstream(dir + "/pair.inp") << deck; }
  ASSERT_EQ(test::run_ccx(dir, "pair").exit_code, 0) << "ccx failed, see " << dir << "/pair.log";
  const std::vector<std::string> ccx = lines_of(read_file(dir + "/pair.dat"));
  const CommandResult run = run_command(styk_executable() + " solve '" + kDeck + "' -o out", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> ours =
      lines_of(read_file(dir + "/out/contact_print_single_pair.dat"));

  const std::vector<std::string> ccx_stress = block(ccx, "contact stress");
  const std::vector<std::string> our_stress = block(ours, "contact stress");
  ASSERT_EQ(ccx_stress.size(), 5u);
  ASSERT_EQ(our_stress.size(), ccx_stress.size());
  EXPECT_EQ(our_stress[0], ccx_stress[0]);
  for (std::size_t i = 1; i < ccx_stress.size(); ++i) {
    const std::string id = ccx_stress[i].substr(0, 10);
    const std::vector<double> a = row_values(ccx_stress[i], id, 3);
    const std::vector<double> b = row_values(our_stress[i], id, 3);
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(b.size(), 3u);
    EXPECT_NEAR(b[0], a[0], 2e-3 * a[0]) << id;
    EXPECT_NEAR(b[1], a[1], 1e-12);
    EXPECT_NEAR(b[2], a[2], 1e-12);
  }

  const std::vector<std::string> ccx_dis = block(ccx, "relative contact displacement");
  const std::vector<std::string> our_dis = block(ours, "contact displacement");
  ASSERT_EQ(ccx_dis.size(), 5u);
  ASSERT_EQ(our_dis.size(), ccx_dis.size());
  EXPECT_EQ(ccx_dis[0],
            " relative contact displacement (slave node,normal,tang1,tang2) for all contact "
            "elements and time 0.1000000E+01");
  EXPECT_EQ(our_dis[0],
            " contact displacement (slave node,gap,slip1,slip2) for all contact elements and "
            "time 0.1000000E+01");
  for (std::size_t i = 1; i < ccx_dis.size(); ++i) {
    const std::string id = ccx_dis[i].substr(0, 10);
    const std::vector<double> a = row_values(ccx_dis[i], id, 3);
    const std::vector<double> b = row_values(our_dis[i], id, 3);
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(b.size(), 3u);
    EXPECT_LT(a[0], 0.0);              // ccx: the penalty's penetration, negative
    EXPECT_LE(std::abs(b[0]), 1e-12);  // Styk: exact, round-off
  }
}

}  // namespace
}  // namespace styk::testing
