// Plane and line geometry objects (SPEC §5: "geometry objects (lines, planes, volumes) meshed
// isoparametrically with user densities (hex and 4-node quad)"): node and element counts, the
// coordinates of a graded line, the area of a meshed patch, sections, undo and refusals.
#include <gtest/gtest.h>

#include <cmath>

#include "session/document.hpp"
#include "session/geometry_objects.hpp"
#include "session/scene.hpp"
#include "styk/elements/builtin.hpp"

namespace styk::gui {
namespace {

class GuiGeometryObjectTest : public ::testing::Test {
 protected:
  GuiGeometryObjectTest() { register_builtin_elements(registry); }
  // Sum of the corner-polygon areas of the elements of set `name` (x-y plane).
  static double area(const Model& m, const std::string& name) {
    double sum = 0.0;
    for (int e : m.find_elset(name)->elements) {
      const int* n = m.element_nodes(e);
      for (int k = 0; k < 4; ++k) {
        const Vec3& p = m.coords[n[k]];
        const Vec3& q = m.coords[n[(k + 1) % 4]];
        sum += 0.5 * (p[0] * q[1] - q[0] * p[1]);
      }
    }
    return sum;
  }
  ElementRegistry registry;
};

PlaneInput rectangle(const std::string& type) {
  PlaneInput in;
  in.name = "plate";
  in.points = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 0}};
  in.divisions_u = 4;
  in.divisions_v = 2;
  in.type = type;
  return in;
}

TEST_F(GuiGeometryObjectTest, FourAndEightNodePlanes) {
  const Model four = model_with_plane(Model{}, rectangle("CPS4"), registry);
  // 4 x 2 elements: (4 + 1) x (2 + 1) = 15 nodes.
  EXPECT_EQ(four.element_count(), 8);
  EXPECT_EQ(four.node_count(), 15);
  EXPECT_EQ(four.elements[0].type, "CPS4");
  ASSERT_NE(four.find_nset("PLATE"), nullptr);
  EXPECT_EQ(four.find_nset("PLATE")->nodes.size(), 15u);
  EXPECT_NEAR(area(four, "PLATE"), 8.0, 1e-12);

  const Model eight = model_with_plane(Model{}, rectangle("CPE8"), registry);
  // 8-node quads: a 9 x 5 grid without the 4 x 2 element centres = 37 nodes.
  EXPECT_EQ(eight.element_count(), 8);
  EXPECT_EQ(eight.node_count(), 37);
  EXPECT_EQ(eight.elements[0].type, "CPE8");
  EXPECT_EQ(eight.elements[0].node_count, 8);
}

TEST_F(GuiGeometryObjectTest, GradedTrapezoidKeepsItsArea) {
  // Trapezoid with parallel sides 6 and 3, height 3: area (6 + 3) / 2 x 3 = 13.5. A straight-sided
  // patch is tiled exactly by its elements whatever the grading (tolerance 1e-12 relative).
  PlaneInput in;
  in.name = "trap";
  in.points = {{0, 0, 0}, {6, 0, 0}, {4, 3, 0}, {1, 3, 0}};
  in.divisions_u = 5;
  in.divisions_v = 3;
  in.grading_u = 3.0;
  in.grading_v = 0.5;
  const Model m = model_with_plane(Model{}, in, registry);
  EXPECT_EQ(m.element_count(), 15);
  EXPECT_NEAR(area(m, "TRAP"), 13.5, 13.5e-12);
}

TEST_F(GuiGeometryObjectTest, MidSidePointsCurveTheSides) {
  // One CPS8 element: its nodes are the 8 given points (side 1-2 bulges down to y = -0.5).
  PlaneInput in = rectangle("CPS8");
  in.divisions_u = 1;
  in.divisions_v = 1;
  in.points.insert(in.points.end(), {{2, -0.5, 0}, {4, 1, 0}, {2, 2, 0}, {0, 1, 0}});
  const Model m = model_with_plane(Model{}, in, registry);
  ASSERT_EQ(m.element_count(), 1);
  const int* n = m.element_nodes(0);
  for (int k = 0; k < 8; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.coords[n[k]][c], in.points[k][c], 1e-12) << k;
}

TEST_F(GuiGeometryObjectTest, GradedLineOfTrusses) {
  // 4 intervals from 0 to 10 with last / first = 8: lengths grow by 8^(1/3) = 2, so the first is
  // 10 / (1 + 2 + 4 + 8) = 2/3 and the nodes lie at 0, 2/3, 2, 14/3, 10 (tolerance 1e-12).
  LineInput in;
  in.name = "bar";
  in.a = {0, 1, 2};
  in.b = {10, 1, 2};
  in.divisions = 4;
  in.grading = 8.0;
  const Model m = model_with_line(Model{}, in, registry);
  ASSERT_EQ(m.node_count(), 5);
  ASSERT_EQ(m.element_count(), 4);
  EXPECT_EQ(m.elements[0].type, "T3D2");
  const double expected[] = {0.0, 2.0 / 3.0, 2.0, 14.0 / 3.0, 10.0};
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(m.coords[k][0], expected[k], 1e-12);
    EXPECT_NEAR(m.coords[k][1], 1.0, 1e-12);
    EXPECT_NEAR(m.coords[k][2], 2.0, 1e-12);
  }
  for (int e = 0; e < 4; ++e) {
    EXPECT_EQ(m.element_nodes(e)[0], e);
    EXPECT_EQ(m.element_nodes(e)[1], e + 1);
  }
}

