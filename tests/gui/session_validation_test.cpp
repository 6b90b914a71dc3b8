// The model-creation dialogs' checks: bad input is refused with a message naming the problem,
// and what passes builds the mesh the dialog promised.
#include <gtest/gtest.h>

#include <algorithm>

#include "refusal.hpp"
#include "session/validation.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/element_setup.hpp"

namespace styk::gui {
namespace {

using test::refusal;

class ValidationTest : public ::testing::Test {
 protected:
  ValidationTest() {
    setup_element_registry(registry, libraries, {build_plugin_directory()});
    Material m;
    m.name = "STEEL";
    m.young = 210000.0;
    m.poisson = 0.3;
    model.materials.push_back(m);
  }
  PluginLibraries libraries;
  ElementRegistry registry;
  Model model;
};

TEST_F(ValidationTest, TextFieldsMustBeNumbers) {
  EXPECT_DOUBLE_EQ(parse_real(" 2.5e3 ", "E"), 2500.0);
  EXPECT_EQ(parse_integer("12", "n"), 12);
  EXPECT_EQ(refusal([] { parse_real("abc", "Young's modulus"); }),
            "Young's modulus: 'abc' is not a number");
  EXPECT_EQ(refusal([] { parse_integer("1.5", "divisions x"); }),
            "divisions x: '1.5' is not a whole number");
  EXPECT_EQ(refusal([] { parse_real("", "x"); }), "x: '' is not a number");
}

TEST_F(ValidationTest, BlockDialogRefusesBadInput) {
  BlockInput in;
  in.divisions = {-2, 1, 1};
  EXPECT_EQ(refusal([&] { check_block(in, model, registry); }),
            "divisions along x must be at least 1, not -2");
  in.divisions = {2, 2, 2};
  in.size = {1, 0, 1};
  EXPECT_EQ(refusal([&] { check_block(in, model, registry); }), "size along y must be > 0");
  in.size = {1, 1, 1};
  in.grading = {1, 1, -4};
  EXPECT_EQ(refusal([&] { check_block(in, model, registry); }),
            "grading along z must be > 0 (1 = uniform)");
  in.grading = {1, 1, 1};
  in.material = "UNOBTAINIUM";
  EXPECT_EQ(refusal([&] { check_block(in, model, registry); }),
            "no material UNOBTAINIUM in the model");
  in.material = "steel";
  in.type = "C3D4";
  EXPECT_NE(refusal([&] { check_block(in, model, registry); }).find("cannot be meshed here"),
            std::string::npos);
  in.type = "C3D20";
  in.name = "9LIVES";
  EXPECT_EQ(refusal([&] { check_block(in, model, registry); }),
            "the block's element set name '9LIVES' must start with a letter");
  in.name = "BLOCK";
  EXPECT_EQ(refusal([&] { check_block(in, model, registry); }), "(accepted)");
  // Left-handed corners: the mesher refuses, the dialog says so.
  in.use_corners = true;
  in.corners = {
      {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}};
  EXPECT_NE(refusal([&] { model_with_block(model, in, registry); }).find("the mesher refuses"),
            std::string::npos);
}

TEST_F(ValidationTest, BlockMeshesWithGradingSetsAndSection) {
  BlockInput in;
  in.name = "beam";
  in.size = {10, 2, 1};
  in.divisions = {5, 2, 1};
  in.grading = {4, 1, 1};
  in.type = "C3D8";
  in.material = "STEEL";
  const Model m = model_with_block(model, in, registry);
  EXPECT_EQ(m.element_count(), 10);
  EXPECT_EQ(m.node_count(), 6 * 3 * 2);
  ASSERT_TRUE(m.find_elset("BEAM"));
  EXPECT_EQ(m.find_nset("BEAM_XMIN")->nodes.size(), 6u);
  for (int n : m.find_nset("BEAM_XMAX")->nodes) EXPECT_NEAR(m.coords[n][0], 10.0, 1e-12);
  EXPECT_EQ(m.surfaces.at("BEAM_ZMAX").faces.size(), 10u);
  ASSERT_EQ(m.sections.size(), 1u);
  for (const Element& e : m.elements) EXPECT_EQ(e.section, 0);
  // Grading 4: the last element along x is 4 times the first. Node x positions along y = z = 0:
  std::vector<double> xs;
  for (int n = 0; n < m.node_count(); ++n)
    if (std::abs(m.coords[n][1]) < 1e-12 && std::abs(m.coords[n][2]) < 1e-12)
      xs.push_back(m.coords[n][0]);
  std::sort(xs.begin(), xs.end());
  ASSERT_EQ(xs.size(), 6u);
  EXPECT_NEAR((xs[5] - xs[4]) / (xs[1] - xs[0]), 4.0, 1e-9);
  // A second block: ids continue after the first, names must differ.
  EXPECT_EQ(refusal([&] { check_block(in, m, registry); }),
            "element set BEAM exists already; choose another name");
  in.name = "BEAM2";
  const Model two = model_with_block(m, in, registry);
  EXPECT_EQ(two.element_count(), 20);
  EXPECT_EQ(two.elements.back().id, 20);
  EXPECT_EQ(two.node_ids.back(), 2 * 36);
}

TEST_F(ValidationTest, AFaceLayerBecomesC3D21OrC3D28) {
  BlockInput in;
  in.divisions = {2, 2, 3};
  in.type = "C3D21";
  in.layer_side = "ZMAX";
  const Model m21 = model_with_block(model, in, registry);
  const long c3d21 = std::count_if(m21.elements.begin(), m21.elements.end(),
                                   [](const Element& e) { return e.type == "C3D21"; });
  EXPECT_EQ(c3d21, 4);  // the 2 x 2 elements on the top side
  EXPECT_EQ(m21.element_count(), 12);
  // The converted side's node set includes the new face-centre nodes.
  const NodeSet* top = m21.find_nset("BLOCK_ZMAX");
  ASSERT_TRUE(top);
  EXPECT_EQ(top->nodes.size(), 21u + 4u);  // 5x5 grid minus 4 C3D20 face centres + 4 new centres
  in.type = "C3D28";
  const Model m28 = model_with_block(model, in, registry);
  EXPECT_EQ(std::count_if(m28.elements.begin(), m28.elements.end(),
                          [](const Element& e) { return e.type == "C3D28"; }),
            4);
}

TEST_F(ValidationTest, LoadAndBoundaryDialogsRefuseBadInput) {
  BlockInput in;
  in.material = "STEEL";
  Model m = model_with_block(model, in, registry);
  m.nsets["EMPTY"] = NodeSet{"EMPTY", {}, {}};
  EXPECT_EQ(refusal([&] {
              boundary_command(m, {"EMPTY", 1, 3, 0.0, -1});
            }),
            "node set EMPTY is empty");
  EXPECT_EQ(refusal([&] {
              boundary_command(m, {"NOWHERE", 1, 3, 0.0, -1});
            }),
            "no node set NOWHERE in the model");
  EXPECT_EQ(refusal([&] {
              boundary_command(m, {"BLOCK_XMIN", 3, 1, 0.0, -1});
            }),
            "last dof must not be below the first dof");
  EXPECT_EQ(refusal([&] {
              boundary_command(m, {"BLOCK_XMIN", 0, 3, 0.0, -1});
            }),
            "first dof must be 1, 2, 3 (x, y, z), 4, 5, 6 (rotations), 11 (temperature) or 9 "
            "(electric potential), not 0");
  EXPECT_EQ(refusal([&] {
              cload_command(m, {"BLOCK_XMAX", 3, -1.0, false, 0});
            }),
            "the model has no step: add a step first");
  EXPECT_EQ(refusal([&] {
              step_command(m, {"S", 2.0, 1.0});
            }),
            "initial increment must be > 0 and not above the total time");
  step_command(m, {"S", 1.0, 1.0})->redo(m);
  EXPECT_EQ(refusal([&] { step_command(m, {"s", 1.0, 1.0}); }), "step s exists already");
  EXPECT_EQ(refusal([&] {
              cload_command(m, {"BLOCK_XMAX", 3, 0.0, false, 0});
            }),
            "a load of 0 does nothing; enter a value");
  EXPECT_EQ(refusal([&] {
              pressure_command(m, {"NOSURF", "", 1, 1.0, 0});
            }),
            "no surface NOSURF in the model");
  EXPECT_EQ(refusal([&] {
              pressure_command(m, {"", "BLOCK", 7, 1.0, 0});
            }),
            "face must be 1..6 (S1..S6)");
  EXPECT_EQ(refusal([&] {
              material_command(m, {"steel", 1.0, 0.3, 0.0});
            }),
            "material STEEL exists already");
  EXPECT_EQ(refusal([&] {
              material_command(m, {"X", 1.0, 0.5, 0.0});
            }),
            "Poisson's ratio must lie between -1 and 0.5 (exclusive)");
  EXPECT_EQ(refusal([&] { section_command(m, {"BLOCK", "STEEL"}); }).substr(0, 10), "element 1 ");

  // Split loads: the total is divided equally among the nodes.
  const std::size_t nodes = m.find_nset("BLOCK_XMAX")->nodes.size();
  cload_command(m, {"BLOCK_XMAX", 3, -90.0, true, 0})->redo(m);
  ASSERT_EQ(m.steps[0].cloads.size(), nodes);
  double total = 0;
  for (const ConcentratedLoad& l : m.steps[0].cloads) total += l.value;
  EXPECT_NEAR(total, -90.0, 1e-12);
  pressure_command(m, {"BLOCK_ZMAX", "", 1, 5.0, 0})->redo(m);
  EXPECT_EQ(m.steps[0].dloads.size(), 4u);  // default block: 4 x 1 x 1 elements
  EXPECT_EQ(m.steps[0].dloads[0].face, 2);  // the top of a block is S2
}

}  // namespace
}  // namespace styk::gui
