// Curved shell objects in the desktop program (docs/gui.md "Shell surfaces"): the cylindrical
// panel of the Scordelis-Lo roof and the pinched hemisphere with its hole, as the Shell surface
// dialog creates them (session/shell_surfaces.hpp): every node on the surface, the element and
// node counts of the mesh, the side sets, the *SHELL SECTION, and the refusals of bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "refusal.hpp"
#include "session/document.hpp"
#include "session/shell_surfaces.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"

namespace styk::gui {
namespace {

using test::refusal;

constexpr double kPi = 3.14159265358979323846;

class GuiShellSurfaceTest : public ::testing::Test {
 protected:
  GuiShellSurfaceTest() : doc(registry) {
    register_builtin_elements(registry);
    MaterialInput steel;
    steel.name = "STEEL";
    steel.young = 4.32e8;
    steel.poisson = 0.0;
    doc.apply(material_command(doc.model(), steel));
  }
  ElementRegistry registry;
  Document doc;
};

// The Scordelis-Lo roof (R = 25, L = 50, 80 degrees) of 4 x 4 S8R: (2*4+1)^2 - 4*4 = 65 nodes
// (the 8-node elements have no centre node), every node at distance R from the y axis (1e-9 R),
// within +-40 degrees of +z and 0 <= y <= 50; the straight edges y = 0 and y = 50 are the sets
// ROOF_SIDE1 and ROOF_SIDE3 (9 nodes each), the curved free edges SIDE2 / SIDE4 at +-40 degrees.
TEST_F(GuiShellSurfaceTest, CylindricalPanelLiesOnTheCylinder) {
  ShellSurfaceInput in;
  in.name = "roof";
  in.divisions_u = 4, in.divisions_v = 4;
  in.type = "S8R";
  in.material = "STEEL";
  in.thickness = 0.25;
  doc.apply(shell_surface_command(doc.model(), in, registry));
  const Model& m = doc.model();
  EXPECT_EQ(m.element_count(), 16);
  EXPECT_EQ(m.node_count(), 65);
  EXPECT_EQ(m.elements[0].type, "S8R");
  const double half = 40.0 * kPi / 180.0;
  for (const Vec3& x : m.coords) {
    EXPECT_NEAR(std::hypot(x[0], x[2]), 25.0, 1e-9 * 25.0);
    EXPECT_GE(x[1], -1e-12);
    EXPECT_LE(x[1], 50.0 + 1e-12);
    EXPECT_LE(std::abs(std::atan2(x[0], x[2])), half + 1e-12);
  }
  for (const char* side : {"ROOF_SIDE1", "ROOF_SIDE3"}) {
    const NodeSet* set = m.find_nset(side);
    ASSERT_NE(set, nullptr) << side;
    EXPECT_EQ(set->nodes.size(), 9u) << side;
    const double y = std::string(side) == "ROOF_SIDE1" ? 0.0 : 50.0;
    for (const int n : set->nodes) EXPECT_NEAR(m.coords[n][1], y, 1e-9) << side;
  }
  const NodeSet* edge = m.find_nset("ROOF_SIDE2");
  ASSERT_NE(edge, nullptr);
  for (const int n : edge->nodes)
    EXPECT_NEAR(std::abs(std::atan2(m.coords[n][0], m.coords[n][2])), half, 1e-9);
  ASSERT_EQ(m.sections.size(), 1u);
  ASSERT_TRUE(m.sections[0].shell.has_value());
  EXPECT_DOUBLE_EQ(*m.sections[0].thickness, 0.25);
  ASSERT_NE(m.find_elset("ROOF"), nullptr);
}

// A closed cylinder (360 degrees) shares its seam: 6 x 2 S4 have 6 x 3 nodes and no SIDE2/4.
TEST_F(GuiShellSurfaceTest, FullCylinderSharesItsSeam) {
  ShellSurfaceInput in;
  in.name = "tube";
  in.angle = 360.0;
  in.divisions_u = 6, in.divisions_v = 2;
  in.type = "S4";
  doc.apply(shell_surface_command(doc.model(), in, registry));
  const Model& m = doc.model();
  EXPECT_EQ(m.element_count(), 12);
  EXPECT_EQ(m.node_count(), 18);
  EXPECT_EQ(m.find_nset("TUBE_SIDE2"), nullptr);
  EXPECT_NE(m.find_nset("TUBE_SIDE1"), nullptr);
}

// MacNeal-Harder's pinched hemisphere: R = 10, an 18-degree hole, a 90-degree quarter, 4 x 4 S4
// (25 nodes): every node on the sphere (1e-9 R), none above the hole's rim z = R cos 18, in the
// quarter x, y >= 0; the equator (SIDE1, 5 nodes) at z = 0, the rim (SIDE3) at z = R cos 18.
TEST_F(GuiShellSurfaceTest, HemisphereLiesOnTheSphereBelowItsHole) {
  ShellSurfaceInput in;
  in.name = "dome";
  in.kind = ShellSurfaceKind::Hemisphere;
  in.radius = 10.0;
  in.divisions_u = 4, in.divisions_v = 4;
  in.type = "S4";
  in.material = "STEEL";
  in.thickness = 0.04;
  doc.apply(shell_surface_command(doc.model(), in, registry));
  const Model& m = doc.model();
  EXPECT_EQ(m.element_count(), 16);
  EXPECT_EQ(m.node_count(), 25);
  const double rim = 10.0 * std::cos(18.0 * kPi / 180.0);
  for (const Vec3& x : m.coords) {
    EXPECT_NEAR(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), 10.0, 1e-9 * 10.0);
    EXPECT_LE(x[2], rim + 1e-9);
    EXPECT_GE(x[0], -1e-9);
    EXPECT_GE(x[1], -1e-9);
  }
  const NodeSet* equator = m.find_nset("DOME_SIDE1");
  const NodeSet* hole = m.find_nset("DOME_SIDE3");
  ASSERT_NE(equator, nullptr);
  ASSERT_NE(hole, nullptr);
  EXPECT_EQ(equator->nodes.size(), 5u);
  for (const int n : equator->nodes) EXPECT_NEAR(m.coords[n][2], 0.0, 1e-9);
  for (const int n : hole->nodes) EXPECT_NEAR(m.coords[n][2], rim, 1e-9);
}

TEST_F(GuiShellSurfaceTest, RefusesBadSurfaces) {
  ShellSurfaceInput in;
  in.angle = 0.0;
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "the angle must be > 0 and <= 360 degrees, not 0");
  in.angle = 80.0;
  in.radius = -1.0;
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "the radius must be > 0");
  in.radius = 10.0;
  in.kind = ShellSurfaceKind::Hemisphere;
  in.hole = 90.0;
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "the hole must be > 0 and < 90 degrees, not 90");
  in.hole = 18.0;
  in.type = "STRI3";
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "curved surfaces are meshed with quadrilateral shells (S4, S4R, S8, S8R, S9, S9R); "
            "STRI3 has 3 nodes");
  in.type = "C3D8";
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "element type C3D8 is no shell type; use S4, S4R, S8, S8R, S9 or S9R");
  in.type = "S4";
  in.offset = 0.6;
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "the offset must lie within -0.5 .. 0.5 (thicknesses from the mid-surface)");
  in.offset = 0.0;
  in.material = "BRASS";
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "no material BRASS in the model");
  in.material.clear();
  doc.apply(shell_surface_command(doc.model(), in, registry));
  EXPECT_EQ(refusal([&] { model_with_shell_surface(doc.model(), in, registry); }),
            "a set SHELL exists already; choose another name");
  EXPECT_EQ(shell_surface_kind_of("Hemisphere"), ShellSurfaceKind::Hemisphere);
  EXPECT_EQ(refusal([&] { shell_surface_kind_of("Cone"); }),
            "unknown shell surface 'Cone'; use Cylindrical panel or Hemisphere");
}

}  // namespace
}  // namespace styk::gui
