// *EL PRINT, POSITION= (Abaqus spelling; docs/input.md, docs/results.md): read from a deck, solved,
// printed to the .dat report and read back. Two C3D8 cubes [0,2] x [0,1] x [0,1] in uniform
// tension s33 = 100 (consistent top loads 25/50/25 per node row, statically determinate
// supports), so every centroid and every averaged node carries (0, 0, 100, 0, 0, 0).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/io/dat_writer.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

std::string deck(const std::string& el_print_lines) {
  return R"(*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
9, 2, 0, 0
10, 2, 1, 0
11, 2, 0, 1
12, 2, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 2, 9, 10, 3, 6, 11, 12, 7
*ELSET, ELSET=RIGHT
2
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
1, 1, 3
2, 3, 3
3, 3, 3
4, 3, 3
9, 2, 3
10, 3, 3
*CLOAD
5, 3, 25.
8, 3, 25.
6, 3, 50.
7, 3, 50.
11, 3, 25.
12, 3, 25.
)" + el_print_lines +
         "*END STEP\n";
}

class ElPrintPosition : public ::testing::Test {
 protected:
  void SetUp() override { register_builtin_elements(registry_); }

  Model read(const std::string& el_print_lines, const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(STYK_BINARY_DIR) / "tests" / "unit" / "recovery" / "scratch";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << deck(el_print_lines);
    return read_inp(path, registry_);
  }

  std::string dat(const Model& model) {
    const Results results = run_static_analysis(model, registry_, SolveOptions{}, nullptr, nullptr);
    std::ostringstream out;
    write_dat(out, model, results);
    return out.str();
  }

  ElementRegistry registry_;
};

TEST_F(ElPrintPosition, ParameterIsRead) {
  using P = OutputRequest::Position;
  const Model model = read(
      "*EL PRINT, ELSET=EALL\nS\n*EL PRINT, ELSET=EALL, POSITION=CENTROIDAL\nS\n"
      "*EL PRINT, POSITION=averaged at nodes\nE\n"
      "*EL PRINT, POSITION=INTEGRATION POINTS\nS\n",
      "read.inp");
  const std::vector<OutputRequest>& outputs = model.steps.at(0).outputs;
  ASSERT_EQ(outputs.size(), 4u);
  EXPECT_EQ(outputs[0].position, P::IntegrationPoints);
  EXPECT_EQ(outputs[1].position, P::Centroidal);
  EXPECT_EQ(outputs[2].position, P::AveragedAtNodes);
  EXPECT_EQ(outputs[3].position, P::IntegrationPoints);
}

TEST_F(ElPrintPosition, UnknownPositionNamesTheLine) {
  try {
    read("*EL PRINT, ELSET=EALL, POSITION=NODES\nS\n", "bad.inp");
    FAIL() << "POSITION=NODES accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad.inp:39:"), std::string::npos) << message;
    EXPECT_NE(message.find("POSITION=NODES"), std::string::npos) << message;
    EXPECT_NE(message.find("CENTROIDAL"), std::string::npos) << message;
  }
  EXPECT_THROW(read("*NODE PRINT, NSET=NALL, POSITION=CENTROIDAL\nU\n", "bad2.inp"), InputError);
}

TEST_F(ElPrintPosition, CentroidRowsHaveNoIntegrationPointColumn) {
  const std::string text =
      dat(read("*EL PRINT, ELSET=RIGHT, POSITION=CENTROIDAL\nS, E\n", "c.inp"));
  EXPECT_NE(text.find("\n stresses at centroids (elem,sxx,syy,szz,sxy,sxz,syz) for set RIGHT and "
                      "time  0.1000000E+01\n\n         2 "),
            std::string::npos)
      << text;
  std::istringstream in(text);
  const std::vector<DatBlock> blocks = parse_dat_blocks(in);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[1].what, "strains at centroids (elem,exx,eyy,ezz,exy,exz,eyz)");
  ASSERT_EQ(blocks[0].rows.size(), 1u);
  const DatRow& row = blocks[0].rows[0];
  EXPECT_EQ(row.id, 2);
  EXPECT_EQ(row.integration_point, 0);
  ASSERT_EQ(row.values.size(), 6u);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(row.values[k], k == 2 ? 100.0 : 0.0, 1e-9) << k;
  // E13.6 keeps 7 significant digits.
  EXPECT_NEAR(blocks[1].rows.at(0).values[2], 100.0 / 210000.0, 1e-6 * 100.0 / 210000.0);
}

TEST_F(ElPrintPosition, AveragedRowsListTheNodesOfTheSet) {
  const std::string text =
      dat(read("*EL PRINT, ELSET=RIGHT, POSITION=AVERAGED AT NODES\nS\n", "n.inp"));
  std::istringstream in(text);
  const std::vector<DatBlock> blocks = parse_dat_blocks(in);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].what, "stresses averaged at nodes (node,sxx,syy,szz,sxy,sxz,syz)");
  EXPECT_EQ(blocks[0].set, "RIGHT");
  const std::vector<Id> expected_ids = {2, 3, 6, 7, 9, 10, 11, 12};  // element 2's, sorted
  ASSERT_EQ(blocks[0].rows.size(), expected_ids.size());
  for (std::size_t i = 0; i < expected_ids.size(); ++i) {
    EXPECT_EQ(blocks[0].rows[i].id, expected_ids[i]);
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(blocks[0].rows[i].values.at(k), k == 2 ? 100.0 : 0.0, 1e-9) << i << " " << k;
  }
}

TEST_F(ElPrintPosition, IntegrationPointsStayTheDefault) {
  const std::string plain = dat(read("*EL PRINT, ELSET=RIGHT\nS\n", "p.inp"));
  const std::string explicit_position =
      dat(read("*EL PRINT, ELSET=RIGHT, POSITION=INTEGRATION POINTS\nS\n", "q.inp"));
  EXPECT_EQ(plain, explicit_position);
  std::istringstream in(plain);
  const std::vector<DatBlock> blocks = parse_dat_blocks(in);
  ASSERT_EQ(blocks.at(0).rows.size(), 8u);
  EXPECT_EQ(blocks[0].rows[7].integration_point, 8);
}

}  // namespace
}  // namespace styk
