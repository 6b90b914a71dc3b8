// read_inp and write_inp on the joint keywords: *TIE, CYCLIC SYMMETRY with *CYCLIC SYMMETRY MODEL
// (CalculiX) and *PRESSURE PENETRATION (Styk extension after Abaqus) — what lands in the Model,
// what is written back, and what is refused (with the line that is wrong).
#include <gtest/gtest.h>

#include <sstream>

#include "deck_errors.hpp"
#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

namespace styk {
namespace {

using test::expect_error;
using test::fake_registry;
using test::line_of;
using test::write_deck;

// Two unit cubes stacked in z without shared nodes (A below, B above) and a contact pair between
// A's top (S2) and B's bottom (S1).
const char* const kBlocks = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
11, 0., 0., 1.
12, 1., 0., 1.
13, 1., 1., 1.
14, 0., 1., 1.
15, 0., 0., 2.
16, 1., 0., 2.
17, 1., 1., 2.
18, 0., 1., 2.
*ELEMENT, TYPE=C3D8, ELSET=A
1, 1, 2, 3, 4, 5, 6, 7, 8
*ELEMENT, TYPE=C3D8, ELSET=B
2, 11, 12, 13, 14, 15, 16, 17, 18
*NSET, NSET=EDGE_B
11, 14
*NSET, NSET=EDGE_A
5, 8
*NSET, NSET=FAR_B
12, 13
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=A, MATERIAL=STEEL
*SOLID SECTION, ELSET=B, MATERIAL=STEEL
*SURFACE, NAME=A_TOP
A, S2
*SURFACE, NAME=B_BOTTOM
B, S1
*SURFACE INTERACTION, NAME=DRY
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*CONTACT PAIR, INTERACTION=DRY
B_BOTTOM, A_TOP
*SURFACE, NAME=LEFT, TYPE=NODE
1, 4, 5, 8
*SURFACE, NAME=RIGHT, TYPE=NODE
2, 3, 6, 7
)";

Model read(const std::string& name, const std::string& text) {
  return read_inp(write_deck(name, text), fake_registry());
}

const char* const kCyclic = R"(*TIE, NAME=CYC, CYCLIC SYMMETRY, POSITION TOLERANCE=0.01
LEFT, RIGHT
*CYCLIC SYMMETRY MODEL, N=12, NGRAPH=3, TIE=CYC
0., 0., 0., 0., 0., 1.
)";

const char* const kPenetration = R"(*STEP
*STATIC
*PRESSURE PENETRATION, SLAVE=B_BOTTOM, MASTER=A_TOP, LEAK=FAR_B
EDGE_B, EDGE_A, 16., 0.5
*END STEP
*STEP
*STATIC
*PRESSURE PENETRATION, SLAVE=b_bottom, MASTER=a_top
11, 5, 20.
*END STEP
)";

TEST(JointKeywords, CyclicSymmetryTieAndModelLandInTheModel) {
  const std::string text = std::string(kBlocks) + kCyclic + "*STEP\n*STATIC\n*END STEP\n";
  const Model m = read("cyclic.inp", text);
  ASSERT_EQ(m.cyclic_symmetries.size(), 1u);
  const CyclicSymmetry& c = m.cyclic_symmetries[0];
  EXPECT_EQ(c.tie, "CYC");
  EXPECT_EQ(c.slave, "LEFT");
  EXPECT_EQ(c.master, "RIGHT");
  ASSERT_TRUE(c.position_tolerance.has_value());
  EXPECT_EQ(*c.position_tolerance, 0.01);
  EXPECT_EQ(c.sectors, 12);
  EXPECT_EQ(c.ngraph, 3);
  EXPECT_EQ(c.b, (Vec3{0, 0, 1}));
  EXPECT_EQ(c.where.line, line_of(text, "*TIE"));
  EXPECT_EQ(c.model_where.line, line_of(text, "*CYCLIC SYMMETRY MODEL"));
}

TEST(JointKeywords, PressurePenetrationIsStepDataThatCarriesOverAndIsReplaced) {
  const std::string text = std::string(kBlocks) + kPenetration;
  const Model m = read("penetration.inp", text);
  ASSERT_EQ(m.steps.size(), 2u);
  ASSERT_EQ(m.steps[0].penetrations.size(), 1u);
  const PressurePenetration& pp = m.steps[0].penetrations[0];
  EXPECT_EQ(pp.slave, "B_BOTTOM");
  EXPECT_EQ(pp.master, "A_TOP");
  EXPECT_EQ(pp.exposed_slave, (std::vector<int>{m.node_index(11), m.node_index(14)}));
  EXPECT_EQ(pp.exposed_master, (std::vector<int>{m.node_index(5), m.node_index(8)}));
  EXPECT_EQ(pp.pressure, 16.0);
  EXPECT_EQ(pp.critical, 0.5);
  EXPECT_EQ(pp.leak_nset, "FAR_B");
  EXPECT_EQ(pp.where.line, line_of(text, "*PRESSURE PENETRATION"));
  // The second step's definition is for the same pair (names are case-insensitive).
  ASSERT_EQ(m.steps[1].penetrations.size(), 1u);
  EXPECT_EQ(m.steps[1].penetrations[0].pressure, 20.0);
  EXPECT_EQ(m.steps[1].penetrations[0].critical, 0.0);  // the default
  EXPECT_FALSE(m.steps[1].penetration_op_new);
}

