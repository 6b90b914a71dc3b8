// Picking in the view (issue 7) on a known box: two C3D8 elements side by side, x in [0, 2],
// y and z in [0, 1]. The pixel of a known point is computed with the camera, the pick must return
// the element / face / node there, and never one hidden behind the front faces. Then the
// selection becomes a node set, element set or surface through one undoable command, and is
// drawn as overlay markers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "session/document.hpp"
#include "session/geometry_objects.hpp"
#include "session/highlight.hpp"
#include "session/picking.hpp"
#include "session/scene.hpp"
#include "session/selection_info.hpp"
#include "session/selection_sets.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"

namespace styk::gui {
namespace {

class PickTest : public ::testing::Test {
 protected:
  PickTest() : doc(registry) {
    register_builtin_elements(registry);
    BlockInput box;
    box.size = {2, 1, 1};
    box.divisions = {2, 1, 1};
    box.type = "C3D8";
    box.name = "BOX";
    doc.apply(block_command(doc.model(), box, registry));
  }
  int node_at(double x, double y, double z) const {
    const Model& m = doc.model();
    for (int n = 0; n < m.node_count(); ++n)
      if (std::abs(m.coords[n][0] - x) + std::abs(m.coords[n][1] - y) +
              std::abs(m.coords[n][2] - z) <
          1e-12)
        return n;
    return -1;
  }
  // The element whose nodes all lie in x >= xmin (x <= xmax).
  int element_between(double xmin, double xmax) const {
    const Model& m = doc.model();
    for (int e = 0; e < m.element_count(); ++e) {
      bool inside = true;
      for (int k = 0; k < m.elements[e].node_count; ++k) {
        const double x = m.coords[m.element_nodes(e)[k]][0];
        inside = inside && x >= xmin - 1e-12 && x <= xmax + 1e-12;
      }
      if (inside) return e;
    }
    return -1;
  }
  // The 1-based face of element e whose corners all have coordinate `axis` equal to `value`.
  int face_on(const Scene& scene, int e, int axis, double value) const {
    const auto& faces = scene.skin()->formulations()[e]->faces();
    for (int f = 0; f < int(faces.size()); ++f) {
      bool on = true;
      for (int n : face_corner_nodes(scene, e, f))
        on = on && std::abs(doc.model().coords[n][axis] - value) < 1e-12;
      if (on) return f + 1;
    }
    return 0;
  }
  // The pixel of the centre of a face (the mean of its corners' pixels).
  static std::array<int, 2> face_pixel(const Scene& scene, int e, int face) {
    double x = 0, y = 0;
    const std::vector<int> corners = face_corner_nodes(scene, e, face - 1);
    for (int n : corners) {
      const auto p = scene.screen_position(n);
      x += p[0] / corners.size(), y += p[1] / corners.size();
    }
    return {int(std::floor(x)), int(std::floor(y))};
  }
  static std::array<int, 2> node_pixel(const Scene& scene, int n) {
    const auto p = scene.screen_position(n);
    return {int(std::floor(p[0])), int(std::floor(p[1]))};
  }

