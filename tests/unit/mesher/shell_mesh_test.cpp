// Shell meshes (mesher/shell_mesh.hpp, docs/mesher.md "Shell meshes"): node and element counts,
// every node on its surface, the shell normal g1 x g2 (+z for the plate, outward for the panel
// and the hemisphere), the side sets, shared seams of closed patches, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "styk/core/diagnostics.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/mesher/shell_mesh.hpp"
#include "support/element_registries.hpp"

namespace styk::mesher {
namespace {

constexpr double kPi = 3.14159265358979323846;

ShellMeshSpec spec(const std::string& type, int nu, int nv, const std::string& elset = "SHELL") {
  ShellMeshSpec s;
  s.type = type, s.divisions_u = nu, s.divisions_v = nv, s.elset = elset;
  return s;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The element's normal from its corners' diagonals (the right-hand normal of the node order) and
// the centre of its corners.
Vec3 corner_normal(const Mesh& mesh, const MeshElement& e) {
  const auto& x = mesh.nodes;
  return cross(sub(x[e.nodes[2]], x[e.nodes[0]]), sub(x[e.nodes[3]], x[e.nodes[1]]));
}
Vec3 corner_centre(const Mesh& mesh, const MeshElement& e) {
  Vec3 c{0, 0, 0};
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) c[d] += 0.25 * mesh.nodes[e.nodes[k]][d];
  return c;
}

// Counts: a 3 x 2 plate has 12 nodes of S4, 7 x 5 - 6 = 29 of S8R (no centres), 35 of S9; it lies
// in z = 0 with the normal +z; the sides hold their grid lines.
TEST(ShellMesh, PlateCountsNormalAndSides) {
  const struct {
    const char* type;
    std::size_t nodes, per_element, side1;
  } cases[] = {{"S4", 12, 4, 4}, {"S8R", 29, 8, 7}, {"S9", 35, 9, 7}};
  for (const auto& c : cases) {
    const Mesh mesh = shell_plate(3.0, 2.0, spec(c.type, 3, 2), test::shared_builtin_registry());
    EXPECT_EQ(mesh.nodes.size(), c.nodes) << c.type;
    ASSERT_EQ(mesh.elements.size(), 6u);
    for (const MeshElement& e : mesh.elements) {
      EXPECT_EQ(e.type, c.type);
      EXPECT_EQ(e.nodes.size(), c.per_element);
      EXPECT_EQ(std::set<int>(e.nodes.begin(), e.nodes.end()).size(), c.per_element);
      const Vec3 n = corner_normal(mesh, e);
      EXPECT_GT(n[2], 0.0);
    }
    for (const Vec3& x : mesh.nodes) EXPECT_EQ(x[2], 0.0);
    EXPECT_EQ(mesh.node_sets.at("SHELL_SIDE1").size(), c.side1);
    EXPECT_EQ(mesh.node_sets.at("SHELL_SIDE3").size(), c.side1);
    EXPECT_EQ(mesh.node_sets.at("SHELL").size(), c.nodes);
    for (const int n : mesh.node_sets.at("SHELL_SIDE2")) EXPECT_NEAR(mesh.nodes[n][0], 3.0, 1e-12);
    for (const int n : mesh.node_sets.at("SHELL_SIDE4")) EXPECT_NEAR(mesh.nodes[n][0], 0.0, 1e-12);
    EXPECT_EQ(mesh.element_sets.at("SHELL").size(), 6u);
  }
}

// The Scordelis-Lo roof's surface (R = 25, L = 50, 80 degrees): every node, mid-side and centre
// nodes included, at R from the y axis (1e-12 R), the normal outward, y from 0 to L.
TEST(ShellMesh, CylindricalPanelNodesOnTheSurfaceNormalOutward) {
  for (const char* type : {"S4", "S8R", "S9R"}) {
    const Mesh mesh = shell_cylindrical_panel(25.0, 50.0, 80.0, spec(type, 4, 4, "ROOF"),
                                              test::shared_builtin_registry());
    double lowest_cos = 1.0;
    for (const Vec3& x : mesh.nodes) {
      EXPECT_NEAR(std::hypot(x[0], x[2]), 25.0, 25e-12);
      EXPECT_GE(x[1], -1e-12);
      EXPECT_LE(x[1], 50.0 + 1e-12);
      lowest_cos = std::min(lowest_cos, x[2] / 25.0);
    }
    EXPECT_NEAR(lowest_cos, std::cos(40.0 * kPi / 180), 1e-12);
    for (const MeshElement& e : mesh.elements) {
      const Vec3 c = corner_centre(mesh, e);
      EXPECT_GT(dot(corner_normal(mesh, e), {c[0], 0.0, c[2]}), 0.0) << type;
    }
    EXPECT_EQ(mesh.node_sets.count("ROOF_SIDE2"), 1u);
  }
}

// A full cylinder (360 degrees) shares its seam: 8 x 2 S4 have 8 x 3 nodes, every node used by
// elements on both sides of the seam, no SIDE2 / SIDE4.
TEST(ShellMesh, ClosedCylinderSharesItsSeam) {
  const Mesh mesh =
      shell_cylindrical_panel(1.0, 2.0, 360.0, spec("S4", 8, 2), test::shared_builtin_registry());
  EXPECT_EQ(mesh.nodes.size(), 24u);
  EXPECT_EQ(mesh.node_sets.count("SHELL_SIDE2"), 0u);
  EXPECT_EQ(mesh.node_sets.count("SHELL_SIDE4"), 0u);
  std::vector<int> uses(mesh.nodes.size(), 0);
  for (const MeshElement& e : mesh.elements)
    for (const int n : e.nodes) ++uses[n];
  for (std::size_t n = 0; n < uses.size(); ++n)
    EXPECT_EQ(uses[n], mesh.nodes[n][1] > 0.5 && mesh.nodes[n][1] < 1.5 ? 4 : 2) << n;
}

// MacNeal-Harder's pinched hemisphere (R = 10, an 18 degree hole, a quarter): nodes at R, the
// highest at R sin 72 deg, the normal outward; the closed hemisphere shares its seam.
TEST(ShellMesh, HemisphereWithAHole) {
  const Mesh quarter =
      shell_hemisphere(10.0, 18.0, 90.0, spec("S8R", 4, 4), test::shared_builtin_registry());
  double top = 0.0;
  for (const Vec3& x : quarter.nodes) {
    EXPECT_NEAR(std::sqrt(dot(x, x)), 10.0, 1e-11);
    EXPECT_GE(x[0], -1e-12);
    EXPECT_GE(x[1], -1e-12);
    top = std::max(top, x[2]);
  }
  EXPECT_NEAR(top, 10.0 * std::sin(72.0 * kPi / 180), 1e-11);
  for (const MeshElement& e : quarter.elements)
    EXPECT_GT(dot(corner_normal(quarter, e), corner_centre(quarter, e)), 0.0);
  const Mesh closed =
      shell_hemisphere(10.0, 18.0, 360.0, spec("S4", 12, 3), test::shared_builtin_registry());
  EXPECT_EQ(closed.nodes.size(), std::size_t(12 * 4));
}

// Refusals: a type that is no shell, no divisions, a hemisphere without a hole, a panel beyond
// 360 degrees, a closed cylinder of 2 elements around.
TEST(ShellMesh, BadInputIsRefusedByName) {
  const auto message = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(nothing thrown)");
  };
  EXPECT_NE(message([] {
              shell_plate(1, 1, spec("C3D8", 2, 2), test::shared_builtin_registry());
            }).find("C3D8 is no shell element type"),
            std::string::npos);
  EXPECT_NE(message([] {
              shell_plate(1, 1, spec("S4", 0, 2), test::shared_builtin_registry());
            }).find("divisions must be >= 1"),
            std::string::npos);
  EXPECT_NE(message([] {
              shell_hemisphere(1, 0, 90, spec("S4", 2, 2), test::shared_builtin_registry());
            }).find("the hole must lie in (0, 90) degrees"),
            std::string::npos);
  EXPECT_NE(message([] {
              shell_cylindrical_panel(1, 1, 400, spec("S4", 2, 2), test::shared_builtin_registry());
            }).find("the angle must lie in (0, 360] degrees"),
            std::string::npos);
  EXPECT_NE(message([] {
              shell_cylindrical_panel(1, 1, 360, spec("S4", 2, 2), test::shared_builtin_registry());
            }).find("a closed patch needs at least 3 divisions around it"),
            std::string::npos);
}

}  // namespace
}  // namespace styk::mesher
