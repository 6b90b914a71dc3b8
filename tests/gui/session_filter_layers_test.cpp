// The view's element filter and layers made from the filter or the selection (issue 7; SPEC §5
// "filter elements by number or type; layers built from sets or by hand"), on a known box:
// 4 x 4 x 4 C3D8 on [0, 4]^3 (ids 1..64, x fastest, then y, then z).
#include <gtest/gtest.h>

#include <algorithm>

#include "box_model.hpp"
#include "session/document.hpp"
#include "session/element_filter.hpp"
#include "session/geometry_objects.hpp"
#include "session/layer_edits.hpp"
#include "session/scene.hpp"
#include "styk/elements/builtin.hpp"

namespace styk::gui {
namespace {

using test::box_model;

class GuiFilterTest : public ::testing::Test {
 protected:
  GuiFilterTest() : doc(registry) {
    register_builtin_elements(registry);
    doc.apply(make_replace_model("box", Model{}, box_model()));
  }
  std::size_t faces(const DisplaySettings& settings) {
    Scene scene;
    scene.rebuild(doc, settings);
    return scene.empty() ? 0 : scene.skin()->face_count();
  }
  std::vector<Id> drawn_ids(const DisplaySettings& settings) {
    Scene scene;
    scene.rebuild(doc, settings);
    std::vector<Id> ids;
    for (const auto& layer : scene.skin()->layers())
      for (int e : layer.elements) ids.push_back(doc.model().elements[e].id);
    std::sort(ids.begin(), ids.end());
    return ids;
  }
  ElementRegistry registry;
  Document doc;
};

TEST(GuiElementFilter, ParsesRangesAndRefusesBadText) {
  const std::vector<IdRange> r = parse_id_ranges("1-500, 700 ,900 - 950");
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].first, 1);
  EXPECT_EQ(r[0].last, 500);
  EXPECT_EQ(r[1].first, 700);
  EXPECT_EQ(r[1].last, 700);
  EXPECT_EQ(r[2].first, 900);
  EXPECT_EQ(r[2].last, 950);
  EXPECT_EQ(format_id_ranges(r), "1-500, 700, 900-950");
  EXPECT_TRUE(parse_id_ranges("  ").empty());
  for (const char* bad : {"abc", "5-2", "1-", "-3", "0", "1-2-3", "1,,x", "2.5"})
    EXPECT_THROW(parse_id_ranges(bad), InputError) << bad;
}

TEST_F(GuiFilterTest, FilterByIdsDrawsTheCutFaces) {
  DisplaySettings settings;
  // The whole box: 6 sides x 16 faces = 96.
  EXPECT_EQ(faces(settings), 96u);
  // Ids 1-16 are the bottom slab 4 x 4 x 1: 2 x 16 + 4 x 4 = 48 faces, the top one a cut face.
  settings.filter = make_element_filter(doc.model(), "1-16", {});
  EXPECT_EQ(faces(settings), 48u);
  std::vector<Id> expected(16);
  for (int i = 0; i < 16; ++i) expected[i] = i + 1;
  EXPECT_EQ(drawn_ids(settings), expected);
  // Two separate slabs (bottom and top): 2 x 48.
  settings.filter = make_element_filter(doc.model(), "1-16, 49-64", {});
  EXPECT_EQ(faces(settings), 96u);
  EXPECT_EQ(drawn_ids(settings).size(), 32u);
  // One element: its 6 faces.
  settings.filter = make_element_filter(doc.model(), "22", {});
  EXPECT_EQ(faces(settings), 6u);
  EXPECT_EQ(drawn_ids(settings), std::vector<Id>{22});
  // Clearing the filter draws everything again.
  settings.filter = ElementDisplayFilter{};
  EXPECT_FALSE(settings.filter.active());
  EXPECT_EQ(faces(settings), 96u);
}

