// Shells and beams in the desktop program (docs/gui.md "Plane and line geometry objects"): a
// Plane object of shells in space with a *SHELL SECTION (thickness, offset), a Line object of
// beams with a *BEAM SECTION, boundary conditions and loads on the rotations (dofs 4-6), and the
// section forces and moments SF/SM as fields of the view after a solve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "refusal.hpp"
#include "session/document.hpp"
#include "session/geometry_objects.hpp"
#include "session/results_navigation.hpp"
#include "session/scene.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::gui {
namespace {

using test::refusal;

class GuiStructuralTest : public ::testing::Test {
 protected:
  GuiStructuralTest() : doc(registry) { register_builtin_elements(registry); }
  void add_material(double poisson) {
    MaterialInput steel;
    steel.name = "STEEL";
    steel.young = 210000.0;
    steel.poisson = poisson;
    doc.apply(material_command(doc.model(), steel));
  }
  ElementRegistry registry;
  Document doc;
};

// A plane of S9 shells tilted in space (the x-z plane turned about x): 2 x 2 elements have 25
// nodes, every node on the plane; the section is a *SHELL SECTION of thickness 0.5 and offset
// 0.25; the sides are node sets.
TEST_F(GuiStructuralTest, ShellPlaneInSpaceWithItsSection) {
  add_material(0.3);
  PlaneInput in;
  in.name = "skin";
  in.points = {{0, 0, 0}, {4, 0, 0}, {4, 3, 3}, {0, 3, 3}};
  in.divisions_u = 2, in.divisions_v = 2;
  in.type = "S9";
  in.material = "STEEL";
  in.thickness = 0.5;
  in.offset = 0.25;
  doc.apply(plane_command(doc.model(), in, registry));
  const Model& m = doc.model();
  EXPECT_EQ(m.element_count(), 4);
  EXPECT_EQ(m.node_count(), 25);
  EXPECT_EQ(m.elements[0].type, "S9");
  for (const Vec3& x : m.coords) EXPECT_NEAR(x[1], x[2], 1e-12);  // the plane y = z
  ASSERT_EQ(m.sections.size(), 1u);
  ASSERT_TRUE(m.sections[0].shell.has_value());
  EXPECT_DOUBLE_EQ(*m.sections[0].thickness, 0.5);
  EXPECT_DOUBLE_EQ(m.sections[0].shell->offset, 0.25);
  for (const char* side : {"SKIN_SIDE1", "SKIN_SIDE2", "SKIN_SIDE3", "SKIN_SIDE4"}) {
    ASSERT_NE(m.find_nset(side), nullptr) << side;
    EXPECT_EQ(m.find_nset(side)->nodes.size(), 5u) << side;
  }
  // The view draws the shells as slabs: the scene holds them, with triangles.
  Scene scene;
  scene.rebuild(doc, DisplaySettings{});
  ASSERT_FALSE(scene.empty());
  EXPECT_EQ(scene.skin()->layers()[0].shells.size(), 4u);
  EXPECT_GT(scene.triangle_count(), 0u);
}

// A line of B32 beams: 4 elements have 9 nodes, the middle node second and at mid-length; the
// section is a PIPE *BEAM SECTION with the given first section axis.
TEST_F(GuiStructuralTest, BeamLineWithItsSection) {
  add_material(0.3);
  LineInput in;
  in.name = "tube";
  in.a = {0, 0, 0};
  in.b = {8, 0, 0};
  in.divisions = 4;
  in.type = "B32";
  in.material = "STEEL";
  in.shape = "PIPE";
  in.dimensions = {0.5, 0.05};
  in.direction = {0, 1, 0};
  doc.apply(line_command(doc.model(), in, registry));
  const Model& m = doc.model();
  EXPECT_EQ(m.element_count(), 4);
  EXPECT_EQ(m.node_count(), 9);
  for (int e = 0; e < 4; ++e) {
    const int* n = m.element_nodes(e);
    EXPECT_NEAR(m.coords[n[1]][0], 0.5 * (m.coords[n[0]][0] + m.coords[n[2]][0]), 1e-12);
    EXPECT_NEAR(m.coords[n[2]][0] - m.coords[n[0]][0], 2.0, 1e-12);
  }
  ASSERT_EQ(m.sections.size(), 1u);
  ASSERT_TRUE(m.sections[0].beam.has_value());
  EXPECT_EQ(m.sections[0].beam->shape, BeamShape::Pipe);
  EXPECT_EQ(m.sections[0].beam->dimensions, (std::vector<double>{0.5, 0.05}));
  EXPECT_EQ(m.sections[0].beam->direction, (Vec3{0, 1, 0}));
  Scene scene;
  scene.rebuild(doc, DisplaySettings{});
  EXPECT_EQ(scene.skin()->layers()[0].beams.size(), 4u);
}

TEST_F(GuiStructuralTest, RefusesBadShellsAndBeams) {
  add_material(0.3);
  PlaneInput plane;
  plane.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 1}};
  plane.type = "S4";
  plane.material = "STEEL";
  plane.offset = 0.7;
  EXPECT_EQ(refusal([&] { model_with_plane(doc.model(), plane, registry); }),
            "the offset must lie within -0.5 .. 0.5 (thicknesses from the mid-surface)");
  plane.offset = 0.0;
  plane.type = "CPS4";
  EXPECT_EQ(refusal([&] { model_with_plane(doc.model(), plane, registry); }),
            "plane elements lie in the x-y plane: every point needs z = 0 (shells may lie "
            "anywhere)");
  plane.type = "S4";
  plane.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};  // crossed: the patch folds
  EXPECT_EQ(refusal([&] { model_with_plane(doc.model(), plane, registry); }),
            "the plane folds: give the corners in order round the patch and mid-side points "
            "that keep the sides apart");
  LineInput line;
  line.type = "B31";
  line.material = "STEEL";
  line.shape = "PIPE";
  line.dimensions = {0.1, 0.2};  // the wall thicker than the radius
  EXPECT_NE(refusal([&] { model_with_line(doc.model(), line, registry); }), "(accepted)");
  line.dimensions = {0.1, 0.02};
  line.direction = {1, 0, 0};  // along the line
  EXPECT_EQ(refusal([&] { model_with_line(doc.model(), line, registry); }),
            "the first section axis runs along the line: give a direction across it");
  line.direction = {0, 0, -1};
  line.shape = "HEX";
  EXPECT_EQ(refusal([&] { model_with_line(doc.model(), line, registry); }),
            "beam section HEX is not RECT, CIRC, PIPE or BOX");
  line.shape = "PIPE";
  line.type = "C3D8";
  EXPECT_EQ(refusal([&] { model_with_line(doc.model(), line, registry); }),
            "element type C3D8 cannot be meshed on a line; use T3D2, B31, B31R, B32 or B32R");
}

