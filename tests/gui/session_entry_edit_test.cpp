// Editing every model tree entry without a display (styk-gui round 2): one group of boundary
// conditions, loads, pressures or temperatures (what one dialog made, found again from the
// per-node lists), sets (rename with the references following, members from the selection),
// equations and transforms — each one undoable command that undo reverts exactly, refused with
// the add dialogs' reasons. And the scalar-field models: heat / electric steps, conductivities,
// prescribed temperature (dof 11) and nodal heat flows, written as a deck the reader accepts.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>

#include "refusal.hpp"
#include "session/constraint_input.hpp"
#include "session/contact_input.hpp"
#include "session/entry_edits.hpp"
#include "session/load_groups.hpp"
#include "session/set_edits.hpp"
#include "session/thermal_input.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

namespace styk::gui {
namespace {

using test::refusal;

template <typename T>
bool same_entries(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto key = [](const auto& x) {
      if constexpr (std::is_same_v<T, DistributedLoad>)
        return std::make_tuple(x.element, x.face, x.magnitude);
      else if constexpr (std::is_same_v<T, NodalTemperature>)
        return std::make_tuple(x.node, 0, x.value);
      else
        return std::make_tuple(x.node, x.dof, x.value);
    };
    if (key(a[i]) != key(b[i])) return false;
  }
  return true;
}

// A 4 x 2 x 2 C3D8 block with a section and two static steps.
class EntryEditTest : public ::testing::Test {
 protected:
  EntryEditTest() {
    register_builtin_elements(registry);
    apply(material_command(model, {"STEEL", 210000.0, 0.3, 0.0, 1.2e-5, {}, {}}));
    BlockInput block;
    block.size = {4, 2, 2};
    block.divisions = {4, 2, 2};
    block.type = "C3D8";
    block.material = "STEEL";
    apply(block_command(model, block, registry));
    apply(step_command(model, {"ONE", 1.0, 1.0, StepKind::Static}));
    apply(step_command(model, {"TWO", 1.0, 1.0, StepKind::Static}));
  }
  void apply(std::unique_ptr<Command> c) { history.push(model, std::move(c)); }
  ElementRegistry registry;
  Model model;
  UndoStack history;
};

TEST_F(EntryEditTest, BoundaryGroupsAreFoundEditedMovedAndUndone) {
  apply(boundary_command(model, {"BLOCK_XMIN", 1, 3, 0.0, -1}));
  apply(boundary_command(model, {"BLOCK_XMAX", 3, 3, 0.5, -1}));
  const std::size_t xmin = model.nsets.at("BLOCK_XMIN").nodes.size();  // 3 x 3 = 9 nodes
  ASSERT_EQ(xmin, 9u);
  const Entry list{EntryKind::ModelBoundaries, -1, {}, -1};
  const std::vector<NodeGroup> groups = node_groups(model, list);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].nset, "BLOCK_XMIN");
  EXPECT_EQ(groups[0].first_dof, 1);
  EXPECT_EQ(groups[0].last_dof, 3);
  EXPECT_EQ(groups[1].nset, "BLOCK_XMAX");
  EXPECT_EQ(group_labels(model, list),
            (std::vector<std::string>{"BLOCK_XMIN: dofs 1-3 = 0", "BLOCK_XMAX: dof 3 = 0.5"}));
  const BoundaryInput filled = boundary_input_of(model, {EntryKind::ModelBoundaries, -1, {}, 0});
  EXPECT_EQ(filled.nset, "BLOCK_XMIN");
  EXPECT_EQ(filled.step, -1);

  // Dofs 1-2 with 0.1 instead: one command, in place of the old entries.
  const std::vector<Boundary> before = model.boundaries;
  apply(boundary_edit_command(model, {EntryKind::ModelBoundaries, -1, {}, 0}, {"", 1, 2, 0.1, -1}));
  EXPECT_EQ(history.undo_text(), "Edit boundary condition on BLOCK_XMIN");
  EXPECT_EQ(model.boundaries.size(), 2 * xmin + 9);
  EXPECT_DOUBLE_EQ(model.boundaries.front().value, 0.1);  // the group keeps its place
  EXPECT_EQ(group_labels(model, list).front(), "BLOCK_XMIN: dofs 1-2 = 0.1");
  history.undo(model);
  EXPECT_TRUE(same_entries(model.boundaries, before));

  // Moved into step TWO.
  apply(boundary_edit_command(model, {EntryKind::ModelBoundaries, -1, {}, 1},
                              {"BLOCK_XMAX", 3, 3, 0.5, 1}));
  EXPECT_EQ(model.boundaries.size(), 3 * xmin);
  EXPECT_EQ(model.steps[1].boundaries.size(), 9u);
  history.undo(model);
  EXPECT_TRUE(same_entries(model.boundaries, before));
  EXPECT_TRUE(model.steps[1].boundaries.empty());

  // The add dialog's checks.
  const Entry first{EntryKind::ModelBoundaries, -1, {}, 0};
  EXPECT_EQ(refusal([&] {
              boundary_edit_command(model, first, {"", 3, 1, 0.0, -1});
            }),
            "last dof must not be below the first dof");
  EXPECT_EQ(refusal([&] {
              boundary_edit_command(model, first, {"NOWHERE", 1, 3, 0.0, -1});
            }),
            "no node set NOWHERE in the model");
  EXPECT_EQ(refusal([&] {
              boundary_edit_command(model, first, {"", 11, 11, 0.0, 0});
            }),
            "first dof 11 does not fit the static step ONE: it takes dofs 1, 2, 3 (x, y, z) and 4, "
            "5, 6 (rotations about x, y, z)");
  EXPECT_EQ(
      refusal([&] {
        boundary_edit_command(model, {EntryKind::ModelBoundaries, -1, {}, 5}, {"", 1, 1, 0.0, -1});
      }),
      "the list has no entry 6");

  // Two dialogs in a row with the same dof and value stay two entries, named after their sets;
  // nodes that form no set any more are "N nodes".
  apply(boundary_command(model, {"BLOCK_YMIN", 2, 2, 0.0, 0}));
  apply(boundary_command(model, {"BLOCK_YMAX", 2, 2, 0.0, 0}));
  apply(boundary_command(model, {"BLOCK_ZMIN", 3, 3, 0.0, 0}));
  const Entry step_one{EntryKind::StepBoundaries, 0, {}, -1};
  EXPECT_EQ(group_labels(model, step_one),
            (std::vector<std::string>{"BLOCK_YMIN: dof 2 = 0", "BLOCK_YMAX: dof 2 = 0",
                                      "BLOCK_ZMIN: dof 3 = 0"}));
  apply(delete_command(model, {EntryKind::NodeSet, -1, "BLOCK_YMAX", -1}));
  EXPECT_EQ(group_labels(model, step_one)[1], "15 nodes: dof 2 = 0");
  history.undo(model);
  for (int i = 0; i < 3; ++i) history.undo(model);
  EXPECT_TRUE(model.steps[0].boundaries.empty());

  // Deleting one group leaves the other.
  apply(delete_command(model, first));
  EXPECT_EQ(model.boundaries.size(), 9u);
  history.undo(model);
  EXPECT_TRUE(same_entries(model.boundaries, before));
}