  ElementRegistry registry;
  Document doc;
};

TEST_F(PickTest, LookingAlongMinusXOnlyTheEndFaceAndItsNodesArePicked) {
  Scene scene;
  scene.rebuild(doc, {});
  ViewState view;
  view.spec.name = "+x";  // the eye on +x: the face x = 2 of the right element hides the rest
  scene.frame(400, 300, view);
  const Picker picker(scene);
  const int right = element_between(1, 2);
  ASSERT_GE(right, 0);
  const int end_face = face_on(scene, right, 0, 2.0);
  ASSERT_GT(end_face, 0);
  const auto centre = face_pixel(scene, right, end_face);
  const auto element = picker.pick(centre[0], centre[1], PickKind::Element);
  ASSERT_TRUE(element);
  EXPECT_EQ(element->element, right);
  const auto face = picker.pick(centre[0], centre[1], PickKind::Face);
  ASSERT_TRUE(face);
  EXPECT_EQ(face->element, right);
  EXPECT_EQ(face->face, end_face);
  // (0,1,1), (1,1,1) and (2,1,1) project to the same pixel; only the front one is picked.
  const int front = node_at(2, 1, 1);
  const auto p = node_pixel(scene, node_at(0, 1, 1));
  EXPECT_EQ(p, node_pixel(scene, front));
  const auto node = picker.pick(p[0], p[1], PickKind::Node, 4);
  ASSERT_TRUE(node);
  EXPECT_EQ(node->node, front);
  EXPECT_FALSE(picker.node_visible(node_at(0, 1, 1)));
  EXPECT_FALSE(picker.node_visible(node_at(1, 1, 1)));
  EXPECT_FALSE(picker.pick(2, 2, PickKind::Element));  // the picture's corner: nothing

  // A box over the whole picture: the 4 nodes of the end face, the right element, its end face.
  std::vector<int> nodes;
  for (const PickedItem& i : picker.pick_box(0, 0, 399, 299, PickKind::Node))
    nodes.push_back(i.node);
  std::sort(nodes.begin(), nodes.end());
  std::vector<int> expected{node_at(2, 0, 0), node_at(2, 1, 0), node_at(2, 0, 1), node_at(2, 1, 1)};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(nodes, expected);
  Selection elements(PickKind::Element);
  elements.apply(SelectOp::Replace, picker.pick_box(0, 0, 399, 299, PickKind::Element));
  EXPECT_EQ(elements.elements(), std::vector<int>{right});
  const auto faces = picker.pick_box(0, 0, 399, 299, PickKind::Face);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].face, end_face);
}

TEST_F(PickTest, IsoViewPicksTheTopFaceAndNeverTheHiddenOnes) {
  Scene scene;
  scene.rebuild(doc, {});
  scene.frame(640, 480, {});  // iso: the eye towards (1, -1, 1)
  const Picker picker(scene);
  const int left = element_between(0, 1);
  const int top = face_on(scene, left, 2, 1.0);
  const auto centre = face_pixel(scene, left, top);
  const auto face = picker.pick(centre[0], centre[1], PickKind::Face);
  ASSERT_TRUE(face);
  EXPECT_EQ(face->element, left);
  EXPECT_EQ(face->face, top);
  // The bottom face's centre lies behind the front faces: something else is picked there.
  const int bottom = face_on(scene, left, 2, 0.0);
  const auto hidden = face_pixel(scene, left, bottom);
  const auto in_front = picker.pick(hidden[0], hidden[1], PickKind::Face);
  ASSERT_TRUE(in_front);
  EXPECT_FALSE(in_front->element == left && in_front->face == bottom);
  // The far corner (0,1,0) is hidden, the near corner (2,0,1) visible and picked at its pixel.
  EXPECT_FALSE(picker.node_visible(node_at(0, 1, 0)));
  const auto far = node_pixel(scene, node_at(0, 1, 0));
  const auto far_pick = picker.pick(far[0], far[1], PickKind::Node, 3);
  EXPECT_TRUE(!far_pick || far_pick->node != node_at(0, 1, 0));
  const auto near = node_pixel(scene, node_at(2, 0, 1));
  const auto near_pick = picker.pick(near[0], near[1], PickKind::Node, 3);
  ASSERT_TRUE(near_pick);
  EXPECT_EQ(near_pick->node, node_at(2, 0, 1));
}