// Moments and rotations through the dialogs' commands, solved, and SF/SM shown: a cantilever
// plate of S4 shells (10 x 2, t = 0.5, E = 210000, nu = 0 so that the clamped root does not
// restrain an anticlastic curvature), clamped on dofs 1-6 at its root, loaded by a moment of 2
// about +y at its tip (*CLOAD dof 5, split over the tip's two nodes). Pure bending (beam theory,
// exact for the element): M11 = 2 / 2 = 1 per unit width everywhere, so the view's SM.1 spans
// 1 .. 1 (tolerance 1e-9), and the tip rotates by 12 m L / (E t^3) = 12 x 1 x 10 / (210000 x
// 0.125) = 4.5714e-3 (1e-9 relative). A rotation dof on a static step is accepted; the fields
// SF.1 .. SM.3 are offered after the solve.
TEST_F(GuiStructuralTest, MomentsRotationsAndSectionForces) {
  add_material(0.0);
  PlaneInput in;
  in.name = "plate";
  in.points = {{0, 0, 0}, {10, 0, 0}, {10, 2, 0}, {0, 2, 0}};
  in.divisions_u = 5, in.divisions_v = 1;
  in.type = "S4";
  in.material = "STEEL";
  in.thickness = 0.5;
  doc.apply(plane_command(doc.model(), in, registry));
  doc.apply(step_command(doc.model(), StepInput{}));
  doc.apply(boundary_command(doc.model(), BoundaryInput{"PLATE_SIDE4", 1, 6, 0.0, -1}));
  doc.apply(cload_command(doc.model(), CloadInput{"PLATE_SIDE2", 5, 2.0, true, 0}));
  const Model& m = doc.model();
  ASSERT_EQ(m.steps.size(), 1u);
  ASSERT_EQ(m.steps[0].cloads.size(), 2u);
  EXPECT_EQ(m.steps[0].cloads[0].dof, 5);
  EXPECT_DOUBLE_EQ(m.steps[0].cloads[0].value, 1.0);
  EXPECT_EQ(m.boundaries.size(), 12u);  // 2 root nodes x 6 dofs
  doc.attach_results(run_static_analysis(m, registry, SolveOptions{}, nullptr, nullptr), "");
  const IncrementResult& inc = doc.results()->increments.back();
  const int tip = m.find_nset("PLATE_SIDE2")->nodes[0];
  const double rotation = 12.0 * 1.0 * 10.0 / (210000.0 * 0.125);
  EXPECT_NEAR(inc.UR[tip][1], rotation, 1e-9 * rotation);

  const std::vector<std::string> fields = available_fields(m, inc);
  for (const char* f : {"SF.1", "SF.2", "SF.3", "SM.1", "SM.2", "SM.3"})
    EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
  Scene scene;
  DisplaySettings settings;
  settings.field = "SM.1";
  scene.rebuild(doc, settings);
  EXPECT_NEAR(scene.colors().min, 1.0, 1e-9);
  EXPECT_NEAR(scene.colors().max, 1.0, 1e-9);
  settings.field = "SM.2";
  scene.rebuild(doc, settings);
  EXPECT_NEAR(scene.colors().min, 0.0, 1e-9);
  EXPECT_NEAR(scene.colors().max, 0.0, 1e-9);
  // S.11 on the top and bottom fibres: +-6 m / t^2 = +-24.
  settings.field = "S.11";
  settings.shell_fibre = render::ShellFibre::Bottom;
  scene.rebuild(doc, settings);
  EXPECT_NEAR(scene.colors().min, -24.0, 24e-9);
  EXPECT_NEAR(scene.colors().max, -24.0, 24e-9);
}

