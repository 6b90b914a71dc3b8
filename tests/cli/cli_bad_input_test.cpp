// Bad input never crashes and never passes silently (brief, "Standards"): every broken deck of
// tests/inputs/bad/manifest.tsv goes through `styk solve`; the exit code, the "file:line:" prefix
// and the problem named in the message are asserted, and nothing may be left in the output
// directory. Decks too large or too binary to commit are made here at run time.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace styk::testing {
namespace {

namespace fs = std::filesystem;

struct BadDeck {
  std::string deck;
  int exit_code = 1;
  int line = 0;
  std::string message;
};

std::vector<BadDeck> read_manifest() {
  const std::string dir = std::string(STYK_SOURCE_DIR) + "/tests/inputs/bad/";
  std::ifstream in(dir + "manifest.tsv");
  std::vector<BadDeck> decks;
  std::string row;
  while (std::getline(in, row)) {
    if (row.empty() || row[0] == '#') continue;
    std::istringstream fields(row);
    BadDeck d;
    std::string code, line;
    std::getline(fields, d.deck, '\t');
    std::getline(fields, code, '\t');
    std::getline(fields, line, '\t');
    std::getline(fields, d.message);
    d.deck = dir + d.deck;
    d.exit_code = std::stoi(code);
    d.line = std::stoi(line);
    decks.push_back(d);
  }
  return decks;
}

bool directory_is_empty(const std::string& dir) { return !fs::exists(dir) || fs::is_empty(dir); }

void expect_rejected(const BadDeck& d, const std::string& scratch) {
  const std::string out = scratch + "/out";
  const CommandResult r =
      run_command(styk_executable() + " solve -q '" + d.deck + "' -o '" + out + "'", scratch);
  SCOPED_TRACE(d.deck + "\nstderr: " + r.err);
  EXPECT_EQ(r.exit_code, d.exit_code);
  if (d.line > 0) {
    EXPECT_NE(r.err.find(":" + std::to_string(d.line) + ": "), std::string::npos);
  }
  EXPECT_NE(r.err.find(".inp"), std::string::npos) << "the message must name the file";
  EXPECT_NE(r.err.find(d.message), std::string::npos);
  EXPECT_EQ(r.err.find("internal error"), std::string::npos);
  EXPECT_TRUE(directory_is_empty(out)) << "a rejected deck must leave no output behind";
}

TEST(CliBadInput, ManifestHasAtLeastTwentyDecks) { EXPECT_GE(read_manifest().size(), 20u); }

TEST(CliBadInput, EveryManifestDeckIsRejectedWithFileLineAndReason) {
  const std::string scratch = scratch_dir("bad_input_manifest");
  for (const BadDeck& d : read_manifest()) expect_rejected(d, scratch);
}

TEST(CliBadInput, HundredMegabyteLine) {
  const std::string scratch = scratch_dir("bad_input_huge_line");
  const std::string deck = scratch + "/huge_line.inp";
  {
    std::ofstream out(deck);
    out << "*HEADING\nhuge line follows\n*NODE\n1, ";
    const std::string chunk(1 << 20, '1');
    for (int i = 0; i < 100; ++i) out << chunk;
    out << "\n";
  }
  expect_rejected({deck, 1, 4, "line"}, scratch);
}

TEST(CliBadInput, BinaryGarbage) {
  const std::string scratch = scratch_dir("bad_input_binary");
  const std::string deck = scratch + "/garbage.inp";
  {
    std::ofstream out(deck, std::ios::binary);
    unsigned state = 12345u;
    for (int i = 0; i < 4096; ++i) {
      state = state * 1103515245u + 12345u;
      out.put(static_cast<char>(state >> 16));
    }
  }
  expect_rejected({deck, 1, 0, "text"}, scratch);
}

TEST(CliBadInput, MissingDeck) {
  const std::string scratch = scratch_dir("bad_input_missing");
  expect_rejected({scratch + "/no_such_deck.inp", 1, 0, "cannot"}, scratch);
}

TEST(CliBadInput, UnknownCommandLineOptionIsBadInput) {
  const std::string scratch = scratch_dir("bad_input_option");
  const CommandResult r = run_command(styk_executable() + " solve --no-such-option x.inp", scratch);
  EXPECT_EQ(r.exit_code, 1);
}

}  // namespace
}  // namespace styk::testing
