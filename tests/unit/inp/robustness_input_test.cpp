// Reader robustness that real CalculiX decks need (issue 15 item 8): set names that start with a
// digit, *NODE lines holding only the id, GENERATE ranges over ids that are not defined, and every
// unknown keyword refused by name with the list of what Styk reads.
#include <gtest/gtest.h>

#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"

namespace styk {
namespace {

using test::fake_registry;
using test::write_deck;

// Two C3D8 stacked along z (nodes 1..12), one spare node 20 and material/section; no step.
const char* const kTwoBricks = R"(*NODE
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
9, 0, 0, 2
10, 1, 0, 2
11, 1, 1, 2
12, 0, 1, 2
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
5, 5, 6, 7, 8, 9, 10, 11, 12
*MATERIAL, NAME=M
*ELASTIC
210000, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=M
)";

const char* const kStep = "*STEP\n*STATIC\n*END STEP\n";

std::vector<Id> nset_ids(const Model& m, const std::string& name) {
  std::vector<Id> ids;
  for (int n : m.find_nset(name)->nodes) ids.push_back(m.node_ids[n]);
  return ids;
}

InputError read_error(const std::string& name, const std::string& text) {
  const ElementRegistry registry = fake_registry();
  try {
    read_inp(write_deck(name, text), registry);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << name << ": no InputError";
  return InputError({}, "");
}

// CalculiX accepts set names such as "1E" (a deck of the issue's survey used one); a data field
// that does not read as a number names a set.
TEST(ReaderRobustness, SetNamesMayStartWithADigit) {
  const std::string deck = std::string(kTwoBricks) +
                           "*NSET, NSET=1TOP\n9, 10, 11, 12\n*ELSET, ELSET=1E\n5\n"
                           "*NSET, NSET=2ALL\n1TOP, 1\n*BOUNDARY\n1TOP, 1, 3\n" +
                           kStep;
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("robust_digit_sets.inp", deck), registry);
  EXPECT_EQ(nset_ids(m, "1TOP"), (std::vector<Id>{9, 10, 11, 12}));
  EXPECT_EQ(nset_ids(m, "2ALL"), (std::vector<Id>{1, 9, 10, 11, 12}));
  ASSERT_NE(m.find_elset("1E"), nullptr);
  EXPECT_EQ(m.find_elset("1E")->elements, (std::vector<int>{1}));
  EXPECT_EQ(m.boundaries.size(), 12u);
}

// A name that reads as a number could never be referred to (such a field is an id).
TEST(ReaderRobustness, SetNameThatReadsAsANumberIsRefused) {
  const InputError e =
      read_error("robust_numeric_set.inp", std::string(kTwoBricks) + "*NSET, NSET=12\n1\n" + kStep);
  EXPECT_EQ(e.where().line, 21);
  EXPECT_NE(std::string(e.what()).find("does not read as a number"), std::string::npos) << e.what();
}

// CalculiX: "*NODE" data "13" alone puts node 13 at the origin.
TEST(ReaderRobustness, NodeLineWithOnlyTheId) {
  const std::string deck = std::string(kTwoBricks) + "*NODE\n13\n14, 2.5\n" + kStep;
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("robust_node_id_only.inp", deck), registry);
  const int n13 = m.node_index(13), n14 = m.node_index(14);
  ASSERT_GE(n13, 0);
  EXPECT_EQ(m.coords[n13], (Vec3{0.0, 0.0, 0.0}));
  EXPECT_EQ(m.coords[n14], (Vec3{2.5, 0.0, 0.0}));
}

// GENERATE skips ids that are not defined, as CalculiX decks expect (ranges over numbered blocks
// with gaps); a range that hits no defined id at all is an error at its line.
TEST(ReaderRobustness, GenerateSkipsUndefinedIds) {
  const std::string deck = std::string(kTwoBricks) +
                           "*NSET, NSET=ODD, GENERATE\n1, 30, 2\n"
                           "*ELSET, ELSET=SOME, GENERATE\n1, 10\n" +
                           kStep;
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("robust_generate_gaps.inp", deck), registry);
  EXPECT_EQ(nset_ids(m, "ODD"), (std::vector<Id>{1, 3, 5, 7, 9, 11}));
  EXPECT_EQ(m.find_elset("SOME")->elements, (std::vector<int>{0, 1}));

  const InputError none =
      read_error("robust_generate_empty.inp",
                 std::string(kTwoBricks) + "*NSET, NSET=FAR, GENERATE\n100, 200, 10\n" + kStep);
  EXPECT_EQ(none.where().line, 22);
  EXPECT_NE(std::string(none.what()).find("no node has an id in 100..200 in steps of 10"),
            std::string::npos)
      << none.what();
}

// An unknown keyword is refused at its line, by name, with the list of the keywords Styk reads.
TEST(ReaderRobustness, UnknownKeywordIsRefusedWithTheSupportedList) {
  const InputError e = read_error("robust_unknown_keyword.inp",
                                  std::string(kTwoBricks) + "*MOHR COULOMB\n30., 5.\n" + kStep);
  const std::string what = e.what();
  EXPECT_EQ(e.where().line, 21);
  EXPECT_NE(what.find("unknown keyword *MOHR COULOMB"), std::string::npos) << what;
  EXPECT_NE(what.find("*NODE, *ELEMENT"), std::string::npos) << what;
  EXPECT_NE(what.find("docs/input.md"), std::string::npos) << what;
}

}  // namespace
}  // namespace styk
