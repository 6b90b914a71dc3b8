// read_inp on the keywords real CalculiX decks need (issue 15 items 1-5): material types and
// tables, body and surface loads, initial stresses, section changes, ties, couplings, MPCs,
// pre-tension sections, node sets in *EQUATION and the output options. What lands in the Model,
// and what is refused at which line.
#include <gtest/gtest.h>

#include "deck_errors.hpp"
#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

#include <sstream>

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
*SURFACE, NAME=TOPFACE
1, S2
*SURFACE, NAME=BOTFACE
1, S1
)";

const char* const kSteel =
    "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
    "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL\n";
const char* const kStep = "*STEP\n*STATIC\n*END STEP\n";

Model read(const std::string& name, const std::string& text) {
  const ElementRegistry registry = fake_registry();
  return read_inp(write_deck(name, text), registry);
}

// The written deck reads back to the same model data (the writer's contract).
Model round_trip(const Model& m, const std::string& name) {
  std::ostringstream out;
  write_inp(m, out);
  return read(name, out.str());
}

TEST(KeywordCoverage, ElasticTypesAndTemperatureTables) {
  const std::string deck = std::string(kBlock) +
                           "*MATERIAL, NAME=ISOT\n*ELASTIC\n200000., 0.3, 20.\n150000., 0.32, "
                           "300.\n*MATERIAL, NAME=ORTHO\n*ELASTIC, TYPE=ORTHO\n1., 0.1, 2., 0.1, "
                           "0.1, 3., 0.5, 0.6,\n0.7, 50.\n*MATERIAL, NAME=ENG\n*ELASTIC, "
                           "TYPE=ENGINEERING CONSTANTS\n100., 50., 20., 0.3, 0.2, 0.25, 30., 20.\n"
                           "10.\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
                           "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL\n" +
                           kStep;
  const Model m = read("kc_elastic.inp", deck);
  const Material& isot = m.materials[m.material_index("ISOT")];
  EXPECT_FALSE(isot.young.has_value());  // a table, not the constant law
  ASSERT_EQ(isot.elastic_table.size(), 2u);
  EXPECT_EQ(isot.elastic_table[1].values, (std::vector<double>{150000.0, 0.32}));
  EXPECT_EQ(isot.elastic_table[1].temperature, 300.0);
  const Material& ortho = m.materials[m.material_index("ORTHO")];
  EXPECT_EQ(ortho.elastic_type, ElasticType::Orthotropic);
  ASSERT_EQ(ortho.elastic_table.size(), 1u);
  EXPECT_EQ(ortho.elastic_table[0].values.size(), 9u);
  EXPECT_EQ(ortho.elastic_table[0].values[8], 0.7);
  EXPECT_EQ(ortho.elastic_table[0].temperature, 50.0);
  const Material& eng = m.materials[m.material_index("ENG")];
  EXPECT_EQ(eng.elastic_type, ElasticType::EngineeringConstants);
  EXPECT_EQ(eng.elastic_table[0].values[8], 10.0);
  // Written and read back: the same tables.
  const Model back = round_trip(m, "kc_elastic_back.inp");
  EXPECT_EQ(back.materials[back.material_index("ORTHO")].elastic_table[0].values,
            ortho.elastic_table[0].values);
  EXPECT_EQ(back.materials[back.material_index("ISOT")].elastic_table.size(), 2u);
}