TEST_F(PickTest, SelectionAddsRemovesAndReplaces) {
  Selection s(PickKind::Node);
  const auto node = [](int n) {
    PickedItem i;
    i.node = n;
    return i;
  };
  s.apply(SelectOp::Replace, {node(5), node(2), node(5)});
  EXPECT_EQ(s.nodes(), (std::vector<int>{2, 5}));
  s.apply(SelectOp::Add, {node(3)});
  EXPECT_EQ(s.nodes(), (std::vector<int>{2, 3, 5}));
  s.apply(SelectOp::Remove, {node(2), node(9)});
  EXPECT_EQ(s.nodes(), (std::vector<int>{3, 5}));
  PickedItem face;
  face.kind = PickKind::Face;
  face.element = 1;
  face.face = 4;
  s.apply(SelectOp::Add, {face});  // another kind: ignored
  EXPECT_EQ(s.size(), 2u);
  s.set_kind(PickKind::Face);
  EXPECT_TRUE(s.empty());
  s.apply(SelectOp::Add, {face, face});
  ASSERT_EQ(s.faces().size(), 1u);
  EXPECT_EQ(s.faces()[0].face, 4);
}

TEST_F(PickTest, SelectionBecomesAnUndoableSetAndKeepsTheResults) {
  Results results;
  results.increments.emplace_back();
  results.increments[0].U.assign(doc.model().coords.size(), Vec3{0, 0, 0});
  doc.attach_results(results, "");
  Selection nodes(PickKind::Node);
  PickedItem a, b;
  a.node = node_at(2, 0, 0);
  b.node = node_at(2, 1, 1);
  nodes.apply(SelectOp::Replace, {a, b});
  doc.apply(set_from_selection_command(doc.model(), nodes, "tip"));
  const NodeSet* tip = doc.model().find_nset("TIP");
  ASSERT_TRUE(tip);
  EXPECT_EQ(tip->nodes, nodes.nodes());
  EXPECT_EQ(doc.history().undo_text(), "Add node set TIP");
  EXPECT_TRUE(doc.results());  // a set changes neither mesh nor analysis
  doc.undo();
  EXPECT_FALSE(doc.model().find_nset("TIP"));
  EXPECT_TRUE(doc.results());
  doc.redo();
  EXPECT_TRUE(doc.model().find_nset("TIP"));

  Selection faces(PickKind::Face);
  PickedItem f;
  f.kind = PickKind::Face;
  f.element = 1;
  f.face = 2;
  faces.apply(SelectOp::Replace, {f});
  doc.apply(set_from_selection_command(doc.model(), faces, "LOADED"));
  const Surface& surface = doc.model().surfaces.at("LOADED");
  EXPECT_EQ(surface.kind, Surface::Kind::ElementFaces);
  ASSERT_EQ(surface.faces.size(), 1u);
  EXPECT_EQ(surface.faces[0].element, 1);
  EXPECT_EQ(surface.faces[0].face, 2);
  Selection elements(PickKind::Element);
  PickedItem e;
  e.kind = PickKind::Element;
  e.element = 0;
  elements.apply(SelectOp::Replace, {e});
  doc.apply(set_from_selection_command(doc.model(), elements, "FIRST"));
  EXPECT_EQ(doc.model().find_elset("FIRST")->elements, std::vector<int>{0});
  doc.undo();
  EXPECT_FALSE(doc.model().find_elset("FIRST"));

  EXPECT_THROW(set_from_selection_command(doc.model(), Selection(PickKind::Node), "X"), InputError);
  EXPECT_THROW(set_from_selection_command(doc.model(), nodes, "1st"), InputError);
  try {
    set_from_selection_command(doc.model(), nodes, "box");  // the block's element set
    FAIL() << "a name in use was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("BOX exists already"), std::string::npos) << error.message();
  }
}

