// read_inp / write_inp on the steady scalar-field keywords (docs/input.md, "Steady heat and
// electric potential"): *HEAT TRANSFER, *COUPLED THERMAL-ELECTRICAL, *CONDUCTIVITY,
// *ELECTRICAL CONDUCTIVITY, *CFLUX, *CECUR, *DFLUX and dofs 11 / 9 in *BOUNDARY; what lands in
// the Model, what round-trips through the writer, and what is refused at which line.
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

const char* const kMesh = R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*ELEMENT, TYPE=C3D8, ELSET=BLOCK
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=BOTTOM
1, 2, 3, 4
*NSET, NSET=TOP
5, 6, 7, 8
*SOLID SECTION, ELSET=BLOCK, MATERIAL=COPPER
)";

const char* const kHeatMaterial = "*MATERIAL, NAME=COPPER\n*CONDUCTIVITY\n390.\n";
const char* const kHeatStep =
    "*STEP\n*HEAT TRANSFER, STEADY STATE\n1., 1.\n*BOUNDARY\nBOTTOM, 11, 11, 20.\n"
    "*CFLUX\nTOP, 11, 2.5\n*DFLUX\n1, S2, 4.\n*NODE PRINT, NSET=ALL\nNT, RFL\n*EL PRINT\nHFL\n"
    "*END STEP\n";

Model read(const std::string& name, const std::string& text) {
  const ElementRegistry registry = fake_registry();
  return read_inp(write_deck(name, text), registry);
}

TEST(ScalarInput, HeatStepLandsInTheModelAndRoundTrips) {
  const std::string text = std::string(kMesh) + kHeatMaterial + kHeatStep;
  const Model m = read("heat.inp", text);
  ASSERT_EQ(m.steps.size(), 1u);
  const Step& step = m.steps[0];
  EXPECT_EQ(step.kind, StepKind::HeatTransfer);
  ASSERT_TRUE(m.materials[0].conductivity.has_value());
  EXPECT_EQ((*m.materials[0].conductivity)[2], 390.0);
  EXPECT_FALSE(m.materials[0].young.has_value());  // a heat deck needs no *ELASTIC
  ASSERT_EQ(step.boundaries.size(), 4u);
  EXPECT_EQ(step.boundaries[0].dof, 11);
  EXPECT_EQ(step.boundaries[0].value, 20.0);
  ASSERT_EQ(step.cfluxes.size(), 4u);
  EXPECT_EQ(step.cfluxes[0].value, 2.5);
  ASSERT_EQ(step.dfluxes.size(), 1u);
  EXPECT_EQ(step.dfluxes[0].face, 2);
  EXPECT_EQ(step.outputs[0].vars, (std::vector<std::string>{"NT", "RFL"}));
  EXPECT_EQ(step.outputs[1].vars, (std::vector<std::string>{"HFL"}));

  std::ostringstream written;
  write_inp(m, written);
  const Model back = read("heat_back.inp", written.str());
  EXPECT_EQ(back.steps[0].kind, StepKind::HeatTransfer);
  EXPECT_EQ(back.steps[0].boundaries.size(), 4u);
  EXPECT_EQ(back.steps[0].cfluxes.size(), 4u);
  EXPECT_EQ(back.steps[0].dfluxes.size(), 1u);
  EXPECT_EQ(*back.materials[0].conductivity, *m.materials[0].conductivity);
}