TEST(KeywordCoverage, ElasticErrors) {
  const std::string base = std::string(kBlock) + "*MATERIAL, NAME=M\n";
  expect_error("kc_el_type.inp", base + "*ELASTIC, TYPE=HYPER\n1., 0.3\n" + kStep,
               "*ELASTIC, TYPE=HYPER", "TYPE=HYPER is not known");
  expect_error("kc_el_order.inp", base + "*ELASTIC\n1., 0.3, 100.\n2., 0.3, 50.\n" + kStep,
               "2., 0.3, 50.", "temperatures must increase");
  expect_error("kc_el_short.inp", base + "*ELASTIC, TYPE=ORTHO\n1., 0.1, 2., 0.1, 0.1\n" + kStep,
               "1., 0.1, 2., 0.1, 0.1", "8 fields per line");
  // Not positive definite: a negative shear modulus, reported at its data line.
  expect_error("kc_el_pd.inp",
               base + "*ELASTIC, TYPE=ORTHO\n1., 0.1, 2., 0.1, 0.1, 3., -0.5, 0.6,\n0.7\n" + kStep,
               "3., -0.5, 0.6", "positive definite");
  expect_error("kc_el_temp_missing.inp", base + "*ELASTIC\n1., 0.3, 0.\n2., 0.3\n" + kStep,
               "2., 0.3\n", "needs its temperature");
}

TEST(KeywordCoverage, ExpansionTypesAndOrientationOnSection) {
  const std::string deck = std::string(kBlock) +
                           "*ORIENTATION, NAME=ROT\n0., 1., 0., -1., 0., 0.\n"
                           "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*EXPANSION, TYPE=ORTHO, "
                           "ZERO=20.\n1e-5, 2e-5, 3e-5, 0.\n1.5e-5, 2e-5, 3e-5, 100.\n"
                           "*SOLID SECTION, ELSET=BLOCK, MATERIAL=M, ORIENTATION=ROT\n" +
                           kStep;
  const Model m = read("kc_expansion.inp", deck);
  const Material& mat = m.materials[0];
  EXPECT_EQ(mat.expansion_type, ExpansionType::Orthotropic);
  EXPECT_FALSE(mat.expansion.has_value());
  ASSERT_EQ(mat.expansion_table.size(), 2u);
  EXPECT_EQ(mat.expansion_table[1].values, (std::vector<double>{1.5e-5, 2e-5, 3e-5}));
  EXPECT_EQ(mat.expansion_reference, 20.0);
  EXPECT_EQ(m.sections[0].orientation, "ROT");
  const Model back = round_trip(m, "kc_expansion_back.inp");
  EXPECT_EQ(back.sections[0].orientation, "ROT");
  EXPECT_EQ(back.materials[0].expansion_table[1].values, mat.expansion_table[1].values);
  expect_error("kc_orientation_missing.inp",
               std::string(kBlock) +
                   "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n*SOLID SECTION, "
                   "ELSET=BLOCK, MATERIAL=M, ORIENTATION=NOPE\n" +
                   kStep,
               "ORIENTATION=NOPE", "ORIENTATION=NOPE, which is not defined");
}

