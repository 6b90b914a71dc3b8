// The *ORIENTATION and *DFLUX dialogs' session side (issue 7), without a display: each entry made,
// undone and redone as one command, refused with the dialog's reason, listed (face-flux groups),
// edited and deleted through entry_edits / load_groups, written as a deck the reader reads back
// equal; and a face flux solved in a heat step, checked against the heat balance of SPEC §6.2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

#include "refusal.hpp"
#include "session/contact_input.hpp"
#include "session/entry_edits.hpp"
#include "session/flux_input.hpp"
#include "session/load_groups.hpp"
#include "session/orientation_input.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::gui {
namespace {

using test::refusal;

std::string deck_text(const Model& model) {
  std::ostringstream out;
  write_inp(model, out);
  return out.str();
}

// The deck written to a file and read back by the deck reader.
Model written_and_read(const Model& model, const ElementRegistry& registry,
                       const std::string& file) {
  const std::string path = ::testing::TempDir() + "/" + file;
  {
    std::ofstream out(path);
    write_inp(model, out);
  }
  Model back = read_inp(path, registry);
  std::remove(path.c_str());
  return back;
}

class GuiEntryTest : public ::testing::Test {
 protected:
  GuiEntryTest() { register_builtin_elements(registry); }
  void apply(std::unique_ptr<Command> c) { history.push(model, std::move(c)); }
  void add_block(const std::string& name, const Vec3& origin, const Vec3& size,
                 const std::array<int, 3>& divisions, const std::string& material) {
    BlockInput block;
    block.name = name;
    block.origin = origin;
    block.size = size;
    block.divisions = divisions;
    block.type = "C3D8";
    block.material = material;
    apply(block_command(model, block, registry));
  }
  ElementRegistry registry;
  Model model;
  UndoStack history;
};

// ---- *ORIENTATION ---------------------------------------------------------------------------

TEST_F(GuiEntryTest, OrientationIsAddedUndoneAndRedone) {
  apply(orientation_command(model, {"aniso", false, {1, 1, 0}, {-1, 1, 0}}));
  ASSERT_EQ(model.orientations.count("ANISO"), 1u);
  const Orientation& o = model.orientations.at("ANISO");
  EXPECT_EQ(o.name, "ANISO");
  EXPECT_EQ(o.axes.system, CoordinateSystem::Rectangular);
  EXPECT_EQ(o.axes.a, (Vec3{1, 1, 0}));
  EXPECT_EQ(o.axes.b, (Vec3{-1, 1, 0}));
  EXPECT_EQ(history.undo_text(), "Add rectangular orientation ANISO");
  history.undo(model);
  EXPECT_TRUE(model.orientations.empty());
  history.redo(model);
  EXPECT_EQ(model.orientations.at("ANISO").axes.b, (Vec3{-1, 1, 0}));
}

TEST_F(GuiEntryTest, OrientationRefusesBadNamesAndDegenerateAxes) {
  apply(orientation_command(model, {"ANISO", false, {1, 0, 0}, {0, 1, 0}}));
  const auto refused = [&](const OrientationInput& in) {
    return refusal([&] { orientation_command(model, in); });
  };
  EXPECT_EQ(refused({"", false, {1, 0, 0}, {0, 1, 0}}), "the orientation needs a name");
  EXPECT_EQ(refused({"1ST", false, {1, 0, 0}, {0, 1, 0}}),
            "the orientation name '1ST' must start with a letter");
  EXPECT_EQ(refused({"aniso", true, {0, 0, 0}, {0, 0, 1}}), "orientation ANISO exists already");
  EXPECT_EQ(refused({"R", false, {0, 0, 0}, {0, 1, 0}}),
            "point a must not be the origin (it gives local x)");
  EXPECT_EQ(refused({"R", false, {1, 2, 3}, {-2, -4, -6}}),
            "point b must not lie on the line of a (it gives the local x-y plane)");
  EXPECT_EQ(refused({"C", true, {0, 0, 5}, {0, 0, 5}}), "the two axis points a and b must differ");
  EXPECT_EQ(refused({"C", true, {0, 0, 0}, {0, 0, std::nan("")}}),
            "point b must be a finite number");
  EXPECT_EQ(model.orientations.size(), 1u);  // nothing refused reached the model
}

// A contact pair whose anisotropic friction names the orientation: it is offered (accepted by the
// contact command), follows a rename, and keeps the orientation from being deleted.
TEST_F(GuiEntryTest, OrientationUsedByAnisotropicFrictionIsRenamedAlongAndNotDeleted) {
  apply(material_command(model, {"STEEL", 210000.0, 0.3, 0.0, 0.0, {}, {}}));
  add_block("LOWER", {0, 0, 0}, {1, 1, 1}, {1, 1, 1}, "STEEL");
  add_block("UPPER", {0, 0, 1}, {1, 1, 1}, {1, 1, 1}, "STEEL");
  ContactInput contact;
  contact.slave = "UPPER_ZMIN";
  contact.master = "LOWER_ZMAX";
  contact.interaction = "FRIC";
  contact.friction = "anisotropic";
  contact.mu = 0.1;
  contact.mu2 = 0.3;
  contact.orientation = "ANISO";
  EXPECT_EQ(refusal([&] { contact_command(model, contact, -1); }),
            "no orientation ANISO in the model");
  apply(orientation_command(model, {"ANISO", false, {1, 0, 0}, {0, 1, 0}}));
  apply(contact_command(model, contact, -1));
  EXPECT_EQ(model.surface_interactions.at("FRIC").friction->orientation, "ANISO");

  const Entry entry{EntryKind::Orientation, -1, "ANISO"};
  EXPECT_EQ(refusal([&] { delete_command(model, entry); }),
            "orientation ANISO gives the slip directions of the anisotropic friction of "
            "interaction FRIC (contact pair UPPER_ZMIN / LOWER_ZMAX); change that friction first");

  // Edit: the dialog is filled from the entry; a new name and system, the friction follows.
  const OrientationInput filled = orientation_input_of(model, "ANISO");
  EXPECT_EQ(filled.name, "ANISO");
  EXPECT_FALSE(filled.cylindrical);
  EXPECT_EQ(filled.a, (Vec3{1, 0, 0}));
  apply(orientation_edit_command(model, "ANISO", {"SHAFT", true, {0, 0, 0}, {0, 0, 1}}));
  EXPECT_EQ(history.undo_text(), "Edit orientation ANISO");
  EXPECT_EQ(model.orientations.count("ANISO"), 0u);
  EXPECT_EQ(model.orientations.at("SHAFT").axes.system, CoordinateSystem::Cylindrical);
  EXPECT_EQ(model.surface_interactions.at("FRIC").friction->orientation, "SHAFT");
  // The deck names it consistently and reads back.
  const std::string deck = deck_text(model);
  EXPECT_NE(deck.find("*ORIENTATION, NAME=SHAFT, SYSTEM=CYLINDRICAL\n0, 0, 0, 0, 0, 1\n"),
            std::string::npos);
  EXPECT_NE(deck.find("ORIENTATION=SHAFT"), std::string::npos);
  history.undo(model);
  EXPECT_EQ(model.orientations.at("ANISO").axes.system, CoordinateSystem::Rectangular);
  EXPECT_EQ(model.surface_interactions.at("FRIC").friction->orientation, "ANISO");
  // Editing into the name of another orientation is refused; keeping its own name is not.
  apply(orientation_command(model, {"OTHER", false, {0, 1, 0}, {0, 0, 1}}));
  EXPECT_EQ(refusal([&] {
              orientation_edit_command(model, "ANISO", {"other", false, {1, 0, 0}, {0, 1, 0}});
            }),
            "orientation OTHER exists already");
  EXPECT_EQ(refusal([&] {
              orientation_edit_command(model, "ANISO", {"ANISO", false, {1, 0, 0}, {2, 0, 0}});
            }),
            "point b must not lie on the line of a (it gives the local x-y plane)");
  // An orientation no friction names goes; undo brings it back.
  apply(delete_command(model, {EntryKind::Orientation, -1, "OTHER"}));
  EXPECT_EQ(history.undo_text(), "Delete orientation OTHER");
  EXPECT_EQ(model.orientations.count("OTHER"), 0u);
  history.undo(model);
  EXPECT_EQ(model.orientations.at("OTHER").axes.a, (Vec3{0, 1, 0}));

  // Once the pair is deleted (its interaction goes with it) the orientation may go too.
  apply(delete_command(model, {EntryKind::ContactPair, 0, ""}));
  apply(delete_command(model, entry));
  EXPECT_EQ(model.orientations.count("ANISO"), 0u);
}

TEST_F(GuiEntryTest, OrientationDeckReadsBackEqual) {
  apply(material_command(model, {"STEEL", 210000.0, 0.3, 0.0, 0.0, {}, {}}));
  add_block("PART", {0, 0, 0}, {1, 1, 1}, {1, 1, 1}, "STEEL");       // a deck needs nodes
  apply(step_command(model, {"LOAD", 1.0, 1.0, StepKind::Static}));  // and a step
  apply(orientation_command(model, {"RECT", false, {0.5, 0.25, 0}, {-1, 2, 0.125}}));
  apply(orientation_command(model, {"CYL", true, {0, 0, -1}, {0, 0, 4}}));
  const std::string deck = deck_text(model);
  EXPECT_NE(deck.find("*ORIENTATION, NAME=RECT, SYSTEM=RECTANGULAR\n0.5, 0.25, 0, -1, 2, 0.125\n"),
            std::string::npos);
  EXPECT_NE(deck.find("*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0, 0, -1, 0, 0, 4\n"),
            std::string::npos);
  const Model back = written_and_read(model, registry, "styk_gui_orientations.inp");
  ASSERT_EQ(back.orientations.size(), 2u);
  for (const auto& [name, o] : model.orientations) {
    const Orientation& read = back.orientations.at(name);
    EXPECT_EQ(read.axes.system, o.axes.system) << name;
    EXPECT_EQ(read.axes.a, o.axes.a) << name;
    EXPECT_EQ(read.axes.b, o.axes.b) << name;
  }
}

// ---- *DFLUX ---------------------------------------------------------------------------------

// A slab 2 x 1 x 3 (z) of C3D8, conductivity k = 5, in one steady heat step.
class GuiFluxTest : public GuiEntryTest {
 protected:
  static constexpr double kConductivity = 5.0;
  static constexpr double kFlux = 3.0;    // per area, into the body through z = 3
  static constexpr double kArea = 2.0;    // of the face z = 3
  static constexpr double kLength = 3.0;  // along z
  static constexpr double kFixed = 20.0;  // temperature at z = 0
  GuiFluxTest() {
    apply(material_command(model, {"COND", 0.0, 0.0, 0.0, 0.0, {kConductivity}, {}}));
    add_block("SLAB", {0, 0, 0}, {2, 1, kLength}, {2, 1, 3}, "COND");
  }
};

TEST_F(GuiFluxTest, RefusedWithoutAHeatStepInOtherStepsAndForBadInput) {
  const FluxInput top{"SLAB_ZMAX", "", 1, kFlux, 0};
  const std::string no_heat_step =
      "the model has no heat transfer step: a face flux (*DFLUX) belongs to one; add a step of "
      "kind heat transfer first";
  EXPECT_EQ(refusal([&] { flux_command(model, top); }), no_heat_step);
  apply(step_command(model, {"PUSH", 1.0, 1.0, StepKind::Static}));
  EXPECT_EQ(refusal([&] { flux_command(model, top); }), no_heat_step);
  apply(step_command(model, {"VOLT", 1.0, 1.0, StepKind::ElectricConduction}));
  apply(step_command(model, {"HEAT", 1.0, 1.0, StepKind::HeatTransfer}));
  EXPECT_EQ(refusal([&] { flux_command(model, top); }),
            "step PUSH is a static step: a face flux (*DFLUX) belongs to a heat transfer step");
  EXPECT_EQ(refusal([&] {
              flux_command(model, {"SLAB_ZMAX", "", 1, kFlux, 1});
            }),
            "step VOLT is a electric conduction step: a face flux (*DFLUX) belongs to a heat "
            "transfer step");
  EXPECT_EQ(refusal([&] {
              flux_command(model, {"SLAB_ZMAX", "", 1, kFlux, 7});
            }),
            "no step 8; the model has 3");
  EXPECT_EQ(refusal([&] {
              flux_command(model, {"SLAB_ZMAX", "", 1, 0.0, 2});
            }),
            "a flux of 0 does nothing; enter a value");
  EXPECT_EQ(refusal([&] {
              flux_command(model, {"NOPE", "", 1, kFlux, 2});
            }),
            "no surface NOPE in the model");
  EXPECT_EQ(refusal([&] {
              flux_command(model, {"", "", 1, kFlux, 2});
            }),
            "choose a surface or an element set");
  EXPECT_EQ(refusal([&] {
              flux_command(model, {"", "SLAB", 7, kFlux, 2});
            }),
            "face must be 1..6 (S1..S6)");
  EXPECT_EQ(refusal([&] {
              flux_command(model, {"", "NOSET", 1, kFlux, 2});
            }),
            "no element set NOSET in the model");
  // A pressure is still refused in the heat step, the flux accepted there.
  EXPECT_EQ(refusal([&] {
              pressure_command(model, {"SLAB_ZMAX", "", 1, kFlux, 2});
            }).rfind("step HEAT is a heat transfer step: a pressure belongs to a static step", 0),
            0u);
  apply(flux_command(model, {"SLAB_ZMAX", "", 1, kFlux, 2}));
  EXPECT_EQ(model.steps[2].dfluxes.size(), 2u);
  for (const Step& s : {model.steps[0], model.steps[1]}) EXPECT_TRUE(s.dfluxes.empty());
}

TEST_F(GuiFluxTest, FluxGroupsAreListedEditedDeletedAndUndone) {
  apply(step_command(model, {"HEAT", 1.0, 1.0, StepKind::HeatTransfer}));
  apply(step_command(model, {"MORE", 1.0, 1.0, StepKind::HeatTransfer}));
  apply(flux_command(model, {"SLAB_ZMAX", "", 1, kFlux, 0}));
  EXPECT_EQ(history.undo_text(), "Face flux into SLAB_ZMAX");
  const std::vector<DistributedLoad> top = model.steps[0].dfluxes;
  ASSERT_EQ(top.size(), 2u);  // the 2 x 1 faces of z = 3
  const Surface& surface = model.surfaces.at("SLAB_ZMAX");
  for (std::size_t i = 0; i < top.size(); ++i) {
    EXPECT_EQ(top[i].element, surface.faces[i].element);
    EXPECT_EQ(top[i].face, surface.faces[i].face);
    EXPECT_EQ(top[i].magnitude, kFlux);
  }
  history.undo(model);
  EXPECT_TRUE(model.steps[0].dfluxes.empty());
  history.redo(model);
  EXPECT_EQ(model.steps[0].dfluxes.size(), 2u);
  // A second dialog: face S1 of the element set (the bottom faces z = 0 of the C3D8 bricks).
  apply(flux_command(model, {"", "slab", 1, -1.5, 0}));
  EXPECT_EQ(history.undo_text(), "Face flux into SLAB S1");
  ASSERT_EQ(model.steps[0].dfluxes.size(), 8u);

  const Entry list{EntryKind::StepDfluxes, 0, {}, -1};
  EXPECT_TRUE(is_load_list(EntryKind::StepDfluxes));
  EXPECT_EQ(group_labels(model, list),
            (std::vector<std::string>{"SLAB_ZMAX: flux 3", "SLAB S1: flux -1.5"}));
  const Entry first{EntryKind::StepDfluxes, 0, {}, 0};
  const FluxInput filled = flux_input_of(model, first);
  EXPECT_EQ(filled.surface, "SLAB_ZMAX");
  EXPECT_EQ(filled.magnitude, kFlux);
  EXPECT_EQ(filled.step, 0);
  const FluxInput second = flux_input_of(model, {EntryKind::StepDfluxes, 0, {}, 1});
  EXPECT_EQ(second.elset, "SLAB");
  EXPECT_EQ(second.face, 1);

  // Edit: a new value in place (the same faces), then moved to the other heat step.
  const std::vector<DistributedLoad> before = model.steps[0].dfluxes;
  apply(flux_edit_command(model, first, {"", "", 1, 4.0, 0}));
  EXPECT_EQ(history.undo_text(), "Edit face flux into SLAB_ZMAX");
  EXPECT_EQ(group_labels(model, list),
            (std::vector<std::string>{"SLAB_ZMAX: flux 4", "SLAB S1: flux -1.5"}));
  history.undo(model);
  ASSERT_EQ(model.steps[0].dfluxes.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i)
    EXPECT_EQ(model.steps[0].dfluxes[i].magnitude, before[i].magnitude);
  apply(flux_edit_command(model, first, {"SLAB_ZMAX", "", 1, 4.0, 1}));
  EXPECT_EQ(model.steps[0].dfluxes.size(), 6u);
  EXPECT_EQ(group_labels(model, {EntryKind::StepDfluxes, 1, {}, -1}),
            (std::vector<std::string>{"SLAB_ZMAX: flux 4"}));
  history.undo(model);
  EXPECT_EQ(model.steps[0].dfluxes.size(), 8u);
  EXPECT_TRUE(model.steps[1].dfluxes.empty());
  EXPECT_EQ(refusal([&] {
              flux_edit_command(model, first, {"", "", 1, 0.0, 0});
            }),
            "a flux of 0 does nothing; enter a value");
  EXPECT_EQ(refusal([&] {
              pressure_edit_command(model, first, {"", "", 1, 1.0, 0});
            }).rfind("step HEAT is a heat transfer step", 0),
            0u);

  // Delete one group, then the whole list; undo restores each exactly.
  apply(delete_command(model, {EntryKind::StepDfluxes, 0, {}, 1}));
  EXPECT_EQ(history.undo_text(), "Delete SLAB S1: flux -1.5");
  EXPECT_EQ(model.steps[0].dfluxes.size(), 2u);
  history.undo(model);
  apply(delete_command(model, list));
  EXPECT_EQ(history.undo_text(), "Delete the face fluxes of HEAT");
  EXPECT_TRUE(model.steps[0].dfluxes.empty());
  history.undo(model);
  ASSERT_EQ(model.steps[0].dfluxes.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(model.steps[0].dfluxes[i].element, before[i].element);
    EXPECT_EQ(model.steps[0].dfluxes[i].face, before[i].face);
    EXPECT_EQ(model.steps[0].dfluxes[i].magnitude, before[i].magnitude);
  }
  // A heat step holding face fluxes does not turn static.
  EXPECT_NE(refusal([&] {
              step_edit_command(model, 0, {"HEAT", 1.0, 1.0, StepKind::Static});
            }),
            "(accepted)");
}

// SPEC §6.2 (steady heat conduction; there a cylinder wall, here its one-dimensional analogue,
// a slab with T = 20 held at z = 0 and a flux q = 3 into the face z = 3, the other faces
// insulated): the heat balance makes the reaction flow at the fixed nodes the applied flux times
// the area, sum RFL = -q A = -6, and T(z) = 20 + q z / k is linear, so C3D8 reproduces it
// exactly: T = 20 + 3 x 3 / 5 = 21.8 on z = 3. Both asserted to 1e-9 relative (round-off of a
// 24-node solve).
TEST_F(GuiFluxTest, FaceFluxSolvedBalancesTheReactionsAndReadsBack) {
  apply(step_command(model, {"HEAT", 1.0, 1.0, StepKind::HeatTransfer}));
  apply(boundary_command(model, {"SLAB_ZMIN", 11, 11, kFixed, 0}));
  apply(flux_command(model, {"SLAB_ZMAX", "", 1, kFlux, 0}));

  // The deck holds one *DFLUX line per face and reads back equal.
  const std::string deck = deck_text(model);
  ASSERT_NE(deck.find("*DFLUX\n"), std::string::npos);
  for (const DistributedLoad& d : model.steps[0].dfluxes)
    EXPECT_NE(deck.find(std::to_string(model.elements[d.element].id) + ", S" +
                        std::to_string(d.face) + ", 3\n"),
              std::string::npos);
  const Model back = written_and_read(model, registry, "styk_gui_dflux.inp");
  ASSERT_EQ(back.steps.size(), 1u);
  ASSERT_EQ(back.steps[0].dfluxes.size(), model.steps[0].dfluxes.size());
  for (std::size_t i = 0; i < back.steps[0].dfluxes.size(); ++i) {
    const DistributedLoad& a = model.steps[0].dfluxes[i];
    const DistributedLoad& b = back.steps[0].dfluxes[i];
    EXPECT_EQ(back.elements[b.element].id, model.elements[a.element].id);
    EXPECT_EQ(b.face, a.face);
    EXPECT_EQ(b.magnitude, a.magnitude);
  }
  EXPECT_EQ(group_labels(back, {EntryKind::StepDfluxes, 0, {}, -1}),
            (std::vector<std::string>{"SLAB_ZMAX: flux 3"}));

  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  ASSERT_EQ(results.increments.size(), 1u);
  const ScalarFieldResult& s = results.increments.front().scalar;
  ASSERT_EQ(s.kind, ScalarFieldResult::Kind::Temperature);
  double reaction = 0.0;
  for (int n : model.nsets.at("SLAB_ZMIN").nodes) reaction += s.reaction[n];
  const double applied = kFlux * kArea;
  std::printf("face flux: sum RFL at z = 0 %.12g (expected %.12g)\n", reaction, -applied);
  EXPECT_NEAR(reaction, -applied, 1e-9 * applied);
  const double top = kFixed + kFlux * kLength / kConductivity;
  double worst = 0.0;
  for (int n : model.nsets.at("SLAB_ZMAX").nodes)
    worst = std::max(worst, std::abs(s.value[n] - top));
  std::printf("face flux: max |T - %.12g| on z = 3: %.3e\n", top, worst);
  EXPECT_LT(worst, 1e-9 * top);
}

}  // namespace
}  // namespace styk::gui