TEST_F(EntryEditTest, LoadPressureAndTemperatureGroupsAreEditedAndUndone) {
  apply(cload_command(model, {"BLOCK_XMAX", 3, -90.0, true, 0}));  // -10 on each of 9 nodes
  const Entry loads{EntryKind::StepCloads, 0, {}, 0};
  const CloadInput filled = cload_input_of(model, loads);
  EXPECT_EQ(filled.nset, "BLOCK_XMAX");
  EXPECT_DOUBLE_EQ(filled.value, -10.0);  // per node: the dialog opens with split off
  EXPECT_FALSE(filled.split);
  const std::vector<ConcentratedLoad> before = model.steps[0].cloads;
  apply(cload_edit_command(model, loads, {"", 1, 45.0, true, 0}));
  ASSERT_EQ(model.steps[0].cloads.size(), 9u);
  EXPECT_EQ(model.steps[0].cloads[0].dof, 1);
  EXPECT_DOUBLE_EQ(model.steps[0].cloads[0].value, 5.0);
  history.undo(model);
  EXPECT_TRUE(same_entries(model.steps[0].cloads, before));
  EXPECT_EQ(refusal([&] {
              cload_edit_command(model, loads, {"", 3, 0.0, false, 0});
            }),
            "a load of 0 does nothing; enter a value");

  apply(pressure_command(model, {"BLOCK_ZMAX", "", 1, 2.0, 1}));
  const Entry pressures{EntryKind::StepDloads, 1, {}, 0};
  const PressureInput p = pressure_input_of(model, pressures);
  EXPECT_EQ(p.surface, "BLOCK_ZMAX");
  EXPECT_DOUBLE_EQ(p.magnitude, 2.0);
  const std::vector<DistributedLoad> dloads = model.steps[1].dloads;
  // Face S2 of the whole block instead (16 elements), 3.0.
  apply(pressure_edit_command(model, pressures, {"", "BLOCK", 2, 3.0, 1}));
  EXPECT_EQ(model.steps[1].dloads.size(), 16u);
  EXPECT_EQ(group_labels(model, pressures), (std::vector<std::string>{"BLOCK S2: pressure 3"}));
  history.undo(model);
  EXPECT_TRUE(same_entries(model.steps[1].dloads, dloads));

  apply(temperature_command(model, {"BLOCK_XMIN", 20.0, -1}));
  apply(temperature_command(model, {"BLOCK_XMAX", 80.0, -1}));
  const Entry second{EntryKind::InitialTemperatures, -1, {}, 1};
  EXPECT_EQ(temperature_input_of(model, second).nset, "BLOCK_XMAX");
  const std::vector<NodalTemperature> initial = model.initial_temperatures;
  apply(temperature_edit_command(model, second, {"", 60.0, -1}));
  EXPECT_EQ(model.initial_temperatures.size(), 18u);
  EXPECT_EQ(group_labels(model, {EntryKind::InitialTemperatures, -1, {}, -1}),
            (std::vector<std::string>{"BLOCK_XMIN: T = 20", "BLOCK_XMAX: T = 60"}));
  history.undo(model);
  EXPECT_TRUE(same_entries(model.initial_temperatures, initial));
  // Moved into step ONE as a *TEMPERATURE.
  apply(temperature_edit_command(model, second, {"", 100.0, 0}));
  EXPECT_EQ(model.initial_temperatures.size(), 9u);
  EXPECT_EQ(model.steps[0].temperatures.size(), 9u);
  history.undo(model);
  EXPECT_TRUE(same_entries(model.initial_temperatures, initial));
  EXPECT_TRUE(model.steps[0].temperatures.empty());
}