TEST_F(GuiGeometryObjectTest, SectionsUndoAndIdsAfterTheModel) {
  Document doc(registry);
  Material steel;
  steel.name = "STEEL";
  steel.young = 2e5;
  steel.poisson = 0.3;
  doc.apply(make_add_material(steel));
  PlaneInput plate = rectangle("CPS4");
  plate.material = "steel";
  plate.thickness = 2.5;
  doc.apply(plane_command(doc.model(), plate, registry));
  LineInput bar;
  bar.name = "bar";
  bar.a = {0, 3, 0};
  bar.b = {4, 3, 0};
  bar.material = "STEEL";
  bar.area = 0.75;
  doc.apply(line_command(doc.model(), bar, registry));
  const Model& m = doc.model();
  ASSERT_EQ(m.sections.size(), 2u);
  EXPECT_EQ(m.sections[0].elset, "PLATE");
  EXPECT_DOUBLE_EQ(*m.sections[0].thickness, 2.5);
  EXPECT_EQ(m.sections[1].elset, "BAR");
  EXPECT_DOUBLE_EQ(*m.sections[1].thickness, 0.75);
  // The line's ids follow the plate's: elements 9..12, nodes 16..20.
  EXPECT_EQ(m.element_count(), 12);
  EXPECT_EQ(m.elements[8].id, 9);
  EXPECT_EQ(m.node_ids[15], 16);
  for (int e : m.find_elset("BAR")->elements) EXPECT_EQ(m.elements[e].section, 1);
  EXPECT_EQ(doc.history().undo_text(), "Line BAR");
  doc.undo();
  EXPECT_EQ(doc.model().element_count(), 8);
  doc.undo();
  EXPECT_EQ(doc.model().element_count(), 0);
}

// The view draws the new objects: the plate's 15 nodes, then 5 more for the line.
TEST_F(GuiGeometryObjectTest, PlaneAndLineAreDrawn) {
  Document doc(registry);
  doc.apply(plane_command(doc.model(), rectangle("CPS4"), registry));
  Scene scene;
  scene.rebuild(doc, DisplaySettings{});
  ASSERT_FALSE(scene.empty());
  EXPECT_GT(scene.triangle_count(), 0u);
  EXPECT_EQ(scene.skin()->visible_nodes().size(), 15u);
  LineInput bar;
  bar.a = {0, 3, 0};
  bar.b = {4, 3, 0};
  doc.apply(line_command(doc.model(), bar, registry));
  scene.rebuild(doc, DisplaySettings{});
  // The trusses add their 5 nodes (render draws no truss faces: they show as nodes).
  EXPECT_EQ(scene.skin()->visible_nodes().size(), 20u);
}

TEST_F(GuiGeometryObjectTest, RefusesBadInput) {
  const Model empty;
  auto refused = [&](PlaneInput in) {
    EXPECT_THROW(model_with_plane(empty, in, registry), InputError);
  };
  PlaneInput in = rectangle("CPS4");
  std::swap(in.points[1], in.points[3]);  // clockwise
  refused(in);
  in = rectangle("CPS4");
  in.points[2][2] = 1.0;  // off the x-y plane
  refused(in);
  in = rectangle("CPS4");
  in.points.pop_back();  // 3 points
  refused(in);
  in = rectangle("C3D8");
  refused(in);
  in = rectangle("CPS4");
  in.divisions_u = 0;
  refused(in);
  in = rectangle("CPS4");
  in.grading_v = 0.0;
  refused(in);
  in = rectangle("CPS4");
  in.material = "NOPE";
  refused(in);
  in = rectangle("CPS4");
  in.name = "2x";
  refused(in);
  const Model plate = model_with_plane(empty, rectangle("CPS4"), registry);
  EXPECT_THROW(model_with_plane(plate, rectangle("CPS4"), registry), InputError);  // name taken

  LineInput line;
  line.b = line.a;  // zero length
  EXPECT_THROW(model_with_line(empty, line, registry), InputError);
  line = LineInput{};
  line.divisions = 0;
  EXPECT_THROW(model_with_line(empty, line, registry), InputError);
  line = LineInput{};
  line.grading = -1.0;
  EXPECT_THROW(model_with_line(empty, line, registry), InputError);
  line = LineInput{};
  line.a[0] = std::nan("");
  EXPECT_THROW(model_with_line(empty, line, registry), InputError);
}

}  // namespace
}  // namespace styk::gui