TEST(JointKeywords, WrittenDecksReadBackTheSame) {
  const Model m = read("joint_keywords.inp", std::string(kBlocks) + kCyclic + kPenetration);
  std::ostringstream out;
  write_inp(m, out);
  const Model back = read("joint_keywords_back.inp", out.str());
  ASSERT_EQ(back.cyclic_symmetries.size(), 1u);
  const CyclicSymmetry& c = back.cyclic_symmetries[0];
  EXPECT_EQ(c.tie, "CYC");
  EXPECT_EQ(c.slave, "LEFT");
  EXPECT_EQ(c.master, "RIGHT");
  EXPECT_EQ(c.sectors, 12);
  EXPECT_EQ(c.ngraph, 3);
  EXPECT_EQ(*c.position_tolerance, 0.01);
  EXPECT_EQ(c.a, (Vec3{0, 0, 0}));
  EXPECT_EQ(c.b, (Vec3{0, 0, 1}));
  ASSERT_EQ(back.steps.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    ASSERT_EQ(back.steps[k].penetrations.size(), 1u);
    const PressurePenetration& a = m.steps[k].penetrations[0];
    const PressurePenetration& b = back.steps[k].penetrations[0];
    EXPECT_EQ(b.exposed_slave, a.exposed_slave);
    EXPECT_EQ(b.exposed_master, a.exposed_master);
    EXPECT_EQ(b.pressure, a.pressure);
    EXPECT_EQ(b.critical, a.critical);
    EXPECT_EQ(b.leak_nset, a.leak_nset);
  }
}

TEST(JointKeywords, RefusesWhatItDoesNotSupportByName) {
  const std::string step = "*STEP\n*STATIC\n*END STEP\n";
  expect_error("tie.inp", std::string(kBlocks) + "*TIE, NAME=T, MULTISTAGE\nLEFT, RIGHT\n" + step,
               "*TIE", "MULTISTAGE is not supported");
  expect_error(
      "tie_adjust.inp",
      std::string(kBlocks) + "*TIE, NAME=T, CYCLIC SYMMETRY, ADJUST=NO\nLEFT, RIGHT\n" + step,
      "*TIE", "ADJUST= belongs to a tied-contact *TIE");
  expect_error("check.inp",
               std::string(kBlocks) +
                   "*TIE, NAME=T, CYCLIC SYMMETRY\nLEFT, RIGHT\n*CYCLIC SYMMETRY MODEL, N=4, "
                   "CHECK=NO\n0,0,0,0,0,1\n" +
                   step,
               "*CYCLIC SYMMETRY MODEL", "CHECK=NO");
  expect_error("elset.inp",
               std::string(kBlocks) +
                   "*TIE, NAME=T, CYCLIC SYMMETRY\nLEFT, RIGHT\n*CYCLIC SYMMETRY MODEL, N=4, "
                   "ELSET=A\n0,0,0,0,0,1\n" +
                   step,
               "*CYCLIC SYMMETRY MODEL", "unknown parameter ELSET");
  expect_error("no_model.inp",
               std::string(kBlocks) + "*TIE, NAME=T, CYCLIC SYMMETRY\nLEFT, RIGHT\n" + step, "*TIE",
               "no *CYCLIC SYMMETRY MODEL");
  expect_error("axis.inp",
               std::string(kBlocks) +
                   "*TIE, NAME=T, CYCLIC SYMMETRY\nLEFT, RIGHT\n*CYCLIC SYMMETRY MODEL, N=4\n1,2,"
                   "3,1,2,3\n" +
                   step,
               "1,2,3,1,2,3", "coincide");
  expect_error("surface.inp",
               std::string(kBlocks) +
                   "*TIE, NAME=T, CYCLIC SYMMETRY\nLEFT, NOWHERE\n*CYCLIC "
                   "SYMMETRY MODEL, N=4\n0,0,0,0,0,1\n" +
                   step,
               "*TIE", "NOWHERE");
  const std::string pp = "*STEP\n*STATIC\n*PRESSURE PENETRATION, SLAVE=B_BOTTOM, MASTER=A_TOP";
  expect_error("amplitude.inp",
               std::string(kBlocks) + pp + ", AMPLITUDE=RAMP\n11, 5, 1.\n*END STEP\n",
               "*PRESSURE PENETRATION", "unknown parameter AMPLITUDE");
  expect_error("time.inp",
               std::string(kBlocks) + pp + ", PENETRATION TIME=0.1\n11, 5, 1.\n*END STEP\n",
               "*PRESSURE PENETRATION", "unknown parameter PENETRATION TIME");
  expect_error("pair.inp",
               std::string(kBlocks) +
                   "*STEP\n*STATIC\n*PRESSURE PENETRATION, SLAVE=A_TOP, MASTER=B_BOTTOM\n5, 11, "
                   "1.\n*END STEP\n",
               "*PRESSURE PENETRATION", "no *CONTACT PAIR");
  expect_error("exposed.inp", std::string(kBlocks) + pp + "\n1, 5, 1.\n*END STEP\n",
               "*PRESSURE PENETRATION", "not a node of the slave surface");
  expect_error("two_pressures.inp",
               std::string(kBlocks) + pp + "\n11, 5, 1.\n14, 8, 2.\n*END STEP\n", "14, 8, 2.",
               "same fluid and critical pressures");
  expect_error("critical.inp", std::string(kBlocks) + pp + "\n11, 5, 1., -1.\n*END STEP\n",
               "11, 5, 1., -1.", "must not be negative");
  expect_error("model_level.inp",
               std::string(kBlocks) +
                   "*PRESSURE PENETRATION, SLAVE=B_BOTTOM, MASTER=A_TOP\n11, 5, 1.\n" + step,
               "*PRESSURE PENETRATION", "only allowed inside a step");
}

}  // namespace
}  // namespace styk