TEST_F(EntryEditTest, SetsAreRenamedWithTheirReferencesAndTakeTheSelection) {
  // A node set a transform names: the transform follows the rename; undo brings both back.
  apply(transform_command(model, {"BLOCK_XMAX", false, {1, 0, 0}, {0, 1, 0}}));
  const Entry xmax{EntryKind::NodeSet, -1, "BLOCK_XMAX", -1};
  const Selection nothing;
  apply(set_edit_command(model, xmax, {"end", Membership::Keep}, nothing));
  EXPECT_EQ(history.undo_text(), "Rename node set BLOCK_XMAX to END");
  EXPECT_TRUE(history.undo_keeps_results());  // a set changes neither the mesh nor the analysis
  EXPECT_EQ(model.nsets.count("BLOCK_XMAX"), 0u);
  EXPECT_EQ(model.nsets.at("END").name, "END");
  EXPECT_EQ(model.transforms[0].nset, "END");
  history.undo(model);
  EXPECT_EQ(model.transforms[0].nset, "BLOCK_XMAX");
  EXPECT_EQ(model.nsets.count("END"), 0u);

  // Members from the selection: add two picked nodes, then remove one.
  Selection picked(PickKind::Node);
  PickedItem a, b;
  a.node = 0;
  b.node = 1;
  picked.apply(SelectOp::Replace, {a, b});
  const std::vector<int> nodes = model.nsets.at("BLOCK_XMAX").nodes;
  apply(set_edit_command(model, xmax, {"BLOCK_XMAX", Membership::Add}, picked));
  EXPECT_EQ(model.nsets.at("BLOCK_XMAX").nodes.size(), nodes.size() + 2);
  history.undo(model);
  EXPECT_EQ(model.nsets.at("BLOCK_XMAX").nodes, nodes);
  apply(set_edit_command(model, xmax, {"BLOCK_XMAX", Membership::Replace}, picked));
  EXPECT_EQ(model.nsets.at("BLOCK_XMAX").nodes, (std::vector<int>{0, 1}));
  history.undo(model);

  // Refusals: a name in use, another kind of selection, nothing to do, an empty set.
  EXPECT_EQ(refusal([&] {
              set_edit_command(model, xmax, {"BLOCK_XMIN", Membership::Keep}, nothing);
            }),
            "node set BLOCK_XMIN exists already; choose another name");
  EXPECT_EQ(refusal([&] {
              set_edit_command(model, xmax, {"BLOCK_XMAX", Membership::Add}, nothing);
            }),
            "a node set takes picked nodes: pick them in the view (Select menu) first");
  EXPECT_EQ(refusal([&] {
              set_edit_command(model, xmax, {"BLOCK_XMAX", Membership::Keep}, nothing);
            }),
            "nothing to change: give a new name or change the members");
  EXPECT_EQ(refusal([&] {
              set_edit_command(model, xmax, {"9X", Membership::Keep}, nothing);
            }),
            "the node set name '9X' must start with a letter");

  // An element set with a section: the section follows the rename; picked elements join the set
  // and the section, and undo takes the section back off them.
  apply(set_edit_command(model, {EntryKind::ElementSet, -1, "BLOCK", -1},
                         {"BODY", Membership::Keep}, nothing));
  EXPECT_EQ(model.sections[0].elset, "BODY");
  history.undo(model);
  EXPECT_EQ(model.sections[0].elset, "BLOCK");
  BlockInput spare;  // 2 elements without a section, beside the block
  spare.name = "SPARE";
  spare.origin = {10, 0, 0};
  spare.divisions = {2, 1, 1};
  spare.type = "C3D8";
  apply(block_command(model, spare, registry));
  const int loose = model.elsets.at("SPARE").elements.front();
  ASSERT_EQ(model.elements[loose].section, -1);
  Selection elements(PickKind::Element);
  PickedItem e0;
  e0.kind = PickKind::Element;
  e0.element = loose;
  elements.apply(SelectOp::Replace, {e0});
  apply(set_edit_command(model, {EntryKind::ElementSet, -1, "BLOCK", -1},
                         {"BLOCK", Membership::Add}, elements));
  EXPECT_EQ(model.elements[loose].section, 0);
  EXPECT_EQ(model.elsets.at("BLOCK").elements.size(), 17u);
  EXPECT_FALSE(history.undo_keeps_results());  // the analysis changed: an element gained a section
  history.undo(model);
  EXPECT_EQ(model.elements[loose].section, -1);
  EXPECT_EQ(model.elsets.at("BLOCK").elements.size(), 16u);

  // A surface a contact pair names.
  apply(contact_command(model, [] {
    ContactInput c;
    c.slave = "BLOCK_XMIN";
    c.master = "BLOCK_XMAX";
    c.interaction = "I";
    return c;
  }()));
  apply(set_edit_command(model, {EntryKind::Surface, -1, "BLOCK_XMIN", -1},
                         {"LEFT", Membership::Keep}, nothing));
  EXPECT_EQ(model.contact_pairs[0].slave, "LEFT");
  EXPECT_EQ(model.surfaces.count("LEFT"), 1u);
  history.undo(model);
  EXPECT_EQ(model.contact_pairs[0].slave, "BLOCK_XMIN");
}

