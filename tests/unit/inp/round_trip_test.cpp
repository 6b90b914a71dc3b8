// write_inp: read -> write -> read gives an equivalent model, and ccx accepts what it writes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "support/ccx_runner.hpp"

namespace styk {
namespace {

using test::fake_registry;
using test::input_path;
using test::write_deck;

// Equivalence: everything but source locations and the source path.
void expect_equivalent(const Model& a, const Model& b) {
  EXPECT_EQ(a.heading, b.heading);
  EXPECT_EQ(a.node_ids, b.node_ids);
  EXPECT_EQ(a.coords, b.coords);
  EXPECT_EQ(a.connectivity, b.connectivity);
  ASSERT_EQ(a.element_count(), b.element_count());
  for (int e = 0; e < a.element_count(); ++e) {
    EXPECT_EQ(a.elements[e].id, b.elements[e].id);
    EXPECT_EQ(a.elements[e].type, b.elements[e].type);
    EXPECT_EQ(a.elements[e].first_node, b.elements[e].first_node);
    EXPECT_EQ(a.elements[e].node_count, b.elements[e].node_count);
    EXPECT_EQ(a.elements[e].section, b.elements[e].section);
  }
  ASSERT_EQ(a.nsets.size(), b.nsets.size());
  for (const auto& [name, set] : a.nsets) {
    ASSERT_NE(b.find_nset(name), nullptr) << name;
    EXPECT_EQ(set.nodes, b.find_nset(name)->nodes) << name;
  }
  ASSERT_EQ(a.elsets.size(), b.elsets.size());
  for (const auto& [name, set] : a.elsets) {
    ASSERT_NE(b.find_elset(name), nullptr) << name;
    EXPECT_EQ(set.elements, b.find_elset(name)->elements) << name;
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    EXPECT_EQ(a.materials[i].name, b.materials[i].name);
    EXPECT_EQ(a.materials[i].young, b.materials[i].young);
    EXPECT_EQ(a.materials[i].poisson, b.materials[i].poisson);
    EXPECT_EQ(a.materials[i].density, b.materials[i].density);
    EXPECT_EQ(a.materials[i].expansion, b.materials[i].expansion);
    EXPECT_EQ(a.materials[i].expansion_reference, b.materials[i].expansion_reference);
  }
  ASSERT_EQ(a.sections.size(), b.sections.size());
  for (std::size_t i = 0; i < a.sections.size(); ++i) {
    EXPECT_EQ(a.sections[i].elset, b.sections[i].elset);
    EXPECT_EQ(a.sections[i].material, b.sections[i].material);
    EXPECT_EQ(a.sections[i].material_index, b.sections[i].material_index);
    EXPECT_EQ(a.sections[i].thickness, b.sections[i].thickness);
  }
  const auto same_boundaries = [](const std::vector<Boundary>& x, const std::vector<Boundary>& y) {
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      EXPECT_EQ(x[i].node, y[i].node);
      EXPECT_EQ(x[i].dof, y[i].dof);
      EXPECT_EQ(x[i].value, y[i].value);
    }
  };
  same_boundaries(a.boundaries, b.boundaries);
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t s = 0; s < a.steps.size(); ++s) {
    const Step& x = a.steps[s];
    const Step& y = b.steps[s];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.has_procedure, y.has_procedure);
    EXPECT_EQ(x.procedure.initial_increment, y.procedure.initial_increment);
    EXPECT_EQ(x.procedure.total_time, y.procedure.total_time);
    EXPECT_EQ(x.procedure.solver, y.procedure.solver);
    same_boundaries(x.boundaries, y.boundaries);
    EXPECT_EQ(x.boundary_op_new, y.boundary_op_new);
    EXPECT_EQ(x.cload_op_new, y.cload_op_new);
    EXPECT_EQ(x.dload_op_new, y.dload_op_new);
    ASSERT_EQ(x.cloads.size(), y.cloads.size());
    for (std::size_t i = 0; i < x.cloads.size(); ++i) {
      EXPECT_EQ(x.cloads[i].node, y.cloads[i].node);
      EXPECT_EQ(x.cloads[i].dof, y.cloads[i].dof);
      EXPECT_EQ(x.cloads[i].value, y.cloads[i].value);
    }
    ASSERT_EQ(x.dloads.size(), y.dloads.size());
    for (std::size_t i = 0; i < x.dloads.size(); ++i) {
      EXPECT_EQ(x.dloads[i].element, y.dloads[i].element);
      EXPECT_EQ(x.dloads[i].face, y.dloads[i].face);
      EXPECT_EQ(x.dloads[i].magnitude, y.dloads[i].magnitude);
    }
    ASSERT_EQ(x.outputs.size(), y.outputs.size());
    for (std::size_t i = 0; i < x.outputs.size(); ++i) {
      EXPECT_EQ(x.outputs[i].kind, y.outputs[i].kind);
      EXPECT_EQ(x.outputs[i].set, y.outputs[i].set);
      EXPECT_EQ(x.outputs[i].vars, y.outputs[i].vars);
      EXPECT_EQ(x.outputs[i].totals, y.outputs[i].totals);
    }
  }
}

std::string written(const Model& m) {
  std::ostringstream out;
  write_inp(m, out);
  return out.str();
}

class RoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, ReadWriteReadIsEquivalentAndWritingIsStable) {
  const ElementRegistry registry = fake_registry();
  const Model original = read_inp(input_path("good/" + GetParam()), registry);
  const std::string text = written(original);
  const Model again = read_inp(write_deck("round_trip/" + GetParam(), text), registry);
  expect_equivalent(original, again);
  // Writing the re-read model gives the same text, apart from the first comment line that names
  // the source file.
  const std::string rewritten = written(again);
  EXPECT_EQ(rewritten.substr(rewritten.find('\n')), text.substr(text.find('\n')));
}