TEST_F(GuiFilterTest, FilterByTypeAndRefusals) {
  LineInput line;
  line.name = "BAR";
  line.a = {0, 0, 5};
  line.b = {4, 0, 5};
  line.divisions = 3;
  doc.apply(line_command(doc.model(), line, registry));
  EXPECT_EQ(element_types_present(doc.model()), (std::vector<std::string>{"C3D8", "T3D2"}));
  ElementDisplayFilter bars = make_element_filter(doc.model(), "", {"t3d2"});
  EXPECT_EQ(filtered_elements(doc.model(), bars).size(), 3u);
  DisplaySettings settings;
  settings.filter = make_element_filter(doc.model(), "", {"C3D8"});
  EXPECT_EQ(filtered_elements(doc.model(), settings.filter).size(), 64u);
  EXPECT_EQ(faces(settings), 96u);
  // Ids and types together: bottom slab ids, but only trusses (ids 65..67) -> none: refused.
  EXPECT_THROW(make_element_filter(doc.model(), "1-16", {"T3D2"}), InputError);
  EXPECT_THROW(make_element_filter(doc.model(), "1000-2000", {}), InputError);
  EXPECT_THROW(make_element_filter(doc.model(), "", {"C3D20"}), InputError);  // not in the model
  EXPECT_THROW(make_element_filter(doc.model(), "1-x", {}), InputError);
}

TEST_F(GuiFilterTest, LayerFromFilterIsUndoableAndHides) {
  const ElementDisplayFilter slab = make_element_filter(doc.model(), "1-16", {});
  add_layer_from_filter(doc, "slab", slab);
  ASSERT_NE(doc.model().find_elset("SLAB"), nullptr);
  ASSERT_EQ(doc.layers().layers().size(), 2u);
  EXPECT_EQ(doc.layers().layers()[0].name, "SLAB");
  EXPECT_EQ(doc.layers().layers()[0].elements.size(), 16u);
  EXPECT_EQ(doc.layers().layers()[1].name, "BOX");  // the part keeps its name, minus the slab
  EXPECT_EQ(doc.layers().layers()[1].elements.size(), 48u);
  EXPECT_EQ(doc.history().undo_text(), "New layer SLAB");

  // Hiding the new layer leaves the upper 4 x 4 x 3 block: 2 x 16 + 4 x 12 = 80 faces.
  doc.layers().set_visible("SLAB", false);
  EXPECT_EQ(faces(DisplaySettings{}), 80u);
  doc.layers().set_color("SLAB", {1.0f, 0.0f, 0.0f});

  doc.undo();
  EXPECT_EQ(doc.model().find_elset("SLAB"), nullptr);
  ASSERT_EQ(doc.layers().layers().size(), 1u);
  EXPECT_EQ(doc.layers().layers()[0].elements.size(), 64u);
  doc.redo();
  ASSERT_EQ(doc.layers().layers().size(), 2u);
  EXPECT_EQ(doc.layers().layers()[0].name, "SLAB");

  // Refused: the name is taken, a bad name, no filter set.
  EXPECT_THROW(add_layer_from_filter(doc, "SLAB", slab), InputError);
  EXPECT_THROW(add_layer_from_filter(doc, "1bad", slab), InputError);
  EXPECT_THROW(add_layer_from_filter(doc, "OTHER2", ElementDisplayFilter{}), InputError);
}

TEST_F(GuiFilterTest, LayerFromSelection) {
  Selection elements(PickKind::Element);
  elements.apply(SelectOp::Replace, {{PickKind::Element, -1, 0, 0}, {PickKind::Element, -1, 5, 0}});
  add_layer_from_selection(doc, "picked", elements);
  EXPECT_EQ(doc.layers().layer("PICKED").elements, (std::vector<int>{0, 5}));

  // The 8 nodes of element index 63 (the top corner cube) stand for that element alone.
  Selection nodes(PickKind::Node);
  std::vector<PickedItem> items;
  const int* conn = doc.model().element_nodes(63);
  for (int k = 0; k < 8; ++k) items.push_back({PickKind::Node, conn[k], -1, 0});
  nodes.apply(SelectOp::Replace, items);
  EXPECT_EQ(elements_of_selection(doc.model(), nodes), std::vector<int>{63});
  add_layer_from_selection(doc, "corner", nodes);
  EXPECT_EQ(doc.layers().layer("CORNER").elements, std::vector<int>{63});
  EXPECT_EQ(doc.layers().layer("BOX").elements.size(), 61u);

  Selection faces(PickKind::Face);
  faces.apply(SelectOp::Replace, {{PickKind::Face, -1, 10, 1}, {PickKind::Face, -1, 10, 2}});
  EXPECT_EQ(elements_of_selection(doc.model(), faces), std::vector<int>{10});

  EXPECT_THROW(add_layer_from_selection(doc, "none", Selection(PickKind::Element)), InputError);
  Selection one_node(PickKind::Node);
  one_node.apply(SelectOp::Replace, {{PickKind::Node, 0, -1, 0}});
  EXPECT_THROW(add_layer_from_selection(doc, "none", one_node), InputError);
}

}  // namespace
}  // namespace styk::gui