TEST_F(PickTest, TheSelectionIsDrawnAsMagentaMarkers) {
  Scene scene;
  scene.rebuild(doc, {});
  const std::size_t plain = scene.frame(400, 300, {}).overlay.triangles.size();
  Selection s(PickKind::Node);
  PickedItem n;
  n.node = node_at(2, 0, 1);
  s.apply(SelectOp::Replace, {n});
  scene.set_selection(s);
  const render::Frame& frame = scene.frame(400, 300, {});
  ASSERT_GT(frame.overlay.triangles.size(), plain);
  const render::OverlayVertex& last = frame.overlay.triangles.back();
  EXPECT_EQ(last.color[0], kHighlight.r);
  EXPECT_EQ(last.color[1], kHighlight.g);
  const auto p = scene.screen_position(n.node);
  EXPECT_LT(std::abs(last.x - p[0]), 10.0);
  EXPECT_LT(std::abs(last.y - p[1]), 10.0);
  // A selected element is outlined along the seen stretches of its 5 skin faces' edges (2
  // triangles = 6 vertices per stretch). Seen from iso (1, -1, 1) the corner (0, 1, 0) is hidden:
  // face x = 0 shows 2 edges (the 2 at the hidden corner are behind), y = 0 and z = 1 all 4,
  // y = 1 and z = 0 one each: 12, not the 5 x 4 = 20 drawn before markers were depth tested.
  Selection e(PickKind::Element);
  PickedItem item;
  item.kind = PickKind::Element;
  item.element = element_between(0, 1);
  e.apply(SelectOp::Replace, {item});
  scene.set_selection(e);
  EXPECT_EQ(scene.frame(400, 300, {}).overlay.triangles.size(), plain + 12 * 6);
}

// Issue 7: markers are depth tested with the picker's face-id buffer, so a selected node or face
// behind the front surface does not show through.
TEST_F(PickTest, MarkersOfHiddenNodesAndEdgesAreNotDrawn) {
  Scene scene;
  scene.rebuild(doc, {});
  const std::size_t plain = scene.frame(400, 300, {}).overlay.triangles.size();
  // The corner (0, 1, 0) is behind the box seen from iso (1, -1, 1); (2, 0, 1) is in front.
  Selection hidden(PickKind::Node);
  PickedItem n;
  n.node = node_at(0, 1, 0);
  hidden.apply(SelectOp::Replace, {n});
  scene.set_selection(hidden);
  EXPECT_EQ(scene.frame(400, 300, {}).overlay.triangles.size(), plain);
  n.node = node_at(2, 0, 1);
  hidden.apply(SelectOp::Add, {n});
  scene.set_selection(hidden);
  EXPECT_EQ(scene.frame(400, 300, {}).overlay.triangles.size(), plain + 2 * 6);  // rim + fill
  // The front face x = 2: its 4 edges, one stretch each. The back face x = 0: only the 2 edges
  // it shares with the front faces y = 0 and z = 1.
  const auto face_selection = [&](int element, int face) {
    Selection s(PickKind::Face);
    PickedItem f;
    f.kind = PickKind::Face;
    f.element = element;
    f.face = face;
    s.apply(SelectOp::Replace, {f});
    return s;
  };
  const int right = element_between(1, 2), left = element_between(0, 1);
  scene.set_selection(face_selection(right, face_on(scene, right, 0, 2.0)));
  EXPECT_EQ(scene.frame(400, 300, {}).overlay.triangles.size(), plain + 4 * 6);
  scene.set_selection(face_selection(left, face_on(scene, left, 0, 0.0)));
  EXPECT_EQ(scene.frame(400, 300, {}).overlay.triangles.size(), plain + 2 * 6);
  // Turned to look from -x, the same face is in front: all 4 edges.
  ViewState from_minus_x;
  from_minus_x.spec.name = "-x";
  EXPECT_EQ(scene.frame(400, 300, from_minus_x).overlay.triangles.size(), plain + 4 * 6);
}