TEST_F(EntryEditTest, EquationsAndTransformsAreEditedInPlace) {
  const Id n1 = model.node_ids[0], n2 = model.node_ids[1], n3 = model.node_ids[2];
  const std::string two = std::to_string(n1) + " 1 1\n" + std::to_string(n2) + " 1 -1";
  apply(equation_command(model, parse_equation_terms(two)));
  // The equation's own first term is not "eliminated by another equation".
  const std::string three = std::to_string(n1) + " 1 1\n" + std::to_string(n3) + " 1 -2";
  apply(equation_edit_command(model, 0, parse_equation_terms(three)));
  EXPECT_EQ(equation_text(model, 0), std::to_string(n1) + " 1 1; " + std::to_string(n3) + " 1 -2");
  history.undo(model);
  EXPECT_EQ(equation_text(model, 0), std::to_string(n1) + " 1 1; " + std::to_string(n2) + " 1 -1");
  EXPECT_EQ(refusal([&] { equation_edit_command(model, 0, parse_equation_terms("1 1 1")); }),
            "an equation needs at least 2 terms (one term is a boundary condition)");

  apply(transform_command(model, {"BLOCK_XMAX", false, {1, 0, 0}, {0, 1, 0}}));
  // Its own nodes do not "have a transform already".
  apply(transform_edit_command(model, 0, {"BLOCK_XMAX", true, {0, 0, 0}, {0, 0, 1}}));
  EXPECT_EQ(model.transforms[0].axes.system, CoordinateSystem::Cylindrical);
  EXPECT_TRUE(transform_input_of(model, 0).cylindrical);
  history.undo(model);
  EXPECT_EQ(model.transforms[0].axes.system, CoordinateSystem::Rectangular);
  // BLOCK_XMIN holds nodes on the z axis (x = y = 0): no radial direction.
  EXPECT_NE(refusal([&] {
              transform_edit_command(model, 0, {"BLOCK_XMIN", true, {0, 0, 0}, {0, 0, 1}});
            }).find("lies on the axis"),
            std::string::npos);
}

