// The model dialogs beyond meshing, without a display: contact pairs, thermal loads, equations,
// transforms, node sets from two sets, and editing/deleting what the model tree lists — each
// refused with its reason when wrong, undoable, and written as a deck the reader accepts.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>

#include "refusal.hpp"
#include "session/constraint_input.hpp"
#include "session/contact_input.hpp"
#include "session/entry_edits.hpp"
#include "session/load_groups.hpp"
#include "session/revolve.hpp"
#include "session/thermal_input.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

namespace styk::gui {
namespace {

using test::refusal;

// The SPEC §4.2 quarter shrink fit as the GUI walk-through builds it (coarse mesh).
class ModelEditTest : public ::testing::Test {
 protected:
  ModelEditTest() {
    setup_element_registry(registry, libraries, {build_plugin_directory()});
    apply(material_command(model, {"STEEL", 200000.0, 0.3, 0.0, 2e-5}));
    RevolveInput shaft;
    shaft.name = "SHAFT";
    shaft.r_inner = 0;
    shaft.r_outer = 10;
    shaft.z1 = 60;
    shaft.axial = 12;
    shaft.material = "STEEL";
    apply(revolve_command(model, shaft, registry));
    RevolveInput sleeve = shaft;
    sleeve.name = "SLEEVE";
    sleeve.r_inner = 10;
    sleeve.r_outer = 15;
    sleeve.z0 = 20;
    sleeve.z1 = 40;
    sleeve.axial = 4;
    apply(revolve_command(model, sleeve, registry));
    apply(step_command(model, {"HEAT", 0.25, 1.0}));
    apply(step_command(model, {"PUSH", 0.25, 1.0}));
  }
  void apply(std::unique_ptr<Command> c) { history.push(model, std::move(c)); }
  ContactInput fit() const {
    ContactInput in;
    in.slave = "SLEEVE_INNER";
    in.master = "SHAFT_OUTER";
    in.interaction = "FIT";
    in.mu = 0.2;
    return in;
  }
  PluginLibraries libraries;
  ElementRegistry registry;
  Model model;
  UndoStack history;
};

TEST_F(ModelEditTest, ContactPairWithFriction) {
  apply(contact_command(model, fit()));
  ASSERT_EQ(model.contact_pairs.size(), 1u);
  EXPECT_EQ(model.contact_pairs[0].slave, "SLEEVE_INNER");
  EXPECT_EQ(model.contact_pairs[0].master, "SHAFT_OUTER");
  EXPECT_EQ(model.contact_pairs[0].type, ContactPair::Type::NodeToSurface);
  const SurfaceInteraction& i = model.surface_interactions.at("FIT");
  ASSERT_TRUE(i.friction);
  EXPECT_EQ(i.friction->kind, Friction::Kind::Isotropic);
  EXPECT_DOUBLE_EQ(i.friction->mu, 0.2);
  EXPECT_EQ(history.undo_text(), "Add Contact SLEEVE_INNER / SHAFT_OUTER");
  history.undo(model);
  EXPECT_TRUE(model.contact_pairs.empty());
  EXPECT_TRUE(model.surface_interactions.empty());
}

TEST_F(ModelEditTest, ContactPairRefusals) {
  const auto refused = [&](const std::function<void(ContactInput&)>& change) {
    ContactInput in = fit();
    change(in);
    return refusal([&] { contact_command(model, in); });
  };
  EXPECT_EQ(refused([](ContactInput& in) { in.slave = "NOPE"; }), "no surface NOPE in the model");
  EXPECT_EQ(refused([](ContactInput& in) { in.master = ""; }), "choose a surface");
  EXPECT_EQ(refused([](ContactInput& in) { in.master = "SLEEVE_INNER"; }),
            "slave and master are the same surface SLEEVE_INNER; self-contact is not supported");
  EXPECT_EQ(refused([](ContactInput& in) { in.mu = -0.1; }),
            "friction coefficient must be >= 0, not -0.100000");
  EXPECT_EQ(refused([](ContactInput& in) {
              in.friction = "anisotropic";
              in.mu2 = 0.4;
            }),
            "anisotropic friction needs an orientation (its axes 1, 2)");
  apply(contact_command(model, fit()));
  EXPECT_EQ(refused([](ContactInput& in) { in.interaction = "OTHER"; }),
            "a contact pair SLEEVE_INNER / SHAFT_OUTER exists already");
  EXPECT_EQ(refused([](ContactInput& in) { in.slave = "SLEEVE_TOP"; }),
            "interaction FIT exists already; choose another name");
}

// The contact form edits friction only: a pair read with a penalty law keeps it when edited.
TEST_F(ModelEditTest, EditContactPairKeepsThePenaltyLaw) {
  apply(contact_command(model, fit()));
  model.surface_interactions.at("FIT").behavior.law = PressureOverclosure::Law::Linear;
  model.surface_interactions.at("FIT").behavior.slope = 5e5;
  ContactInput in = contact_input_of(model, 0);
  in.mu = 0.3;
  apply(contact_command(model, in, 0));
  const SurfaceInteraction& i = model.surface_interactions.at("FIT");
  EXPECT_EQ(i.behavior.law, PressureOverclosure::Law::Linear);
  EXPECT_EQ(i.behavior.slope, 5e5);
  ASSERT_TRUE(i.friction);
  EXPECT_DOUBLE_EQ(i.friction->mu, 0.3);
}

TEST_F(ModelEditTest, EditContactPairRoughWithInterference) {
  apply(contact_command(model, fit()));
  ContactInput in = contact_input_of(model, 0);
  EXPECT_EQ(in.friction, "isotropic");
  EXPECT_DOUBLE_EQ(in.mu, 0.2);
  in.friction = "rough";
  in.interaction = "GRIP";
  in.has_clearance = true;
  in.clearance = -0.02;
  apply(contact_command(model, in, 0));
  EXPECT_EQ(model.surface_interactions.count("FIT"), 0u);
  EXPECT_EQ(model.surface_interactions.at("GRIP").friction->kind, Friction::Kind::Rough);
  EXPECT_DOUBLE_EQ(*model.contact_pairs[0].clearance, -0.02);
  history.undo(model);
  EXPECT_EQ(model.contact_pairs[0].interaction, "FIT");
  EXPECT_FALSE(model.contact_pairs[0].clearance);
  EXPECT_EQ(model.surface_interactions.count("GRIP"), 0u);
}

// The pair's type (docs/input.md *CONTACT PAIR, TYPE=) survives an edit of its friction, MORTAR
// included; a node slave cannot be mortar.
TEST_F(ModelEditTest, EditContactPairKeepsItsType) {
  ContactInput mortar = fit();
  mortar.type = ContactPair::Type::Mortar;
  apply(contact_command(model, mortar));
  ContactInput in = contact_input_of(model, 0);
  EXPECT_EQ(in.type, ContactPair::Type::Mortar);
  in.mu = 0.3;
  apply(contact_command(model, in, 0));
  EXPECT_EQ(model.contact_pairs[0].type, ContactPair::Type::Mortar);
  in.type = ContactPair::Type::SurfaceToSurface;
  apply(contact_command(model, in, 0));
  EXPECT_EQ(model.contact_pairs[0].type, ContactPair::Type::SurfaceToSurface);
}

// SPEC §4.2 heating: alpha = 2e-5 on the material, shaft at 0 initially and 100 in step 1.
TEST_F(ModelEditTest, ThermalLoads) {
  EXPECT_DOUBLE_EQ(*model.materials[0].expansion, 2e-5);
  EXPECT_EQ(refusal([&] {
              material_command(model, {"HOT", 2e5, 0.3, 0.0, -1e-5});
            }),
            "expansion coefficient must be >= 0 (0: not given)");
  const std::size_t shaft = model.nsets.at("SHAFT").nodes.size();
  apply(temperature_command(model, {"SHAFT", 0.0, -1}));
  EXPECT_EQ(model.initial_temperatures.size(), shaft);
  apply(temperature_command(model, {"SHAFT", 100.0, 0}));
  apply(temperature_command(model, {"SHAFT_TOP", 150.0, 0}));  // replaces those nodes' values
  EXPECT_EQ(model.steps[0].temperatures.size(), shaft);
  int hot = 0;
  for (const NodalTemperature& t : model.steps[0].temperatures) hot += t.value == 150.0;
  EXPECT_EQ(hot, static_cast<int>(model.nsets.at("SHAFT_TOP").nodes.size()));
  EXPECT_EQ(history.undo_text(), "Temperature of SHAFT_TOP in HEAT");
  history.undo(model);
  for (const NodalTemperature& t : model.steps[0].temperatures) EXPECT_EQ(t.value, 100.0);
  EXPECT_EQ(refusal([&] {
              temperature_command(model, {"SHAFT", 1.0, 5});
            }),
            "no step 6; the model has 2");
  EXPECT_EQ(refusal([&] {
              temperature_command(model, {"NOPE", 1.0, 0});
            }),
            "no node set NOPE in the model");
}

TEST_F(ModelEditTest, EquationsAndTransforms) {
  EXPECT_EQ(parse_equation_terms("3, 1, 1.0\n\n 7 1 -1").size(), 2u);
  EXPECT_EQ(refusal([] { parse_equation_terms("3, 1"); }),
            "term line 1: give node, dof, coefficient");
  EXPECT_EQ(refusal([&] { equation_command(model, parse_equation_terms("3 1 1")); }),
            "an equation needs at least 2 terms (one term is a boundary condition)");
  EXPECT_EQ(refusal([&] { equation_command(model, parse_equation_terms("3 1 0\n7 1 -1")); }),
            "the first term's coefficient must not be 0 (it is the dof the equation eliminates)");
  EXPECT_EQ(refusal([&] { equation_command(model, parse_equation_terms("3 4 1\n7 1 -1")); }),
            "dof must be 1, 2 or 3 (x, y, z), not 4");
  EXPECT_EQ(refusal([&] { equation_command(model, parse_equation_terms("999999 1 1\n7 1 -1")); }),
            "no node 999999 in the model");
  EXPECT_EQ(refusal([&] { equation_command(model, parse_equation_terms("3 1 1\n3 1 -1")); }),
            "node 3 dof 1 appears twice in the equation");
  apply(equation_command(model, parse_equation_terms("3 1 1\n7 1 -1")));
  ASSERT_EQ(model.equations.size(), 1u);
  EXPECT_EQ(model.equations[0].terms[1].node, model.node_index(7));
  EXPECT_EQ(refusal([&] { equation_command(model, parse_equation_terms("3 1 1\n8 1 -1")); }),
            "node 3 dof 1 is eliminated by another equation already");

  TransformInput t;
  t.nset = "SLEEVE_OUTER";
  t.cylindrical = true;
  t.a = {0, 0, 0};
  t.b = {0, 0, 1};
  apply(transform_command(model, t));
  EXPECT_EQ(model.transforms.at(0).axes.system, CoordinateSystem::Cylindrical);
  EXPECT_EQ(refusal([&] { transform_command(model, t); }).substr(0, 5), "node ");
  t.nset = "SHAFT_CUT1";  // holds the axis nodes
  EXPECT_NE(refusal([&] { transform_command(model, t); }).find("lies on the axis"),
            std::string::npos);
  t.cylindrical = false;
  t.a = {1, 0, 0};
  t.b = {2, 0, 0};
  EXPECT_EQ(refusal([&] { transform_command(model, t); }),
            "point b must not lie on the line of a (it gives the local x-y plane)");
}

TEST_F(ModelEditTest, NodeSetOfCommonNodes) {
  apply(common_nodes_command(model, {"SLEEVE_LINE", "SLEEVE_INNER", "SLEEVE_CUT0"}));
  const NodeSet& line = model.nsets.at("SLEEVE_LINE");
  EXPECT_EQ(line.nodes.size(), 9u);  // 4 quadratic elements along z 20..40
  for (int n : line.nodes) {
    EXPECT_NEAR(model.coords[n][0], 10.0, 1e-9);
    EXPECT_NEAR(model.coords[n][1], 0.0, 1e-9);
  }
  EXPECT_EQ(refusal([&] {
              common_nodes_command(model, {"X", "SLEEVE_TOP", "SHAFT_BOTTOM"});
            }),
            "node sets SLEEVE_TOP and SHAFT_BOTTOM share no node");
}

TEST_F(ModelEditTest, DeletingWhatIsUsedIsRefusedWithTheReason) {
  apply(contact_command(model, fit()));
  EXPECT_EQ(refusal([&] {
              delete_command(model, {EntryKind::Material, 0, ""});
            }),
            "material STEEL is used by the section on SHAFT; delete or change that section first");
  EXPECT_EQ(refusal([&] {
              delete_command(model, {EntryKind::Surface, -1, "SHAFT_OUTER"});
            }),
            "surface SHAFT_OUTER is used by the contact pair SLEEVE_INNER / SHAFT_OUTER; delete "
            "the pair first");
  EXPECT_EQ(refusal([&] {
              delete_command(model, {EntryKind::ElementSet, -1, "SLEEVE"});
            }),
            "element set SLEEVE has a section (material STEEL); delete the section first");
  // Delete both sections, then the material; undo brings everything back, element by element.
  const Model before = model;
  apply(delete_command(model, {EntryKind::Section, 0, ""}));
  EXPECT_EQ(model.sections.size(), 1u);
  EXPECT_EQ(model.elements.back().section, 0);  // the sleeve's section moved to index 0
  EXPECT_EQ(model.elements.front().section, -1);
  apply(delete_command(model, {EntryKind::Section, 0, ""}));
  apply(delete_command(model, {EntryKind::Material, 0, ""}));
  EXPECT_TRUE(model.materials.empty());
  for (int k = 0; k < 3; ++k) history.undo(model);
  ASSERT_EQ(model.sections.size(), 2u);
  for (int e = 0; e < model.element_count(); ++e)
    EXPECT_EQ(model.elements[e].section, before.elements[e].section);
  apply(delete_command(model, {EntryKind::ContactPair, 0, ""}));
  EXPECT_TRUE(model.surface_interactions.empty());
  apply(delete_command(model, {EntryKind::Surface, -1, "SHAFT_OUTER"}));
  apply(delete_command(model, {EntryKind::Step, 0, ""}));
  EXPECT_EQ(model.steps.at(0).name, "PUSH");
  history.undo(model);
  EXPECT_EQ(model.steps.at(0).name, "HEAT");
  EXPECT_EQ(refusal([&] {
              delete_command(model, {EntryKind::StepCloads, 0, ""});
            }),
            "there is nothing to delete");
}

TEST_F(ModelEditTest, EditMaterialSectionAndStep) {
  MaterialInput in = material_input_of(model, 0);
  EXPECT_DOUBLE_EQ(in.expansion, 2e-5);
  in.name = "C45";
  in.young = 210000.0;
  apply(material_edit_command(model, 0, in));
  EXPECT_EQ(model.materials[0].name, "C45");
  EXPECT_EQ(model.sections[0].material, "C45");  // sections follow the rename
  history.undo(model);
  EXPECT_EQ(model.sections[1].material, "STEEL");
  apply(material_command(model, {"BRONZE", 110000.0, 0.34, 0.0, 0.0}));
  apply(section_edit_command(model, 1, "BRONZE"));
  EXPECT_EQ(model.sections[1].material_index, 1);
  EXPECT_EQ(refusal([&] { section_edit_command(model, 1, "LEAD"); }),
            "no material LEAD in the model");
  EXPECT_EQ(refusal([&] {
              step_edit_command(model, 1, {"HEAT", 1.0, 1.0});
            }),
            "step HEAT exists already");
  apply(step_edit_command(model, 1, {"PUSH-1", 0.5, 2.0}));
  EXPECT_EQ(model.steps[1].name, "PUSH-1");
  EXPECT_DOUBLE_EQ(model.steps[1].procedure.total_time, 2.0);
}

// Everything the dialogs make is written as a deck the reader takes back unchanged in substance.
TEST_F(ModelEditTest, TheWalkThroughModelIsAValidDeck) {
  apply(contact_command(model, fit()));
  apply(temperature_command(model, {"SHAFT", 0.0, -1}));
  apply(temperature_command(model, {"SHAFT", 100.0, 0}));
  apply(boundary_command(model, {"SHAFT_BOTTOM", 3, 3, 0.0, -1}));
  for (const char* cut : {"SHAFT_CUT0", "SLEEVE_CUT0"})
    apply(boundary_command(model, {cut, 2, 2, 0.0, -1}));
  for (const char* cut : {"SHAFT_CUT1", "SLEEVE_CUT1"})
    apply(boundary_command(model, {cut, 1, 1, 0.0, -1}));
  apply(pressure_command(model, {"SLEEVE_TOP", "", 1, 52.5, 1}));
  // The model tree finds every dialog's entry again, also where two in a row share dof and value.
  EXPECT_EQ(group_labels(model, {EntryKind::ModelBoundaries, -1, {}, -1}),
            (std::vector<std::string>{"SHAFT_BOTTOM: dof 3 = 0", "SHAFT_CUT0: dof 2 = 0",
                                      "SLEEVE_CUT0: dof 2 = 0", "SHAFT_CUT1: dof 1 = 0",
                                      "SLEEVE_CUT1: dof 1 = 0"}));
  EXPECT_EQ(group_labels(model, {EntryKind::StepDloads, 1, {}, -1}),
            (std::vector<std::string>{"SLEEVE_TOP: pressure 52.5"}));
  const std::string path = ::testing::TempDir() + "/styk_gui_walkthrough.inp";
  {
    std::ofstream out(path);
    write_inp(model, out);
  }
  const Model back = read_inp(path, registry);
  std::remove(path.c_str());
  EXPECT_EQ(back.element_count(), model.element_count());
  EXPECT_EQ(back.contact_pairs.size(), 1u);
  EXPECT_DOUBLE_EQ(back.surface_interactions.at("FIT").friction->mu, 0.2);
  EXPECT_DOUBLE_EQ(*back.materials.at(0).expansion, 2e-5);
  EXPECT_EQ(back.steps.at(0).temperatures.size(), model.steps[0].temperatures.size());
  EXPECT_EQ(back.steps.at(1).dloads.size(), model.surfaces.at("SLEEVE_TOP").faces.size());
  EXPECT_EQ(back.surfaces.at("SLEEVE_INNER").faces.size(), 24u);
}

}  // namespace
}  // namespace styk::gui