// The markers' depth test rasterises only the faces around the selection (issue 7: the picker was
// rebuilt over the whole skin every frame while something was selected). Inside its region a
// region picker must answer exactly like the whole one. An 8 x 4 x 4 box seen from iso.
TEST(PickRegion, ARegionPickerAnswersLikeTheWholePickerInsideItsRegion) {
  ElementRegistry registry;
  register_builtin_elements(registry);
  Document doc(registry);
  BlockInput box;
  box.size = {8, 4, 4};
  box.divisions = {8, 4, 4};
  box.type = "C3D8";
  box.name = "BOX";
  doc.apply(block_command(doc.model(), box, registry));
  Scene scene;
  scene.rebuild(doc, {});
  scene.frame(640, 480, {});
  const Picker whole(scene);
  ASSERT_EQ(whole.face_count(), 2u * (8 * 4 + 8 * 4 + 4 * 4));  // the skin: 160 faces
  int visible = 0;
  for (int n = 0; n < doc.model().node_count(); ++n) {
    const auto p = scene.screen_position(n);
    const render::PixelRect region{int(std::floor(p[0])), int(std::floor(p[1])), 1, 1};
    const Picker part(scene, region);
    ASSERT_EQ(part.node_visible(n), whole.node_visible(n)) << "node " << n;
    visible += whole.node_visible(n) ? 1 : 0;
    // About one face's neighbourhood, not the skin: at most the 12 faces around a node (a
    // projected face spans ~40 px here, so only the faces meeting the node's pixel +- 3 count).
    EXPECT_LE(part.face_count(), 12u) << "node " << n;
    EXPECT_GE(part.face_count(), whole.node_visible(n) ? 1u : 0u);
  }
  // Seen from iso 3 sides show: (9 x 5) + (9 x 5) + (5 x 5) - 9 - 5 - 5 + 1 = 97 nodes.
  EXPECT_EQ(visible, 97);
  // A region in the empty corner of the picture rasterises no face at all.
  EXPECT_EQ(Picker(scene, render::PixelRect{0, 0, 4, 4}).face_count(), 0u);
}

// Bars (line elements, drawn since issue 7's line objects) are picked along their drawn width as
// elements, never as faces, and hidden behind solids like faces are; a picked bar is traced.
TEST_F(PickTest, BarsArePickedAsElementsAndHiddenBehindSolids) {
  LineInput out;  // beside the block along +x: seen from +y
  out.name = "OUT";
  out.a = {3, 0.5, 0.5};
  out.b = {5, 0.5, 0.5};
  out.divisions = 2;
  doc.apply(line_command(doc.model(), out, registry));
  LineInput behind;  // behind the end face x = 2 seen from +x
  behind.name = "BEHIND";
  behind.a = {-1, 0.2, 0.5};
  behind.b = {-1, 0.8, 0.5};
  behind.divisions = 1;
  doc.apply(line_command(doc.model(), behind, registry));
  const ElementSet& out_set = *doc.model().find_elset("OUT");
  const int behind_bar = doc.model().find_elset("BEHIND")->elements.front();
  Scene scene;
  scene.rebuild(doc, {});
  ViewState from_plus_y;
  from_plus_y.spec.name = "+y";
  scene.frame(400, 300, from_plus_y);
  const Picker seen(scene);
  const auto middle = node_pixel(scene, node_at(4, 0.5, 0.5));  // between the two OUT bars
  const auto quarter = [&](int sign) {  // a pixel on the bar, 1 px off its axis
    const auto a = scene.screen_position(node_at(3, 0.5, 0.5));
    const auto b = scene.screen_position(node_at(4, 0.5, 0.5));
    return std::array<int, 2>{int(std::floor(0.5 * (a[0] + b[0]))),
                              int(std::floor(0.5 * (a[1] + b[1]))) + sign};
  };
  for (int sign : {-1, 1}) {
    const auto p = quarter(sign);
    const auto element = seen.pick(p[0], p[1], PickKind::Element);
    ASSERT_TRUE(element) << sign;
    EXPECT_EQ(element->element, out_set.elements.front());
    EXPECT_FALSE(seen.pick(p[0], p[1], PickKind::Face));  // a bar has no face
  }
  const auto node = seen.pick(middle[0], middle[1], PickKind::Node, 4);
  ASSERT_TRUE(node);
  EXPECT_EQ(node->node, node_at(4, 0.5, 0.5));
  EXPECT_TRUE(seen.node_visible(node_at(5, 0.5, 0.5)));
  std::vector<int> boxed;
  for (const PickedItem& i : seen.pick_box(0, 0, 399, 299, PickKind::Element))
    boxed.push_back(i.element);
  EXPECT_NE(std::find(boxed.begin(), boxed.end(), out_set.elements.back()), boxed.end());
  for (const PickedItem& i : seen.pick_box(0, 0, 399, 299, PickKind::Face)) EXPECT_GE(i.face, 1);
  // Seen from +x the BEHIND bar lies behind the block's end face: its pixels pick the block.
  ViewState from_plus_x;
  from_plus_x.spec.name = "+x";
  scene.frame(400, 300, from_plus_x);
  const Picker hidden(scene);
  const auto a = scene.screen_position(node_at(-1, 0.2, 0.5));
  const auto b = scene.screen_position(node_at(-1, 0.8, 0.5));
  const int hx = int(std::floor(0.5 * (a[0] + b[0]))), hy = int(std::floor(0.5 * (a[1] + b[1])));
  const auto front = hidden.pick(hx, hy, PickKind::Element);
  ASSERT_TRUE(front);
  EXPECT_NE(front->element, behind_bar);
  EXPECT_FALSE(hidden.node_visible(node_at(-1, 0.2, 0.5)));
  // A selected bar is traced: seen from +y one stretch along it (6 vertices), from +x nothing.
  const std::size_t plain = scene.frame(400, 300, from_plus_y).overlay.triangles.size();
  Selection bar(PickKind::Element);
  PickedItem item;
  item.kind = PickKind::Element;
  item.element = out_set.elements.front();
  bar.apply(SelectOp::Replace, {item});
  scene.set_selection(bar);
  EXPECT_EQ(scene.frame(400, 300, from_plus_y).overlay.triangles.size(), plain + 6);
  item.element = behind_bar;
  bar.apply(SelectOp::Replace, {item});
  scene.set_selection(bar);
  const std::size_t plain_x = [&] {
    Scene bare;
    bare.rebuild(doc, {});
    return bare.frame(400, 300, from_plus_x).overlay.triangles.size();
  }();
  EXPECT_EQ(scene.frame(400, 300, from_plus_x).overlay.triangles.size(), plain_x);
}

