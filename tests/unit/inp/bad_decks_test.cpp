// Broken decks: every deck of tests/inputs/bad/manifest.tsv that the reader must reject raises an
// InputError at the listed line with the listed text; the solver-level decks read fine. Plus the
// pathological inputs that are generated at run time (a 100 MB line, NUL bytes late in a file).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"

namespace styk {
namespace {

using test::fake_registry;
using test::input_path;
using test::write_deck;

struct ManifestRow {
  std::string deck;
  int exit_code = 0;
  int line = 0;
  std::string substring;
};

std::vector<ManifestRow> manifest() {
  std::ifstream in(input_path("bad/manifest.tsv"));
  std::vector<ManifestRow> rows;
  std::string text;
  while (std::getline(in, text)) {
    if (text.empty()) continue;
    std::istringstream fields(text);
    ManifestRow row;
    std::string code, line;
    std::getline(fields, row.deck, '\t');
    std::getline(fields, code, '\t');
    std::getline(fields, line, '\t');
    std::getline(fields, row.substring);
    row.exit_code = std::stoi(code);
    row.line = std::stoi(line);
    rows.push_back(row);
  }
  return rows;
}

void PrintTo(const ManifestRow& row, std::ostream* out) { *out << row.deck; }

bool solver_level(const ManifestRow& row) { return row.deck.rfind("solver_", 0) == 0; }

TEST(BadDecks, ManifestListsEveryDeckAndEnoughOfThem) {
  const std::vector<ManifestRow> rows = manifest();
  EXPECT_GE(rows.size(), 24u);
  std::set<std::string> listed;
  for (const ManifestRow& row : rows) {
    EXPECT_TRUE(listed.insert(row.deck).second) << row.deck << " listed twice";
    EXPECT_EQ(row.exit_code, 1) << row.deck;
    EXPECT_FALSE(row.substring.empty()) << row.deck;
  }
  for (const auto& entry : std::filesystem::directory_iterator(input_path("bad"))) {
    if (entry.path().extension() != ".inp") continue;
    EXPECT_EQ(listed.count(entry.path().filename().string()), 1u)
        << entry.path() << " is not in manifest.tsv";
  }
}

class BadDeck : public ::testing::TestWithParam<ManifestRow> {};

TEST_P(BadDeck, ReaderRejectsItAtTheListedLine) {
  const ManifestRow& row = GetParam();
  const ElementRegistry registry = fake_registry();
  const std::string path = input_path("bad/" + row.deck);
  if (solver_level(row)) {
    // Valid input that the solver rejects (its message is checked through `styk solve` in
    // tests/cli); the reader must accept it.
    EXPECT_NO_THROW(read_inp(path, registry));
    return;
  }
  try {
    read_inp(path, registry);
    FAIL() << row.deck << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, row.line) << e.what();
    EXPECT_NE(e.message().find(row.substring), std::string::npos)
        << "message: " << e.what() << "\nexpected to contain: " << row.substring;
    // The error names a file of this deck (the deck itself or one it includes).
    EXPECT_EQ(e.where().file.rfind(input_path("bad/"), 0), 0u) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(e.where().str() + ": ", 0), 0u) << e.what();
  }
}

std::string row_name(const ::testing::TestParamInfo<ManifestRow>& info) {
  std::string name = info.param.deck.substr(0, info.param.deck.size() - 4);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Manifest, BadDeck, ::testing::ValuesIn(manifest()), row_name);

long peak_rss_kib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// A 100 MB single line must be refused quickly and without holding it in memory.
TEST(PathologicalInput, HundredMegabyteLineIsRefusedFastInBoundedMemory) {
  const std::string path = (test::scratch_dir() / "huge_line.inp").string();
  {
    std::ofstream out(path, std::ios::binary);
    out << "*NODE\n1, ";
    const std::string chunk(1 << 20, '7');
    for (int i = 0; i < 100; ++i) out << chunk;
    out << ", 0., 0.\n";
  }
  const ElementRegistry registry = fake_registry();
  const long peak_before = peak_rss_kib();
  const auto start = std::chrono::steady_clock::now();
  try {
    read_inp(path, registry);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(e.message().find("line is longer than"), std::string::npos) << e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::filesystem::remove(path);
  // The reader stops at the 1 MiB line cap: a few ms. 2 s leaves room for a loaded CI machine.
  EXPECT_LT(seconds, 2.0);
  // Reading must not raise the process' peak memory by anything near the 100 MB the line would
  // take (the line cap is 1 MiB; 32 MiB leaves room for sanitizer builds).
  EXPECT_LT(peak_rss_kib() - peak_before, 32 * 1024);
}

TEST(PathologicalInput, NulByteDeepInAFileIsReportedAtItsLine) {
  std::string deck = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n";
  deck += std::string("3, 1., 1.") + '\0' + ", 0.\n";
  const ElementRegistry registry = fake_registry();
  try {
    read_inp(write_deck("nul.inp", deck), registry);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(e.message().find("not a text line (byte 0x00 at column 10)"), std::string::npos)
        << e.what();
  }
}

TEST(PathologicalInput, RandomBytesNeverEscapeAsAnythingButInputError) {
  // Deterministic pseudo-random decks (fixed LCG seed), printable and not: the reader must end
  // every one with an InputError, never another exception or a crash.
  std::uint32_t state = 12345;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return state >> 24;
  };
  const std::string alphabet = "*,=. \n0123456789EeNODELMTSPYCRAIUV-+\t*\n";
  const ElementRegistry registry = fake_registry();
  for (int deck = 0; deck < 200; ++deck) {
    std::string text;
    const int length = 1 + static_cast<int>(next() % 400);
    for (int i = 0; i < length; ++i) text += alphabet[next() % alphabet.size()];
    const std::string path = write_deck("fuzz.inp", text);
    try {
      read_inp(path, registry);
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "deck " << deck << " raised " << e.what() << "\n" << text;
    }
  }
}

}  // namespace
}  // namespace styk
