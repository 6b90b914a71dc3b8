// The GUI session without a display: edit commands, undo/redo, the clean state, layers.
#include <gtest/gtest.h>

#include "session/document.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"

namespace styk::gui {
namespace {

const std::string kCantilever = std::string(STYK_SOURCE_DIR) + "/samples/cantilever-c3d20.inp";

class SessionTest : public ::testing::Test {
 protected:
  SessionTest() { register_builtin_elements(registry); }
  ElementRegistry registry;
};

TEST_F(SessionTest, EveryEditIsUndoneAndRedoneExactly) {
  Document doc(registry);
  doc.open_inp(kCantilever);
  const std::size_t materials = doc.model().materials.size();
  const std::size_t steps = doc.model().steps.size();
  const std::size_t cloads = doc.model().steps[0].cloads.size();
  const std::size_t tip = doc.model().find_nset("TIP")->nodes.size();
  EXPECT_FALSE(doc.is_modified());

  doc.apply(material_command(doc.model(), {"STEEL2", 200000.0, 0.29, 7.8e-9}));
  doc.apply(step_command(doc.model(), {"PUSH", 0.5, 1.0}));
  doc.apply(cload_command(doc.model(), {"TIP", 2, -10.0, false, 1}));
  EXPECT_TRUE(doc.is_modified());
  ASSERT_EQ(doc.model().materials.size(), materials + 1);
  EXPECT_EQ(doc.model().materials.back().name, "STEEL2");
  ASSERT_EQ(doc.model().steps.size(), steps + 1);
  EXPECT_EQ(doc.model().steps.back().cloads.size(), tip);
  EXPECT_EQ(doc.history().undo_text(), "Load TIP");

  doc.undo();
  EXPECT_TRUE(doc.model().steps.back().cloads.empty());
  doc.undo();
  EXPECT_EQ(doc.model().steps.size(), steps);
  EXPECT_EQ(doc.model().steps[0].cloads.size(), cloads);
  doc.undo();
  EXPECT_EQ(doc.model().materials.size(), materials);
  EXPECT_FALSE(doc.is_modified());  // back at the opened state
  EXPECT_FALSE(doc.history().can_undo());

  doc.redo();
  doc.redo();
  EXPECT_EQ(doc.model().steps.size(), steps + 1);
  EXPECT_EQ(doc.history().redo_text(), "Load TIP");
  // A new edit drops what was undone.
  doc.apply(boundary_command(doc.model(), {"TIP", 1, 1, 0.0, 1}));
  EXPECT_FALSE(doc.history().can_redo());
  EXPECT_EQ(doc.model().steps.back().boundaries.size(), tip);
}

TEST_F(SessionTest, SectionAssignsElementsAndUndoClearsThem) {
  Document doc(registry);
  BlockInput block;
  block.name = "PART";
  block.divisions = {3, 2, 1};
  doc.apply(material_command(doc.model(), {"ALU", 70000.0, 0.33, 0.0}));
  doc.apply(block_command(doc.model(), block, registry));
  ASSERT_EQ(doc.model().element_count(), 6);
  for (const Element& e : doc.model().elements) EXPECT_EQ(e.section, -1);
  doc.apply(section_command(doc.model(), {"PART", "ALU"}));
  for (const Element& e : doc.model().elements) EXPECT_EQ(e.section, 0);
  EXPECT_EQ(doc.model().sections[0].material_index, 0);
  doc.undo();
  for (const Element& e : doc.model().elements) EXPECT_EQ(e.section, -1);
  EXPECT_TRUE(doc.model().sections.empty());
  doc.undo();  // the block
  EXPECT_EQ(doc.model().element_count(), 0);
  EXPECT_EQ(doc.model().node_count(), 0);
  doc.redo();
  EXPECT_EQ(doc.model().element_count(), 6);
}

TEST_F(SessionTest, SavingMarksCleanAndTheDeckReadsBack) {
  Document doc(registry);
  doc.open_inp(kCantilever);
  doc.apply(material_command(doc.model(), {"EXTRA", 1000.0, 0.2, 0.0}));
  EXPECT_TRUE(doc.is_modified());
  const std::string path = std::string(STYK_BINARY_DIR) + "/tests/gui/saved-cantilever.inp";
  doc.save_inp(path);
  EXPECT_FALSE(doc.is_modified());
  Document again(registry);
  again.open_inp(path);
  EXPECT_EQ(again.model().element_count(), doc.model().element_count());
  EXPECT_EQ(again.model().materials.size(), doc.model().materials.size());
  EXPECT_GE(again.model().material_index("EXTRA"), 0);
  doc.undo();  // undoing past the save makes the document modified again
  EXPECT_TRUE(doc.is_modified());
}

TEST_F(SessionTest, LayersFollowSectionsAndKeepVisibilityAndColour) {
  Document doc(registry);
  doc.apply(material_command(doc.model(), {"M", 1000.0, 0.3, 0.0}));
  BlockInput a;
  a.name = "SHAFT";
  a.material = "M";
  doc.apply(block_command(doc.model(), a, registry));
  BlockInput b;
  b.name = "HUB";
  b.origin = {0, 0, 2};
  doc.apply(block_command(doc.model(), b, registry));  // no section: joins "OTHER"
  ASSERT_EQ(doc.layers().layers().size(), 2u);
  EXPECT_EQ(doc.layers().layers()[0].name, "SHAFT");
  EXPECT_EQ(doc.layers().layers()[1].name, "OTHER");
  EXPECT_EQ(doc.layers().layers()[1].elements.size(), 4u);

  doc.layers().set_visible("SHAFT", false);
  doc.layers().set_color("SHAFT", {0.1f, 0.2f, 0.3f});
  doc.apply(section_command(doc.model(), {"HUB", "M"}));
  ASSERT_EQ(doc.layers().layers().size(), 2u);
  EXPECT_EQ(doc.layers().layers()[1].name, "HUB");
  EXPECT_FALSE(doc.layers().layer("SHAFT").visible);
  EXPECT_FLOAT_EQ(doc.layers().layer("SHAFT").color.b, 0.3f);
  EXPECT_TRUE(doc.layers().any_visible());
  doc.layers().set_visible("HUB", false);
  EXPECT_FALSE(doc.layers().any_visible());
  EXPECT_THROW(doc.layers().set_visible("NOPE", true), std::out_of_range);
}

TEST_F(SessionTest, AWholeModelSetBesideThePartsIsNoLayerOfAResultsMesh) {
  Model model;
  BlockInput a;
  a.name = "A";
  model = model_with_block(model, a, registry);
  BlockInput b;
  b.name = "B";
  b.origin = {2, 0, 0};
  model = model_with_block(model, b, registry);
  ElementSet all;
  all.name = "EALL";
  for (int e = 0; e < model.element_count(); ++e) all.elements.push_back(e);
  model.elsets["EALL"] = all;
  LayerTable table;
  table.rebuild(model);
  ASSERT_EQ(table.layers().size(), 2u);
  EXPECT_EQ(table.layers()[0].name, "A");
  EXPECT_EQ(table.layers()[1].name, "B");
}

TEST_F(SessionTest, AFailedOpenLeavesTheDocumentAsItWas) {
  Document doc(registry);
  doc.open_inp(kCantilever);
  const long revision = doc.revision();
  const std::string bad = std::string(STYK_SOURCE_DIR) + "/tests/inputs/bad/does-not-exist.inp";
  EXPECT_THROW(doc.open_inp(bad), InputError);
  EXPECT_EQ(doc.revision(), revision);
  EXPECT_EQ(doc.path(), kCantilever);
  EXPECT_THROW(doc.open_results(kCantilever), std::runtime_error);  // not an HDF5 file
  EXPECT_EQ(doc.model().element_count(), 80);
}

}  // namespace
}  // namespace styk::gui