TEST_F(PickTest, TheSelectionIsDescribedWithIdsCoordinatesAndValues) {
  Results results;
  results.increments.emplace_back();
  for (const Vec3& x : doc.model().coords) results.increments[0].U.push_back({0, 0, 0.5 * x[0]});
  doc.attach_results(results, "");
  Scene scene;
  DisplaySettings settings;
  settings.field = "U.z";
  scene.rebuild(doc, settings);
  Selection s(PickKind::Node);
  PickedItem n;
  n.node = node_at(2, 1, 1);
  s.apply(SelectOp::Replace, {n});
  const Id id = doc.model().node_ids[n.node];
  // U.z = 0.5 x = 1 at x = 2, in the legend's format.
  EXPECT_EQ(selection_summary(scene, s),
            "node " + std::to_string(id) + " (2, 1, 1)  U.z = 1.000E+00");
  Selection e(PickKind::Element);
  PickedItem item;
  item.kind = PickKind::Element;
  item.element = element_between(1, 2);
  e.apply(SelectOp::Replace, {item});
  // The element's value: the mean of U.z over its 8 nodes, x = 1 and 2: 0.75.
  const std::vector<std::string> lines = describe_selection(scene, e);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "element " + std::to_string(doc.model().elements[item.element].id) +
                          " C3D8, centroid (1.5, 0.5, 0.5)  U.z = 7.500E-01");
  Selection f(PickKind::Face);
  item.kind = PickKind::Face;
  item.face = 3;
  f.apply(SelectOp::Replace, {item});
  EXPECT_EQ(selection_summary(scene, f),
            "element " + std::to_string(doc.model().elements[item.element].id) + " C3D8 face S3");
}

}  // namespace
}  // namespace styk::gui
