// Layout of the .dat report against a hand-written expectation in CalculiX's format (header text,
// blank lines, I10 ids, I3 integration points, 1P E13.6 values, total-force line), as observed in
// ccx 2.20 output (tests/unit/io/data/ccx_two_steps.dat).
#include <gtest/gtest.h>

#include <sstream>

#include "styk/io/dat_reader.hpp"
#include "styk/io/dat_writer.hpp"

namespace styk {
namespace {

// Three nodes added out of id order (rows must come out sorted by id), one element with two
// integration points.
Model tiny_model() {
  Model model;
  model.add_node(2, {1, 0, 0}, {});
  model.add_node(1, {0, 0, 0}, {});
  model.add_node(1234567, {0, 1, 0}, {});
  model.add_element(7, "CPS3", {1, 0, 2}, {});
  model.nsets["NALL"] = NodeSet{"NALL", {0, 1, 2}, {}};
  Step step;
  OutputRequest nodes;
  nodes.kind = OutputRequest::Kind::NodePrint;
  nodes.set = "NALL";
  nodes.vars = {"U", "RF"};
  nodes.totals = true;
  OutputRequest elements;
  elements.kind = OutputRequest::Kind::ElementPrint;
  elements.vars = {"S", "E"};  // no ELSET: the whole model, printed as set ALL
  OutputRequest file_output;   // *NODE FILE goes to the results file, not the .dat
  file_output.kind = OutputRequest::Kind::NodeFile;
  file_output.vars = {"U"};
  step.outputs = {nodes, elements, file_output};
  model.steps.push_back(step);
  return model;
}

Results tiny_results() {
  IncrementResult inc;
  inc.step = 1;
  inc.increment = 1;
  inc.step_time = 0.5;
  inc.total_time = 0.5;
  inc.U = {{1e-3, -2.5e-4, 0.0}, {0.0, 0.0, 0.0}, {-0.125, 3.0, 1e5}};
  inc.RF = {{10.0, 0.0, -5.0}, {-10.0, 2.5, 0.0}, {0.0, 0.0, 0.0}};
  inc.ip_offset = {0, 2};
  inc.S = {{1, 2, 3, 4, 5, 6}, {-1.5e-3, 0.0, 123456.789, -0.5, 1e-120, 7.0}};
  inc.E = {{1e-3, -3e-4, 0.0, 2e-5, 0.0, 0.0}, {0.0, 0.0, 0.0, 0.0, 0.0, -1e-6}};
  Results results;
  results.increments.push_back(inc);
  return results;
}

TEST(DatWriter, MatchesCalculixLayout) {
  std::ostringstream out;
  write_dat(out, tiny_model(), tiny_results());
  const std::string expected =
      "\n"
      " displacements (vx,vy,vz) for set NALL and time  0.5000000E+00\n"
      "\n"
      "         1  0.000000E+00  0.000000E+00  0.000000E+00\n"
      "         2  1.000000E-03 -2.500000E-04  0.000000E+00\n"
      "   1234567 -1.250000E-01  3.000000E+00  1.000000E+05\n"
      "\n"
      " forces (fx,fy,fz) for set NALL and time  0.5000000E+00\n"
      "\n"
      "         1 -1.000000E+01  2.500000E+00  0.000000E+00\n"
      "         2  1.000000E+01  0.000000E+00 -5.000000E+00\n"
      "   1234567  0.000000E+00  0.000000E+00  0.000000E+00\n"
      "\n"
      " total force (fx,fy,fz) for set NALL and time  0.5000000E+00\n"
      "\n"
      "        0.000000E+00  2.500000E+00 -5.000000E+00\n"
      "\n"
      " stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set ALL and time  0.5000000E+00\n"
      "\n"
      "         7   1  1.000000E+00  2.000000E+00  3.000000E+00  4.000000E+00  5.000000E+00  "
      "6.000000E+00\n"
      "         7   2 -1.500000E-03  0.000000E+00  1.234568E+05 -5.000000E-01  1.000000-120  "
      "7.000000E+00\n"
      "\n"
      " strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz) for set ALL and time  0.5000000E+00\n"
      "\n"
      "         7   1  1.000000E-03 -3.000000E-04  0.000000E+00  2.000000E-05  0.000000E+00  "
      "0.000000E+00\n"
      "         7   2  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00 "
      "-1.000000E-06\n";
  EXPECT_EQ(out.str(), expected);
}

// A node named by a *TRANSFORM prints its local components with a trailing " L" (ccx 2.20 does,
// checked live in tests/cli/ccx_crosscheck_test.cpp); the total force stays a sum of global
// components. Node 2 at (1, 0, 0) in a system with local x = global y, local y = -global x.
TEST(DatWriter, TransformedNodesPrintLocalComponentsMarkedL) {
  Model model = tiny_model();
  model.nsets["TURNED"] = NodeSet{"TURNED", {0}, {}};
  model.transforms.push_back(
      Transform{"TURNED", {CoordinateSystem::Rectangular, {0, 1, 0}, {-1, 0, 0}}, {}});
  std::ostringstream out;
  write_dat(out, model, tiny_results());
  const std::string text = out.str();
  EXPECT_NE(text.find("         2 -2.500000E-04 -1.000000E-03  0.000000E+00 L\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("         2  0.000000E+00 -1.000000E+01 -5.000000E+00 L\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("         1  0.000000E+00  0.000000E+00  0.000000E+00\n"), std::string::npos);
  EXPECT_NE(text.find("        0.000000E+00  2.500000E+00 -5.000000E+00\n"), std::string::npos);
  // The reader takes the marker back.
  std::istringstream in(text);
  const std::vector<DatBlock> blocks = parse_dat_blocks(in);
  ASSERT_GE(blocks.size(), 2u);
  for (const DatRow& row : blocks[0].rows) EXPECT_EQ(row.local, row.id == 2) << row.id;
  EXPECT_DOUBLE_EQ(blocks[0].rows[1].values[0], -2.5e-4);
}

TEST(DatWriter, EveryIncrementPrintsItsStepsRequestsAtTotalTime) {
  Model model = tiny_model();
  model.steps[0].outputs.resize(1);
  model.steps[0].outputs[0].vars = {"U"};
  Step second;
  second.outputs = {model.steps[0].outputs[0]};
  second.outputs[0].vars = {"RF"};
  second.outputs[0].totals = false;
  model.steps.push_back(second);
  Results results = tiny_results();
  results.increments.push_back(results.increments[0]);
  results.increments[1].step = 2;
  results.increments[1].total_time = 1.5;  // ccx prints the total time, not the step time
  std::ostringstream out;
  write_dat(out, model, results);
  const std::string text = out.str();
  EXPECT_NE(text.find(" displacements (vx,vy,vz) for set NALL and time  0.5000000E+00\n"),
            std::string::npos);
  EXPECT_NE(text.find(" forces (fx,fy,fz) for set NALL and time  0.1500000E+01\n"),
            std::string::npos);
  EXPECT_EQ(text.find("total force"), std::string::npos);
  EXPECT_EQ(text.find("stresses"), std::string::npos);
}

TEST(DatWriter, UnknownSetIsAnInputErrorAtTheRequest) {
  Model model = tiny_model();
  model.steps[0].outputs[0].set = "NOPE";
  model.steps[0].outputs[0].where = SourceLoc{"deck.inp", 12};
  std::ostringstream out;
  try {
    write_dat(out, model, tiny_results());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "deck.inp:12: *NODE PRINT: node set NOPE is not defined");
  }
}

TEST(DatWriter, UnprintableVariableIsAnInputError) {
  Model model = tiny_model();
  model.steps[0].outputs[1].vars = {"S", "PEEQ"};
  model.steps[0].outputs[1].where = SourceLoc{"deck.inp", 20};
  std::ostringstream out;
  try {
    write_dat(out, model, tiny_results());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.inp:20: *EL PRINT: variable PEEQ"),
              std::string::npos)
        << e.what();
  }
}

TEST(DatWriter, MissingFieldIsReported) {
  Results results = tiny_results();
  results.increments[0].S.clear();
  std::ostringstream out;
  EXPECT_THROW(write_dat(out, tiny_model(), results), std::runtime_error);
}

// *CONTACT PRINT of a step with *PRESSURE PENETRATION: after the pair totals, the fluid pressure,
// the penetrated share and the leak flag, then the penetrated slave nodes (fluid pressure > 0)
// with their fluid pressure, sorted by id (docs/results.md).
TEST(DatWriter, PressurePenetrationBlockFollowsTheContactPrint) {
  Model model = tiny_model();
  ContactPair pair;
  pair.slave = "S";
  pair.master = "M";
  model.contact_pairs.push_back(pair);
  OutputRequest contact;
  contact.kind = OutputRequest::Kind::ContactPrint;
  contact.vars = {"CSTATUS"};
  model.steps[0].outputs = {contact};
  Results results = tiny_results();
  IncrementResult& inc = results.increments[0];
  for (int node : {2, 0, 1}) {
    ContactNodeResult c;
    c.node = node;
    c.fluid_pressure = node == 1 ? 0.0 : 16.0;
    c.status = node == 1 ? ContactStatus::Stick : ContactStatus::Open;
    inc.contact.push_back(c);
  }
  inc.contact_pairs.resize(1);
  PenetrationResult pr;
  pr.pressure = 16.0;
  pr.penetrated = 2;
  pr.nodes = 3;
  inc.penetrations.push_back(pr);
  std::ostringstream out;
  write_dat(out, model, results);
  const std::string text = out.str();
  const std::string expected =
      "\n pressure penetration (slave node,fluid pressure) of pair S/M and time 0.5000000E+00\n\n"
      "  fluid pressure  1.600000E+01, 2 of 3 slave nodes penetrated, not leaking\n"
      "         2  1.600000E+01\n"
      "   1234567  1.600000E+01\n";
  EXPECT_NE(text.find(expected), std::string::npos) << text;
}

}  // namespace
}  // namespace styk
