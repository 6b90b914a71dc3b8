// The deck set (tests/inputs/decks, issue 15 "Done when"): decks written the way a CalculiX or
// Abaqus user writes them, one per keyword or option of the manuals. Every deck must solve with
// `styk solve`; where manifest.tsv names ccx as the reference, ccx 2.20 solves the same deck and
// every compared .dat block must agree row by row: the same ids, integration points, local-system
// marks and orientation names, and every value within the manifest's relative tolerance (1e-6
// unless a row states a measured cause) of the largest absolute value of its block.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "styk/io/dat_reader.hpp"
#include "support/ccx_runner.hpp"

namespace styk::testing {
namespace {

struct DeckCase {
  std::string deck;
  std::string reference;  // "ccx" or "none"
  double tolerance = 1e-6;
  std::vector<std::string> compare;  // block-title prefixes, empty = all
  std::string note;
};

// gtest prints the parameter in failure messages and ctest test names: the deck's file name.
void PrintTo(const DeckCase& c, std::ostream* out) { *out << c.deck; }

std::string decks_dir() { return std::string(STYK_SOURCE_DIR) + "/tests/inputs/decks"; }

std::vector<DeckCase> load_manifest() {
  std::vector<DeckCase> cases;
  std::ifstream in(decks_dir() + "/manifest.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> columns;
    std::stringstream fields(line);
    std::string column;
    while (std::getline(fields, column, '\t')) columns.push_back(column);
    columns.resize(5);
    DeckCase c;
    c.deck = columns[0];
    c.reference = columns[1];
    c.tolerance = std::stod(columns[2]);
    if (columns[3] != "all") {
      std::stringstream list(columns[3]);
      std::string prefix;
      while (std::getline(list, prefix, ',')) c.compare.push_back(prefix);
    }
    c.note = columns[4];
    cases.push_back(c);
  }
  return cases;
}

std::vector<DatBlock> compared_blocks(const std::string& path, const DeckCase& c) {
  std::ifstream in(path);
  std::vector<DatBlock> out;
  for (DatBlock& block : parse_dat_blocks(in)) {
    const bool wanted = c.compare.empty() ||
                        std::any_of(c.compare.begin(), c.compare.end(),
                                    [&](const auto& p) { return block.what.rfind(p, 0) == 0; });
    if (wanted) out.push_back(std::move(block));
  }
  return out;
}

// The largest difference of block `ours` from `theirs` relative to the largest value of theirs.
double compare_block(const DatBlock& ours, const DatBlock& theirs, const std::string& where) {
  EXPECT_EQ(ours.what, theirs.what) << where;
  EXPECT_EQ(ours.set, theirs.set) << where;
  EXPECT_DOUBLE_EQ(ours.time, theirs.time) << where;
  EXPECT_EQ(ours.rows.size(), theirs.rows.size()) << where << " (" << theirs.what << ")";
  if (ours.rows.size() != theirs.rows.size()) return INFINITY;
  double largest = 0.0;
  for (const DatRow& row : theirs.rows)
    for (double v : row.values) largest = std::max(largest, std::abs(v));
  double worst = 0.0;
  for (std::size_t i = 0; i < theirs.rows.size(); ++i) {
    const DatRow& a = ours.rows[i];
    const DatRow& b = theirs.rows[i];
    EXPECT_EQ(a.id, b.id) << where << " row " << i;
    EXPECT_EQ(a.integration_point, b.integration_point) << where << " row " << i;
    EXPECT_EQ(a.local, b.local) << where << " row " << i;
    EXPECT_EQ(a.label, b.label) << where << " row " << i;
    EXPECT_EQ(a.values.size(), b.values.size()) << where << " row " << i;
    for (std::size_t k = 0; k < std::min(a.values.size(), b.values.size()); ++k)
      worst = std::max(worst, std::abs(a.values[k] - b.values[k]) / std::max(largest, 1e-300));
  }
  return worst;
}

class DeckSet : public ::testing::TestWithParam<DeckCase> {};

TEST_P(DeckSet, SolvesAndMatchesItsReference) {
  const DeckCase& c = GetParam();
  const std::string job = c.deck.substr(0, c.deck.size() - 4);
  const std::string dir = scratch_dir("deck_set_" + job);
  std::filesystem::copy_file(decks_dir() + "/" + c.deck, dir + "/" + c.deck);
  const CommandResult ours =
      run_command(styk_executable() + " solve -q " + c.deck + " -o styk", dir);
  ASSERT_EQ(ours.exit_code, 0) << ours.err;
  if (c.reference == "none") {
    std::printf("deck %-40s solved (reference: %s)\n", c.deck.c_str(), c.note.c_str());
    return;
  }
  ASSERT_EQ(c.reference, "ccx");
  const test::CcxRun peer = test::run_ccx(dir, job);
  ASSERT_EQ(peer.exit_code, 0) << peer.log;
  const std::vector<DatBlock> a = compared_blocks(dir + "/styk/" + job + ".dat", c);
  const std::vector<DatBlock> b = compared_blocks(dir + "/" + job + ".dat", c);
  ASSERT_FALSE(b.empty()) << "ccx printed no compared block";
  ASSERT_EQ(a.size(), b.size()) << "blocks printed: Styk " << a.size() << ", ccx " << b.size();
  double worst = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i)
    worst = std::max(
        worst, compare_block(a[i], b[i],
                             c.deck + " block " + std::to_string(i + 1) + " (" + b[i].what + ")"));
  std::printf("deck %-40s %2zu blocks  max difference / block max %.2e (tolerance %.0e)\n",
              c.deck.c_str(), b.size(), worst, c.tolerance);
  EXPECT_LE(worst, c.tolerance) << c.note;
}

std::string deck_name(const ::testing::TestParamInfo<DeckCase>& info) {
  return info.param.deck.substr(0, info.param.deck.size() - 4);
}

INSTANTIATE_TEST_SUITE_P(Decks, DeckSet, ::testing::ValuesIn(load_manifest()), deck_name);

}  // namespace
}  // namespace styk::testing
