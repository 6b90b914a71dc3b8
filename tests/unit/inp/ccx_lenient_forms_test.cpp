// Forms the CalculiX test-suite decks use that ccx reads and Styk therefore reads the same way:
// Fortran D exponents, blank or trailing zero *NODE fields, DEFINITION=COORDINATES on
// *ORIENTATION, OUTPUT=2D|3D on *NODE FILE / *EL FILE and OFFSET=0 on *SOLID SECTION; and the
// forms next to them that would lose data, which stay refused at their line.
#include <gtest/gtest.h>

#include "deck_errors.hpp"
#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"

namespace styk {
namespace {

using test::expect_error;
using test::fake_registry;
using test::write_deck;

const char* const kNodes = R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
)";
const char* const kRest = R"(*ELEMENT, TYPE=C3D8, ELSET=BLOCK
1, 1, 2, 3, 4, 5, 6, 7, 8
*MATERIAL, NAME=STEEL
*ELASTIC
2.1D5, 3.d-1
*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL
*STEP
*STATIC
*NODE FILE, OUTPUT=3D
U
*EL FILE, OUTPUT=2D, SECTION FORCES
S
*END STEP
)";

Model read(const std::string& name, const std::string& text) {
  const ElementRegistry registry = fake_registry();
  return read_inp(write_deck(name, text), registry);
}

TEST(CcxLenientForms, FortranDExponentsReadAsE) {
  const Model m = read("d_exponent.inp", std::string(kNodes) + "8, 0., 1.D0, 1.d0\n" + kRest);
  ASSERT_EQ(m.materials.size(), 1u);
  const Material& steel = m.materials.front();
  EXPECT_EQ(*steel.young, 2.1e5);  // exact: the same decimal text as 2.1E5
  EXPECT_EQ(*steel.poisson, 0.3);
  EXPECT_EQ(m.coords.back()[1], 1.0);
  EXPECT_EQ(m.coords.back()[2], 1.0);
}

TEST(CcxLenientForms, TwoExponentLettersAreRefused) {
  const std::string text = std::string(kNodes) + "8, 0., 1.D0D1, 1.\n" + kRest;
  expect_error("two_exponents.inp", text, "8, 0., 1.D0D1", "expected a number, read '1.D0D1'");
}

TEST(CcxLenientForms, BlankCoordinateIsZeroAndTrailingZeroFieldIgnored) {
  // ccx's planestress.inp has "21, 7.5e-01, 1.0, ,0.0": z blank (0), a fifth field ccx ignores.
  const Model m = read("blank_z.inp", std::string(kNodes) + "8, 0.,1., ,0.0\n" + kRest);
  EXPECT_EQ(m.coords.back()[0], 0.0);
  EXPECT_EQ(m.coords.back()[1], 1.0);
  EXPECT_EQ(m.coords.back()[2], 0.0);
}

TEST(CcxLenientForms, TrailingNonzeroFieldIsRefusedBecauseItWouldBeLost) {
  const std::string text = std::string(kNodes) + "8, 0.,1., ,1.0\n" + kRest;
  // Field 5 is the first component of a normal in Abaqus' form, which only a shell takes.
  expect_error("lost_z.inp", text, "8, 0.,1., ,1.0",
               "has a normal (fields 5-7) but belongs to no curved shell");
}

TEST(CcxLenientForms, OrientationDefinitionCoordinatesIsTheDefault) {
  const std::string axes =
      "*ORIENTATION, NAME=OR1, DEFINITION=COORDINATES, SYSTEM=RECTANGULAR\n"
      "0., 1., 0., -1., 0., 0.\n";
  const Model m = read("definition.inp", std::string(kNodes) + "8, 0., 1., 1.\n" + axes + kRest);
  EXPECT_EQ(m.orientations.count("OR1"), 1u);
  const std::string by_nodes =
      "*ORIENTATION, NAME=OR1, DEFINITION=NODES\n0., 1., 0., -1., 0., 0.\n";
  expect_error("definition_nodes.inp", std::string(kNodes) + "8, 0., 1., 1.\n" + by_nodes + kRest,
               "*ORIENTATION", "DEFINITION=NODES of *ORIENTATION is not supported");
}

TEST(CcxLenientForms, FileOutputDimensionAndZeroSolidOffsetAreRead) {
  std::string text = std::string(kNodes) + "8, 0., 1., 1.\n" + kRest;
  text.replace(text.find("MATERIAL=STEEL\n*STEP"), 14, "MATERIAL=STEEL, OFFSET=0.");
  const Model m = read("offset_zero.inp", text);
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_EQ(m.steps[0].outputs.size(), 2u);

  std::string shifted = text;
  shifted.replace(shifted.find("OFFSET=0."), 9, "OFFSET=0.5");
  expect_error("offset_half.inp", shifted, "*SOLID SECTION", "OFFSET=0.5 on *SOLID SECTION");
  std::string four_d = std::string(kNodes) + "8, 0., 1., 1.\n" + kRest;
  four_d.replace(four_d.find("OUTPUT=3D"), 9, "OUTPUT=4D");
  expect_error("output_4d.inp", four_d, "*NODE FILE", "OUTPUT=4D of *NODE FILE: expected 2D or 3D");
}

}  // namespace
}  // namespace styk
