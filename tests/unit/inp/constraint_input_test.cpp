// read_inp on *ORIENTATION, *TRANSFORM, *EQUATION, *INITIAL CONDITIONS, *TEMPERATURE and the
// *STATIC increment fields: what lands in the Model and what is refused, at which line.
#include <gtest/gtest.h>

#include <cmath>

#include "deck_errors.hpp"
#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"

namespace styk {
namespace {

using test::expect_error;
using test::fake_registry;
using test::line_of;
using test::write_deck;

const char* const kBlock = R"(*NODE, NSET=ALL
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
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*EXPANSION, ZERO=20.
1.2e-5
*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL
)";

const char* const kStep = "*STEP\n*STATIC\n*END STEP\n";

Model read(const std::string& name, const std::string& text) {
  const ElementRegistry registry = fake_registry();
  return read_inp(write_deck(name, text), registry);
}

TEST(ConstraintInput, TransformsAndOrientationsLandInTheModel) {
  // A sector symmetry plane at 22.5 degrees: local x along (cos, sin, 0) of 22.5 deg.
  const double c = std::cos(M_PI / 8), s = std::sin(M_PI / 8);
  const std::string plane = std::to_string(c) + ", " + std::to_string(s) + ", 0., " +
                            std::to_string(-s) + ", " + std::to_string(c) + ", 0.\n";
  const std::string text = std::string(kBlock) + "*TRANSFORM, NSET=TOP, TYPE=R\n" + plane +
                           "*TRANSFORM, NSET=BOTTOM, TYPE=C\n0., 0., 0., 0., 0., 1.\n" +
                           "*ORIENTATION, NAME=Cyl, SYSTEM=CYLINDRICAL\n0., 0., 0., 0., 0., 1.\n" +
                           kStep;
  const Model m = read("transforms.inp", text);
  ASSERT_EQ(m.transforms.size(), 2u);
  EXPECT_EQ(m.transforms[0].nset, "TOP");
  EXPECT_EQ(m.transforms[0].axes.system, CoordinateSystem::Rectangular);
  EXPECT_NEAR(m.transforms[0].axes.a[0], c, 1e-6);
  EXPECT_NEAR(m.transforms[0].axes.b[0], -s, 1e-6);
  EXPECT_EQ(m.transforms[0].where.line, line_of(text, "*TRANSFORM, NSET=TOP"));
  EXPECT_EQ(m.transforms[1].axes.system, CoordinateSystem::Cylindrical);
  EXPECT_EQ(m.transforms[1].axes.b, (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(m.orientations.at("CYL").axes.system, CoordinateSystem::Cylindrical);
}

TEST(ConstraintInput, TransformAndOrientationErrors) {
  const std::string base = kBlock;
  expect_error("transform_nset.inp",
               base + "*TRANSFORM, NSET=SIDE\n1., 0., 0., 0., 1., 0.\n" + kStep, "*TRANSFORM",
               "NSET=SIDE of *TRANSFORM is not defined; node sets: ALL, BOTTOM");
  expect_error("transform_twice.inp",
               base + "*TRANSFORM, NSET=TOP\n1., 0., 0., 0., 1., 0.\n" +
                   "*TRANSFORM, NSET=ALL, TYPE=C\n0., 0., 0., 0., 0., 1.\n" + kStep,
               "*TRANSFORM, NSET=ALL", "node 5 of NSET=ALL already has a *TRANSFORM (NSET=TOP");
  expect_error("transform_type.inp",
               base + "*TRANSFORM, NSET=TOP, TYPE=S\n1., 0., 0., 0., 1., 0.\n" + kStep,
               "*TRANSFORM", "TYPE=S is not supported");
  expect_error("transform_parallel.inp",
               base + "*TRANSFORM, NSET=TOP\n1., 0., 0., -2., 0., 0.\n" + kStep, "-2.",
               "point b must not lie on the line of a");
  expect_error("transform_origin.inp",
               base + "*TRANSFORM, NSET=TOP\n0., 0., 0., 0., 1., 0.\n" + kStep, "0., 0., 0., 0., 1",
               "point a must not be the origin");
  expect_error("transform_axis.inp",
               base + "*TRANSFORM, NSET=TOP, TYPE=C\n1., 2., 3., 1., 2., 3.\n" + kStep,
               "1., 2., 3.", "the two axis points a and b must differ");
  expect_error("transform_fields.inp", base + "*TRANSFORM, NSET=TOP\n1., 0., 0.5\n" + kStep,
               "1., 0., 0.5", "expected a1, a2, a3, b1, b2, b3");
  expect_error("transform_in_step.inp",
               base + "*STEP\n*STATIC\n*TRANSFORM, NSET=TOP\n1., 0., 0., 0., 1., 0.\n*END STEP\n",
               "*TRANSFORM", "*TRANSFORM is not allowed inside a step");
  expect_error("orientation_twice.inp",
               base + "*ORIENTATION, NAME=O\n1., 0., 0., 0., 1., 0.\n" +
                   "*ORIENTATION, NAME=O\n1., 0., 0., 0., 1., 0.\n" + kStep,
               "*ORIENTATION, NAME=O\n1., 0., 0., 0., 1., 0.\n*STEP",
               "orientation O is defined twice");
  expect_error("orientation_system.inp",
               base + "*ORIENTATION, NAME=O, SYSTEM=SPHERICAL\n1., 0., 0., 0., 1., 0.\n" + kStep,
               "*ORIENTATION", "SYSTEM=SPHERICAL is not supported");
  expect_error("orientation_rotation_line.inp",
               base + "*ORIENTATION, NAME=O\n1., 0., 0., 0., 1., 0.\n3, 10.\n" + kStep, "3, 10.",
               "takes one data line");
}

TEST(ConstraintInput, EquationsLandInTheModel) {
  const std::string text = std::string(kBlock) + R"(*EQUATION
2
5, 1, 1., 6, 1, -1.
5
7, 3, 2.5, 8, 3, -1., 6, 3, -0.5, 5, 3, -0.5,
4, 3, -0.5
*EQUATION
3
8, 2, 1.
7, 2, -0.5
6, 2, -0.5
)" + kStep;
  const Model m = read("equations.inp", text);
  ASSERT_EQ(m.equations.size(), 3u);
  const Equation& e0 = m.equations[0];
  ASSERT_EQ(e0.terms.size(), 2u);
  EXPECT_EQ(e0.terms[0].node, m.node_index(5));
  EXPECT_EQ(e0.terms[0].dof, 1);
  EXPECT_EQ(e0.terms[0].coefficient, 1.0);
  EXPECT_EQ(e0.terms[1].node, m.node_index(6));
  EXPECT_EQ(e0.terms[1].coefficient, -1.0);
  EXPECT_EQ(e0.where.line, line_of(text, "2\n5, 1"));
  const Equation& e1 = m.equations[1];
  ASSERT_EQ(e1.terms.size(), 5u);  // four terms on a line, the fifth on the next
  EXPECT_EQ(e1.terms[0].coefficient, 2.5);
  EXPECT_EQ(e1.terms[4].node, m.node_index(4));
  EXPECT_EQ(e1.terms[4].dof, 3);
  ASSERT_EQ(m.equations[2].terms.size(), 3u);
  EXPECT_EQ(m.equations[2].terms[2].coefficient, -0.5);
}

TEST(ConstraintInput, EquationErrors) {
  const std::string base = std::string(kBlock) + "*EQUATION\n";
  expect_error("equation_one_term.inp", base + "1\n5, 1, 1.\n" + kStep, "1\n5, 1",
               "an equation needs at least 2 terms, read 1");
  expect_error("equation_zero_first.inp", base + "2\n5, 1, 0., 6, 1, 1.\n" + kStep, "5, 1, 0.",
               "the first coefficient of an equation must not be zero");
  expect_error("equation_dof_11.inp", base + "2\n5, 11, 1., 6, 11, -1.\n" + kStep, "5, 11",
               "dof of term 1 11 (temperature) is not supported yet");
  expect_error("equation_dof_7.inp", base + "2\n5, 1, 1., 6, 7, -1.\n" + kStep, "5, 1, 1., 6, 7",
               "dof of term 2 7 is out of range");
  expect_error("equation_short.inp", base + "3\n5, 1, 1., 6, 1, -1.\n" + kStep, "3\n5, 1",
               "the equation announces 3 terms but gives 2");
  expect_error("equation_fields.inp", base + "2\n5, 1, 1., 6, 1\n" + kStep, "5, 1, 1., 6, 1\n",
               "term line has 5 fields");
  expect_error("equation_too_many.inp", base + "2\n5, 1, 1., 6, 1, -1., 7, 1, 1.\n" + kStep,
               "5, 1, 1., 6", "expected node, dof, coefficient for 1 to 2 terms");
  expect_error("equation_node.inp", base + "2\n5, 1, 1., 66, 1, -1.\n" + kStep, "5, 1, 1., 66",
               "node 66 is not defined");
  // A node set: copy 1 pairs node 5 with itself (keyword_coverage_input_test: node sets).
  expect_error("equation_set.inp", base + "2\n5, 1, 1., TOP, 1, -1.\n" + kStep, "5, 1, 1., TOP",
               "node 5, dof 1 appears twice in the equation");
  expect_error("equation_repeat.inp", base + "2\n5, 1, 1., 5, 1, -1.\n" + kStep, "5, 1, 1., 5",
               "node 5, dof 1 appears twice in the equation");
  expect_error("equation_dependent_twice.inp",
               base + "2\n5, 1, 1., 6, 1, -1.\n2\n5, 1, 1., 7, 1, -1.\n" + kStep, "2\n5, 1, 1., 7",
               "node 5, dof 1 is already the dependent (first) term of the equation at");
  expect_error("equation_empty.inp", base + kStep, "*EQUATION", "*EQUATION needs data lines");
  expect_error(
      "equation_in_step.inp",
      std::string(kBlock) + "*STEP\n*STATIC\n*EQUATION\n2\n5, 1, 1., 6, 1, -1.\n*END STEP\n",
      "*EQUATION", "*EQUATION is not allowed inside a step");
}

TEST(ThermalInput, InitialAndStepTemperaturesLandInTheModel) {
  const std::string text = std::string(kBlock) + R"(*INITIAL CONDITIONS, TYPE=TEMPERATURE
ALL, 20.
3, 25.
*STEP
*STATIC
*TEMPERATURE
TOP, 120.
*END STEP
*STEP
*STATIC
*TEMPERATURE, OP=NEW
5, 80.
*END STEP
*STEP
*STATIC
*TEMPERATURE, OP=NEW
*END STEP
)";
  const Model m = read("temperatures.inp", text);
  ASSERT_EQ(m.initial_temperatures.size(), 9u);  // eight from ALL, then node 3 again
  EXPECT_EQ(m.initial_temperatures[0].value, 20.0);
  EXPECT_EQ(m.initial_temperatures[8].node, m.node_index(3));
  EXPECT_EQ(m.initial_temperatures[8].value, 25.0);
  EXPECT_EQ(m.initial_temperatures[8].where.line, line_of(text, "3, 25."));
  ASSERT_EQ(m.steps.size(), 3u);
  ASSERT_EQ(m.steps[0].temperatures.size(), 4u);
  EXPECT_EQ(m.steps[0].temperatures[0].node, m.node_index(5));
  EXPECT_EQ(m.steps[0].temperatures[0].value, 120.0);
  EXPECT_FALSE(m.steps[0].temperature_op_new);
  ASSERT_EQ(m.steps[1].temperatures.size(), 1u);
  EXPECT_TRUE(m.steps[1].temperature_op_new);
  EXPECT_TRUE(m.steps[2].temperatures.empty());
  EXPECT_TRUE(m.steps[2].temperature_op_new);
}

TEST(ThermalInput, TemperatureErrors) {
  const std::string base = kBlock;
  expect_error("temperature_node.inp", base + "*STEP\n*STATIC\n*TEMPERATURE\n99, 100.\n*END STEP\n",
               "99, 100.", "node 99 is not defined");
  expect_error("temperature_set.inp", base + "*STEP\n*STATIC\n*TEMPERATURE\nHOT, 100.\n*END STEP\n",
               "HOT, 100.", "node set HOT is not defined");
  expect_error("temperature_outside.inp", base + "*TEMPERATURE\nTOP, 100.\n" + kStep,
               "*TEMPERATURE", "*TEMPERATURE is only allowed inside a step");
  expect_error("temperature_empty.inp", base + "*STEP\n*STATIC\n*TEMPERATURE\n*END STEP\n",
               "*TEMPERATURE", "*TEMPERATURE needs data lines");
  expect_error("temperature_op.inp",
               base + "*STEP\n*STATIC\n*TEMPERATURE, OP=ADD\nTOP, 1.\n*END STEP\n", "*TEMPERATURE",
               "OP=ADD on *TEMPERATURE: expected NEW or MOD");
  expect_error("temperature_value.inp",
               base + "*STEP\n*STATIC\n*TEMPERATURE\nTOP, hot\n*END STEP\n", "TOP, hot",
               "field 2 (temperature)");
  expect_error("initial_type.inp", base + "*INITIAL CONDITIONS, TYPE=VELOCITY\n1, 0.\n" + kStep,
               "*INITIAL CONDITIONS", "TYPE=VELOCITY is not supported");
  expect_error("initial_no_type.inp", base + "*INITIAL CONDITIONS\n1, 0.\n" + kStep,
               "*INITIAL CONDITIONS", "needs TYPE=");
  expect_error("initial_fields.inp",
               base + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n1, 0., 5.\n" + kStep, "1, 0., 5.",
               "expected node or node set, temperature");
  expect_error("initial_in_step.inp",
               base + "*STEP\n*STATIC\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n1, 0.\n*END STEP\n",
               "*INITIAL CONDITIONS", "not allowed inside a step");
}

TEST(StaticInput, IncrementFieldsAndDirectAreStored) {
  const std::string text = std::string(kBlock) +
                           "*STEP\n*STATIC, DIRECT\n0.1, 2., 0.01, 0.5\n*END STEP\n"
                           "*STEP\n*STATIC\n0.2, 1., , 0.4\n*END STEP\n"
                           "*STEP\n*STATIC\n*END STEP\n";
  const Model m = read("static.inp", text);
  const StaticProcedure& fixed = m.steps[0].procedure;
  EXPECT_TRUE(fixed.fixed_increments);
  EXPECT_EQ(fixed.initial_increment, 0.1);
  EXPECT_EQ(fixed.total_time, 2.0);
  EXPECT_EQ(fixed.min_increment, 0.01);
  EXPECT_EQ(fixed.max_increment, 0.5);
  const StaticProcedure& automatic = m.steps[1].procedure;
  EXPECT_FALSE(automatic.fixed_increments);
  EXPECT_FALSE(automatic.min_increment.has_value());
  EXPECT_EQ(automatic.max_increment, 0.4);
  EXPECT_FALSE(m.steps[2].procedure.min_increment.has_value());
  EXPECT_FALSE(m.steps[2].procedure.max_increment.has_value());
  EXPECT_FALSE(m.steps[2].procedure.fixed_increments);

  expect_error("static_min_max.inp",
               std::string(kBlock) + "*STEP\n*STATIC\n0.1, 1., 0.5, 0.2\n*END STEP\n",
               "0.1, 1., 0.5", "the minimum increment (0.5) is larger than the maximum increment");
  expect_error("static_direct_value.inp",
               std::string(kBlock) + "*STEP\n*STATIC, DIRECT=YES\n*END STEP\n", "*STATIC, DIRECT",
               "parameter DIRECT of *STATIC takes no value");
}

}  // namespace
}  // namespace styk