INSTANTIATE_TEST_SUITE_P(GoodDecks, RoundTrip,
                         ::testing::Values("block_c3d8.inp", "block_c3d20.inp",
                                           "include_block.inp"));

// Everything the writer knows how to write, including awkward numbers.
const char* const kEverything = R"(*HEADING
first heading line, with a comma
second heading line
*NODE
10, 0., 0., 0.
20, 0.1, 0., 0.
30, 0.1, 0.30000000000000004, 0.
40, 0., 1e-300, 0.
50, 0., 0., 1.7976931348623157e308
60, 1., 0., 1.
70, 1., 1., 1.
80, -0., 1., 1.
*ELEMENT, TYPE=C3D8
7, 10, 20, 30, 40, 50, 60, 70, 80
*ELSET, ELSET=PLATE
7
*NSET, NSET=EMPTY
*MATERIAL, NAME=AL
*ELASTIC
70000., 0.33
*EXPANSION, ZERO=20.
2.3e-5
*MATERIAL, NAME=UNUSED
*ELASTIC
1., 0.
*DENSITY
2.7e-9
*SOLID SECTION, ELSET=PLATE, MATERIAL=AL
0.125
*BOUNDARY
10, 1, 3, 0.
*STEP, NAME=first
*STATIC, SOLVER=PARDISO
0.25, 2.
*CLOAD
70, 2, -3.5
*DLOAD
7, P3, 1.25
*NODE PRINT, NSET=EMPTY, TOTALS=YES
RF
*EL PRINT, ELSET=PLATE
E
*END STEP
*STEP
*STATIC, SOLVER=AMG
*BOUNDARY, OP=NEW
*CLOAD, OP=NEW
*DLOAD, OP=NEW
*NODE FILE
RF, U
*EL FILE
S
*END STEP
)";

TEST(RoundTripAll, EveryWrittenFeatureReadsBack) {
  const ElementRegistry registry = fake_registry();
  const Model original = read_inp(write_deck("everything.inp", kEverything), registry);
  ASSERT_TRUE(original.sections[0].thickness.has_value());
  ASSERT_TRUE(original.steps[1].boundary_op_new);
  // DBL_MAX's shortest exact form has 23 characters, more than CalculiX reads in a field: it is
  // written as the nearest 20-character number (docs/input.md), every other value exactly.
  Model expected = original;
  expected.coords[4][2] = 1.7976931348623e308;
  const Model again = read_inp(write_deck("everything_written.inp", written(original)), registry);
  expect_equivalent(expected, again);
  EXPECT_EQ(again.coords[2][1], 0.30000000000000004);
  EXPECT_NEAR(again.coords[4][2] / 1.7976931348623157e308, 1.0, 5e-13);
}

// CalculiX refuses a number of more than 20 characters (ccx 2.20: "*ERROR reading *CLOAD"), so no
// field of a written deck is longer; a value whose exact form is longer is rounded to fit, at most
// 5e-13 relative (13 significant digits for 3-digit exponents, 14 otherwise).
TEST(RoundTripAll, NoWrittenNumberIsLongerThanCalculixReads) {
  const ElementRegistry registry = fake_registry();
  Model model = read_inp(write_deck("long_numbers.inp", kEverything), registry);
  const std::vector<double> values{-0.0070710678118654755,
                                   1.2246467991473532e-16,
                                   -1.2345678901234567e-123,
                                   1.0 / 3.0,
                                   2.0 / 3.0e7,
                                   0.30000000000000004};
  for (std::size_t i = 0; i < values.size() && i < model.coords.size(); ++i)
    model.coords[i][0] = values[i];
  const std::string text = written(model);
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("**", 0) == 0 || line.rfind("*", 0) == 0) continue;  // comments, keywords
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) {
      const auto first = field.find_first_not_of(' ');
      EXPECT_LE(first == std::string::npos ? 0 : field.size() - first, 20u) << line;
    }
  }
  const Model again = read_inp(write_deck("long_numbers_written.inp", text), registry);
  for (std::size_t i = 0; i < values.size() && i < model.coords.size(); ++i)
    EXPECT_NEAR(again.coords[i][0], values[i], 5e-13 * std::abs(values[i])) << i;
  EXPECT_EQ(again.coords[5][0], 0.30000000000000004);  // 19 characters: exact
  EXPECT_EQ(again.coords[3][0], 1.0 / 3.0);            // 0.3333333333333333: exact
}

// ccx must accept what write_inp produces from a standard-element deck.
TEST(RoundTripCcx, CalculixRunsTheWrittenDeck) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const ElementRegistry registry = fake_registry();
  Model original = read_inp(input_path("good/block_c3d20.inp"), registry);
  // A pressure whose exact form has 22 characters ("1.2345678901234567e-05"): ccx refuses the
  // card unless the writer shortens it.
  ASSERT_FALSE(original.steps.at(0).dloads.empty());
  original.steps[0].dloads[0].magnitude = 1.2345678901234567e-05;
  const std::string path = write_deck("ccx_run/written_c3d20.inp", written(original));
  const std::string dir = (test::scratch_dir() / "ccx_run").string();
  const test::CcxRun run = test::run_ccx(dir, "written_c3d20");
  ASSERT_EQ(run.exit_code, 0) << run.log;
  EXPECT_EQ(run.log.find("*ERROR"), std::string::npos) << run.log;
  std::ifstream dat(dir + "/written_c3d20.dat");
  const std::string results((std::istreambuf_iterator<char>(dat)),
                            std::istreambuf_iterator<char>());
  EXPECT_NE(results.find("forces (fx,fy,fz) for set FIXED"), std::string::npos) << results;
}

}  // namespace
}  // namespace styk