// The §6.2 model's ingredients through the dialogs' commands: a conducting material without
// elastic constants, a steady heat step, prescribed temperatures (dof 11), a nodal heat flow.
TEST(ScalarFieldInput, HeatStepConductivityAndDof11) {
  ElementRegistry registry;
  register_builtin_elements(registry);
  Model model;
  UndoStack history;
  const auto apply = [&](std::unique_ptr<Command> c) { history.push(model, std::move(c)); };
  apply(material_command(model, {"COPPER", 0.0, 0.0, 0.0, 0.0, {380.0}, {5.8e7}}));
  EXPECT_FALSE(model.materials[0].young.has_value());
  EXPECT_EQ(*model.materials[0].conductivity, (std::array<double, 3>{380.0, 380.0, 380.0}));
  EXPECT_EQ(material_input_of(model, 0).conductivity, (std::vector<double>{380.0}));
  EXPECT_EQ(refusal([&] {
              material_command(model, {"X", 0.0, 0.3, 0.0, 0.0, {}, {}});
            }),
            "Young's modulus must be > 0 (0 only for a heat or electric material with a "
            "conductivity)");
  EXPECT_EQ(refusal([&] {
              material_command(model, {"X", 1.0, 0.3, 0.0, 0.0, {1.0, 2.0}, {}});
            }),
            "conductivity: give 1 value (isotropic) or 3 (k11 k22 k33), not 2");
  EXPECT_EQ(refusal([&] {
              material_command(model, {"X", 1.0, 0.3, 0.0, 0.0, {-1.0}, {}});
            }),
            "conductivity must be > 0 (leave it empty: not given)");
  apply(material_edit_command(model, 0, {"COPPER", 0.0, 0.0, 0.0, 0.0, {1.0, 2.0, 3.0}, {}}));
  EXPECT_EQ(*model.materials[0].conductivity, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_FALSE(model.materials[0].electrical_conductivity.has_value());

  BlockInput block;
  block.size = {1, 1, 1};
  block.divisions = {2, 1, 1};
  block.type = "C3D8";
  block.material = "COPPER";
  apply(block_command(model, block, registry));
  apply(step_command(model, {"HEAT", 1.0, 1.0, StepKind::HeatTransfer}));
  EXPECT_EQ(model.steps[0].kind, StepKind::HeatTransfer);
  apply(boundary_command(model, {"BLOCK_XMIN", 11, 11, 100.0, 0}));
  apply(cload_command(model, {"BLOCK_XMAX", 11, 8.0, true, 0}));
  EXPECT_TRUE(model.steps[0].cloads.empty());
  ASSERT_EQ(model.steps[0].cfluxes.size(), 4u);
  EXPECT_DOUBLE_EQ(model.steps[0].cfluxes[0].value, 2.0);
  EXPECT_EQ(history.undo_text(), "Heat flow into BLOCK_XMAX");
  // What does not fit a heat step is refused with what it takes.
  EXPECT_EQ(refusal([&] {
              boundary_command(model, {"BLOCK_XMIN", 1, 3, 0.0, 0});
            }),
            "first dof 1 does not fit the heat transfer step HEAT: it takes dof 11 (temperature)");
  EXPECT_EQ(refusal([&] {
              boundary_command(model, {"BLOCK_XMIN", 9, 9, 0.0, -1});
            }),
            "first dof 9 does not fit the heat transfer step HEAT (held in every step): it takes "
            "dof 11 (temperature)");
  EXPECT_EQ(refusal([&] {
              boundary_command(model, {"BLOCK_XMIN", 9, 11, 0.0, 0});
            }),
            "first dof 9 does not fit the heat transfer step HEAT: it takes dof 11 (temperature)");
  EXPECT_NE(refusal([&] {
              pressure_command(model, {"BLOCK_ZMAX", "", 1, 1.0, 0});
            }).find("a pressure belongs to a static step"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              temperature_command(model, {"BLOCK_XMIN", 1.0, 0});
            }).find("prescribe the temperature as a boundary condition, dof 11"),
            std::string::npos);
  // The step cannot turn static while it holds dof 11; the flux group edits into the same list.
  EXPECT_NE(refusal([&] {
              step_edit_command(model, 0, {"HEAT", 1.0, 1.0, StepKind::Static});
            }).find("delete them first"),
            std::string::npos);
  const Entry flux{EntryKind::StepFluxes, 0, {}, 0};
  EXPECT_EQ(cload_input_of(model, flux).dof, 11);
  apply(cload_edit_command(model, flux, {"", 11, 3.0, false, 0}));
  EXPECT_DOUBLE_EQ(model.steps[0].cfluxes[0].value, 3.0);
  history.undo(model);

  // Written and read back by the deck reader.
  const std::string path = ::testing::TempDir() + "/styk_gui_heat.inp";
  {
    std::ofstream out(path);
    write_inp(model, out);
  }
  const Model back = read_inp(path, registry);
  std::remove(path.c_str());
  ASSERT_EQ(back.steps.size(), 1u);
  EXPECT_EQ(back.steps[0].kind, StepKind::HeatTransfer);
  EXPECT_EQ(back.steps[0].boundaries.size(), model.steps[0].boundaries.size());
  EXPECT_EQ(back.steps[0].boundaries[0].dof, 11);
  EXPECT_EQ(back.steps[0].cfluxes.size(), 4u);
  EXPECT_EQ(*back.materials[0].conductivity, (std::array<double, 3>{1.0, 2.0, 3.0}));
}

}  // namespace
}  // namespace styk::gui