TEST(KeywordCoverage, BodyLoadsSurfacePressureAndSectionChange) {
  const std::string deck = std::string(kBlock) + kSteel +
                           "*MATERIAL, NAME=ALU\n*ELASTIC\n70000., 0.33\n*STEP\n*STATIC\n*DLOAD\n"
                           "BLOCK, GRAV, 9810., 0., 0., -2.\nBLOCK, CENTRIF, 100., 1., 2., 3., 0., "
                           "0., 5.\n*DSLOAD\nTOPFACE, P, 4.5\n*END STEP\n*STEP\n*CHANGE SOLID "
                           "SECTION, ELSET=BLOCK, MATERIAL=ALU\n*STATIC\n*END STEP\n";
  const Model m = read("kc_loads.inp", deck);
  const Step& s = m.steps[0];
  ASSERT_EQ(s.body_loads.size(), 2u);
  EXPECT_EQ(s.body_loads[0].kind, BodyLoad::Kind::Gravity);
  EXPECT_EQ(s.body_loads[0].magnitude, 9810.0);
  EXPECT_EQ(s.body_loads[0].direction, (Vec3{0.0, 0.0, -1.0}));  // normalised
  EXPECT_EQ(s.body_loads[1].kind, BodyLoad::Kind::Centrifugal);
  EXPECT_EQ(s.body_loads[1].point, (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(s.body_loads[1].direction, (Vec3{0.0, 0.0, 1.0}));
  ASSERT_EQ(s.dloads.size(), 1u);  // *DSLOAD: a P2 pressure on element 1
  EXPECT_EQ(s.dloads[0].face, 2);
  EXPECT_EQ(s.dloads[0].magnitude, 4.5);
  ASSERT_EQ(m.steps[1].section_changes.size(), 1u);
  EXPECT_EQ(m.steps[1].section_changes[0].material_index, m.material_index("ALU"));
  const Model back = round_trip(m, "kc_loads_back.inp");
  EXPECT_EQ(back.steps[0].body_loads.size(), 2u);
  EXPECT_EQ(back.steps[1].section_changes.size(), 1u);

  const std::string base = std::string(kBlock) + kSteel + "*STEP\n*STATIC\n";
  expect_error("kc_grav_zero.inp", base + "*DLOAD\nBLOCK, GRAV, 1., 0., 0., 0.\n*END STEP\n",
               "BLOCK, GRAV", "gravity direction is the zero vector");
  expect_error("kc_dsload_label.inp", base + "*DSLOAD\nTOPFACE, TRVEC, 1.\n*END STEP\n",
               "TOPFACE, TRVEC", "'TRVEC' is not supported");
  expect_error("kc_change_material.inp",
               base + "*CHANGE SOLID SECTION, ELSET=BLOCK, MATERIAL=WOOD\n*END STEP\n",
               "*CHANGE SOLID", "material WOOD is not defined");
}

TEST(KeywordCoverage, InitialStressAndBoundaryFixed) {
  const std::string deck = std::string(kBlock) + kSteel +
                           "*INITIAL CONDITIONS, TYPE=STRESS\n1, 3, 1., 2., 3., 4., 5., 6.\n"
                           "*STEP\n*STATIC\n*END STEP\n*STEP\n*STATIC\n*BOUNDARY, FIXED\nTOP, 3, "
                           "3\n*END STEP\n";
  const Model m = read("kc_stress.inp", deck);
  ASSERT_EQ(m.initial_stresses.size(), 1u);
  EXPECT_EQ(m.initial_stresses[0].point, 3);
  EXPECT_EQ(m.initial_stresses[0].stress[5], 6.0);
  ASSERT_EQ(m.steps[1].boundaries.size(), 4u);
  EXPECT_TRUE(m.steps[1].boundaries[0].fixed);
  const Model back = round_trip(m, "kc_stress_back.inp");
  EXPECT_EQ(back.initial_stresses.size(), 1u);
  EXPECT_TRUE(back.steps[1].boundaries[0].fixed);
  expect_error("kc_user_stress.inp",
               std::string(kBlock) + kSteel + "*INITIAL CONDITIONS, TYPE=STRESS, USER\n" + kStep,
               "*INITIAL CONDITIONS", "user subroutine");
  expect_error("kc_fixed_value.inp",
               std::string(kBlock) + kSteel +
                   "*STEP\n*STATIC\n*BOUNDARY, FIXED\nTOP, 3, 3, 0.5\n*END STEP\n",
               "TOP, 3, 3, 0.5", "FIXED takes no value");
  expect_error("kc_fixed_model.inp",
               std::string(kBlock) + kSteel + "*BOUNDARY, FIXED\nTOP, 3\n" + kStep,
               "*BOUNDARY, FIXED", "it belongs inside a step");
}

TEST(KeywordCoverage, TiesCouplingsMpcsPretension) {
  const std::string deck = std::string(kBlock) + "*NODE\n100, 0.5, 0.5, 2.\n101, 0.5, 0.5, -1.\n" +
                           kSteel +
                           "*TIE, NAME=T1, POSITION TOLERANCE=0.05, ADJUST=NO\nTOPFACE, BOTFACE\n"
                           "*COUPLING, REF NODE=100, SURFACE=TOPFACE, CONSTRAINT NAME=C1\n"
                           "*KINEMATIC\n1, 2\n3\n*COUPLING, REF NODE=101, SURFACE=BOTFACE, "
                           "CONSTRAINT NAME=C2\n*DISTRIBUTING\n4, 6\n*MPC\nBEAM, 1, 7\nSTRAIGHT, "
                           "1, 2, 3,\n4\n*PRE-TENSION SECTION, SURFACE=TOPFACE, NODE=100\n0., 0., "
                           "2.\n*STEP\n*STATIC\n*CLOAD\n101, 4, 2.5\n*END STEP\n";
  const Model m = read("kc_constraints.inp", deck);
  ASSERT_EQ(m.ties.size(), 1u);
  EXPECT_EQ(m.ties[0].slave, "TOPFACE");
  EXPECT_EQ(*m.ties[0].position_tolerance, 0.05);
  EXPECT_FALSE(m.ties[0].adjust);
  ASSERT_EQ(m.couplings.size(), 2u);
  EXPECT_EQ(m.couplings[0].kind, Coupling::Kind::Kinematic);
  EXPECT_EQ(m.couplings[0].dofs, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(m.couplings[1].kind, Coupling::Kind::Distributing);
  EXPECT_EQ(m.couplings[1].dofs, (std::vector<int>{4, 5, 6}));
  ASSERT_EQ(m.mpcs.size(), 2u);
  EXPECT_EQ(m.mpcs[0].type, Mpc::Type::Beam);
  EXPECT_EQ(m.mpcs[1].nodes.size(), 4u);  // continued on the next line
  ASSERT_EQ(m.pretension_sections.size(), 1u);
  EXPECT_EQ(*m.pretension_sections[0].normal, (Vec3{0.0, 0.0, 1.0}));
  EXPECT_EQ(m.steps[0].cloads[0].dof, 4);  // a moment on the distributing reference node
  const Model back = round_trip(m, "kc_constraints_back.inp");
  EXPECT_EQ(back.ties.size(), 1u);
  EXPECT_EQ(back.couplings[0].dofs, m.couplings[0].dofs);
  EXPECT_EQ(back.mpcs[1].nodes, m.mpcs[1].nodes);
  EXPECT_EQ(back.pretension_sections.size(), 1u);
}

TEST(KeywordCoverage, ConstraintErrors) {
  const std::string base = std::string(kBlock) + "*NODE\n100, 0.5, 0.5, 2.\n" + kSteel;
  expect_error("kc_tie_multistage.inp",
               base + "*TIE, NAME=T, MULTISTAGE\nTOPFACE, BOTFACE\n" + kStep, "*TIE",
               "MULTISTAGE is not supported");
  expect_error("kc_tie_surface.inp", base + "*TIE, NAME=T\nTOPFACE, NOPE\n" + kStep, "*TIE",
               "surface NOPE, which is not defined");
  expect_error("kc_coupling_alone.inp",
               base + "*COUPLING, REF NODE=100, SURFACE=TOPFACE, CONSTRAINT NAME=C\n*STEP\n" +
                   "*STATIC\n*END STEP\n",
               "*STEP", "must be followed directly by *KINEMATIC");
  expect_error("kc_kinematic_dof.inp",
               base +
                   "*COUPLING, REF NODE=100, SURFACE=TOPFACE, CONSTRAINT NAME=C\n"
                   "*KINEMATIC\n1, 6\n" +
                   kStep,
               "1, 6", "out of range 1..3");
  expect_error("kc_mpc_type.inp", base + "*MPC\nMEANROT, 1, 2, 3\n" + kStep, "MEANROT",
               "'MEANROT' is not supported");
  expect_error("kc_mpc_count.inp", base + "*MPC\nBEAM, 1, 2, 3\n" + kStep, "BEAM, 1", "exactly 2");
  expect_error("kc_pretension_beam.inp",
               base + "*PRE-TENSION SECTION, ELEMENT=1, NODE=100\n" + kStep, "*PRE-TENSION",
               "ELEMENT= (a beam bolt) is not supported");
  // A moment on a node without rotations is read and refused by the solver, which knows the
  // node's elements (tests/inputs/bad: solver_rotation_on_solid.inp).
}

TEST(KeywordCoverage, EquationWithNodeSets) {
  const std::string deck = std::string(kBlock) + "*NODE\n100, 0.5, 0.5, 2.\n" + kSteel +
                           "*EQUATION\n2\nTOP, 3, 1., 100, 3, -1.\n3\nBOTTOM, 1, 1., TOP, 1, "
                           "-0.5, 100, 1, -0.5\n" +
                           kStep;
  const Model m = read("kc_equation_sets.inp", deck);
  // Four copies of the first (node 100 repeats), four of the second (nodes matched by id).
  ASSERT_EQ(m.equations.size(), 8u);
  EXPECT_EQ(m.node_ids[m.equations[0].terms[0].node], 5);
  EXPECT_EQ(m.node_ids[m.equations[3].terms[0].node], 8);
  EXPECT_EQ(m.node_ids[m.equations[3].terms[1].node], 100);
  EXPECT_EQ(m.node_ids[m.equations[6].terms[0].node], 3);
  EXPECT_EQ(m.node_ids[m.equations[6].terms[1].node], 7);
  expect_error("kc_equation_sizes.inp",
               std::string(kBlock) + kSteel +
                   "*NSET, NSET=TWO\n1, 2\n*EQUATION\n2\nTOP, 1, 1., "
                   "TWO, 1, -1.\n" +
                   kStep,
               "2\nTOP", "hold 4 and 2 nodes");
}

TEST(KeywordCoverage, OutputOptions) {
  const std::string deck = std::string(kBlock) + kSteel +
                           "*STEP\n*STATIC\n*NODE PRINT, NSET=TOP, GLOBAL=YES, FREQUENCY=3, "
                           "TOTALS=ONLY\nRF\n*EL PRINT, ELSET=BLOCK, TOTALS=YES, GLOBAL=NO\nENER, "
                           "ELSE, EVOL, CENT\n*EL FILE\nS, NOE, THE, ERR\n*SECTION PRINT, "
                           "SURFACE=TOPFACE, NAME=SP1\nSOF, SOM\n*END STEP\n";
  const Model m = read("kc_outputs.inp", deck);
  const std::vector<OutputRequest>& o = m.steps[0].outputs;
  ASSERT_EQ(o.size(), 4u);
  EXPECT_TRUE(o[0].totals_only);
  EXPECT_TRUE(*o[0].global);
  EXPECT_EQ(*o[0].frequency, 3);
  EXPECT_FALSE(*o[1].global);
  EXPECT_EQ(o[1].vars, (std::vector<std::string>{"ENER", "ELSE", "EVOL", "CENT"}));
  EXPECT_EQ(o[3].kind, OutputRequest::Kind::SectionPrint);
  EXPECT_EQ(o[3].set, "TOPFACE");
  const Model back = round_trip(m, "kc_outputs_back.inp");
  EXPECT_TRUE(back.steps[0].outputs[0].totals_only);
  EXPECT_EQ(back.steps[0].outputs[3].name, "SP1");
  const std::string base = std::string(kBlock) + kSteel + "*STEP\n*STATIC\n";
  expect_error("kc_section_nodes.inp",
               base + "*SECTION PRINT, SURFACE=NOPE, NAME=X\nSOF\n*END STEP\n", "*SECTION PRINT",
               "SURFACE=NOPE of *SECTION PRINT is not defined");
  expect_error("kc_totals.inp", base + "*NODE PRINT, NSET=TOP, TOTALS=SOME\nRF\n*END STEP\n",
               "*NODE PRINT", "expected YES, NO or ONLY");
  expect_error("kc_noe_alone.inp", base + "*EL FILE\nNOE\n*END STEP\n", "*EL FILE", "follows no S");
  expect_error("kc_err_print.inp", base + "*EL PRINT, ELSET=BLOCK\nERR\n*END STEP\n", "ERR\n",
               "'ERR' is not supported by *EL PRINT");
}

}  // namespace
}  // namespace styk