// The dof checks: a rotation is a dof of a static step, a temperature is not; 7 is nothing.
TEST_F(GuiStructuralTest, RotationDofsFitStaticSteps) {
  add_material(0.3);
  LineInput line;
  line.type = "B31";
  line.material = "STEEL";
  line.dimensions = {0.1, 0.2};
  doc.apply(line_command(doc.model(), line, registry));
  doc.apply(step_command(doc.model(), StepInput{}));
  EXPECT_EQ(refusal([&] {
              doc.apply(boundary_command(doc.model(), BoundaryInput{"BAR", 4, 6, 0.0, 0}));
            }),
            "(accepted)");
  EXPECT_EQ(refusal([&] {
              doc.apply(cload_command(doc.model(), CloadInput{"BAR", 6, 1.0, false, 0}));
            }),
            "(accepted)");
  EXPECT_EQ(doc.model().steps[0].cloads.back().dof, 6);
  EXPECT_EQ(refusal([&] {
              boundary_command(doc.model(), BoundaryInput{"BAR", 7, 7, 0.0, 0});
            }),
            "first dof must be 1, 2, 3 (x, y, z), 4, 5, 6 (rotations), 11 (temperature) or 9 "
            "(electric potential), not 7");
}

}  // namespace
}  // namespace styk::gui