TEST(ScalarInput, ElectricStepWithOrthotropicConductivity) {
  const std::string text = std::string(kMesh) +
                           "*MATERIAL, NAME=COPPER\n*ELECTRICAL CONDUCTIVITY, TYPE=ORTHO\n"
                           "1., 2., 3.\n*BOUNDARY\nBOTTOM, 9, 9, -1.\n*STEP\n"
                           "*COUPLED THERMAL-ELECTRICAL, STEADY STATE\n*CECUR\n7, 9, 0.5\n"
                           "*NODE PRINT, NSET=TOP\nEPOT, RECUR\n*EL PRINT\nECD\n*END STEP\n";
  const Model m = read("electric.inp", text);
  EXPECT_EQ(m.steps[0].kind, StepKind::ElectricConduction);
  EXPECT_EQ(*m.materials[0].electrical_conductivity, (std::array<double, 3>{1.0, 2.0, 3.0}));
  ASSERT_EQ(m.boundaries.size(), 4u);
  EXPECT_EQ(m.boundaries[0].dof, 9);
  ASSERT_EQ(m.steps[0].cfluxes.size(), 1u);
  EXPECT_EQ(m.steps[0].cfluxes[0].dof, 9);

  std::ostringstream written;
  write_inp(m, written);
  EXPECT_NE(written.str().find("*ELECTRICAL CONDUCTIVITY, TYPE=ORTHO"), std::string::npos);
  const Model back = read("electric_back.inp", written.str());
  EXPECT_EQ(back.steps[0].kind, StepKind::ElectricConduction);
  EXPECT_EQ(back.steps[0].cfluxes.size(), 1u);
}

TEST(ScalarInput, MisfitsAreRefusedAtTheirLine) {
  const std::string mesh = kMesh;
  const std::string heat = kHeatMaterial;
  expect_error("transient.inp", mesh + heat + "*STEP\n*HEAT TRANSFER\n*END STEP\n",
               "*HEAT TRANSFER", "without STEADY STATE is a transient analysis");
  expect_error("no_conductivity.inp",
               mesh + "*MATERIAL, NAME=COPPER\n*ELASTIC\n1., 0.3\n" + kHeatStep, "*MATERIAL",
               "has no *CONDUCTIVITY");
  expect_error("dof11_static.inp",
               mesh +
                   "*MATERIAL, NAME=COPPER\n*ELASTIC\n1., 0.3\n*STEP\n*STATIC\n*BOUNDARY\n"
                   "BOTTOM, 11, 11, 5.\n*END STEP\n",
               "BOTTOM, 11", "dof 11 (temperature) in a *STATIC step");
  expect_error("dof1_heat.inp",
               mesh + heat +
                   "*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\nBOTTOM, 1, 3\n"
                   "*END STEP\n",
               "BOTTOM, 1, 3", "*HEAT TRANSFER steps take dof 11 (temperature) only");
  expect_error("cload_heat.inp",
               mesh + heat +
                   "*STEP\n*HEAT TRANSFER, STEADY STATE\n*CLOAD\nTOP, 3, 1.\n"
                   "*END STEP\n",
               "TOP, 3", "use *CFLUX");
  expect_error("cflux_dof.inp",
               mesh + heat +
                   "*STEP\n*HEAT TRANSFER, STEADY STATE\n*CFLUX\nTOP, 9, 1.\n"
                   "*END STEP\n",
               "TOP, 9", "*CFLUX acts on dof 11");
  expect_error("dflux_label.inp",
               mesh + heat +
                   "*STEP\n*HEAT TRANSFER, STEADY STATE\n*DFLUX\n1, BF, 1.\n"
                   "*END STEP\n",
               "1, BF", "flux label 'BF' is not supported");
  expect_error("hfl_static.inp",
               mesh +
                   "*MATERIAL, NAME=COPPER\n*ELASTIC\n1., 0.3\n*STEP\n*STATIC\n"
                   "*EL PRINT\nHFL\n*END STEP\n",
               "*EL PRINT", "output variable HFL in a *STATIC step");
  expect_error("dof_range.inp",
               mesh + heat +
                   "*BOUNDARY\nBOTTOM, 1, 11\n*STEP\n*HEAT TRANSFER, STEADY STATE\n"
                   "*END STEP\n",
               "BOTTOM, 1, 11", "a scalar-field dof (9, 11) is given alone");
  expect_error(
      "conductivity_negative.inp",
      mesh + "*MATERIAL, NAME=COPPER\n*CONDUCTIVITY, TYPE=ORTHO\n1., -2., 3.\n" + kHeatStep,
      "1., -2.", "conductivity must be positive");
  expect_error("model_dof9_heat.inp",
               mesh + heat +
                   "*BOUNDARY\nBOTTOM, 9, 9, 1.\n*STEP\n*HEAT TRANSFER, STEADY STATE\n"
                   "*END STEP\n",
               "BOTTOM, 9", "cannot take it");
}

}  // namespace
}  // namespace styk
