// Lines, patch and block maps, revolve/sweep, and the SPEC §4.4/§4.5 profiles.
#include <cmath>

#include <gtest/gtest.h>

#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"

namespace styk::mesher {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Line, GradedParametersHaveTheRequestedRatio) {
  // SPEC §3.1.7: 5 elements, longest / shortest = 4.
  const auto t = graded_parameters(5, 4.0);
  ASSERT_EQ(t.size(), 6u);
  EXPECT_DOUBLE_EQ(t.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.back(), 1.0);
  EXPECT_NEAR((t[5] - t[4]) / (t[1] - t[0]), 4.0, 1e-12);
  for (int i = 1; i < 5; ++i)
    EXPECT_NEAR((t[i + 1] - t[i]) / (t[i] - t[i - 1]), std::pow(4.0, 0.25), 1e-12);
  const auto u = graded_parameters(4);
  EXPECT_NEAR(u[1], 0.25, 1e-15);
  EXPECT_THROW(graded_parameters(0), std::invalid_argument);
  EXPECT_THROW(graded_parameters(3, -1.0), std::invalid_argument);
  const auto pts = mesh_line({0, 0, 0}, {2, 0, 0}, 2, 3.0);
  EXPECT_NEAR(pts[1][0], 0.5, 1e-12);  // lengths 0.5 and 1.5
}

TEST(PatchMap, NineNodeMapReproducesAQuadraticSurface) {
  // z = x^2 + x*y on [-1,1]^2 lies in the biquadratic space: exact at any (u, v).
  std::vector<Vec3> control;
  const double c[9][2] = {{-1, -1}, {1, -1}, {1, 1},  {-1, 1}, {0, -1},
                          {1, 0},   {0, 1},  {-1, 0}, {0, 0}};
  for (const auto& p : c) control.push_back({p[0], p[1], p[0] * p[0] + p[0] * p[1]});
  const PatchMap map = quad_map(control);
  const Vec3 x = map(0.3, -0.7);
  EXPECT_NEAR(x[2], 0.09 - 0.21, 1e-14);
  EXPECT_THROW(quad_map({{0, 0, 0}}), std::invalid_argument);
  // A 2 x 3 patch of 8-node quads: 2*3 quads, (5*7 - 6) nodes.
  const PatchMesh m = mesh_patch(map, 2, 3, 1.0, 1.0, 2);
  EXPECT_EQ(m.quads.size(), 6u);
  EXPECT_EQ(m.nodes.size(), 29u);
}

TEST(BlockMap, TwentySevenNodeMapIsExactForATriquadratic) {
  std::vector<Vec3> control = {
      {-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
      {-1, 1, 1},   {0, -1, -1}, {1, 0, -1},  {0, 1, -1},  {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},
      {0, 1, 1},    {-1, 0, 1},  {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},   {-1, 1, 0}, {0, 0, -1},
      {0, 0, 1},    {0, -1, 0},  {1, 0, 0},   {0, 1, 0},   {-1, 0, 0},  {0, 0, 0}};
  for (Vec3& p : control) p[0] += 0.1 * p[1] * p[1] * p[2] * p[2];  // a triquadratic bend
  const BlockMap map = hex_map(control);
  const Vec3 x = map({0.2, 0.5, -0.4});
  EXPECT_NEAR(x[0], 0.2 + 0.1 * 0.25 * 0.16, 1e-14);
  EXPECT_NEAR(x[1], 0.5, 1e-14);
}

TEST(BlockMap, RevolvePlacesEveryNodeOnTheCylinder) {
  // A 90 deg sleeve r 2..3: every C3D20 node (mid-edge nodes too) lies exactly at its radius.
  const PatchMap profile = quad_map({{2, 0, 0}, {3, 0, 0}, {3, 0, 1}, {2, 0, 1}});
  // (u: r along x, v: z, zeta: angle about -y ... ) about z: profile (x, z), rotation -> y.
  // (e_r, e_z, e_theta) is left-handed, so revolve from 0 to -90 deg to stay right-handed.
  const BlockMap map = revolve(profile, {0, 0, 0}, {0, 0, 1}, 0.0, -kPi / 2);
  Mesh mesh;
  const Block b = mesh_block(mesh, map, {"C3D20", {2, 1, 6}, {1, 1, 1}, "EALL"});
  EXPECT_EQ(mesh.elements.size(), 12u);
  for (int n : b.side_nodes(0, -1))
    EXPECT_NEAR(std::hypot(mesh.nodes[n][0], mesh.nodes[n][1]), 2.0, 1e-14);
  for (int n : b.side_nodes(0, +1))
    EXPECT_NEAR(std::hypot(mesh.nodes[n][0], mesh.nodes[n][1]), 3.0, 1e-14);
  // The same revolve to +90 deg is left-handed: refused.
  EXPECT_THROW(mesh_block(mesh, revolve(profile, {0, 0, 0}, {0, 0, 1}, 0.0, kPi / 2),
                          {"C3D8", {1, 1, 1}, {1, 1, 1}, ""}),
               std::invalid_argument);
}

TEST(BlockMap, SweepFollowsThePathWithTwist) {
  const PatchMap section = [](double u, double v) { return Vec3{u, 0.5 * v, 0}; };
  const BlockMap map = sweep(
      section,
      [](double t) {
        return Vec3{10 * t, 0, 0};
      },
      {0, 1, 0}, [](double t) { return 0.5 * kPi * t; });
  const Vec3 root = map({1, 0, -1}), tip = map({1, 0, 1});
  EXPECT_NEAR(root[1], 1.0, 1e-9);  // width along y at the root
  EXPECT_NEAR(tip[0], 10.0, 1e-9);
  EXPECT_NEAR(tip[2], 1.0, 1e-9);  // along z after 90 deg
  const Vec3 e = extrude(section, {0, 0, 3})({0, 0, 1});
  EXPECT_NEAR(e[2], 3.0, 1e-15);
}

TEST(Profiles, P3gFollowsTheDin32711Formula) {
  // SPEC §4.5, D = 60, n = 3, e = 2.25: at v = 0 the radius is D/2 - e; at v = pi/3, D/2 + e.
  const Vec3 a = p3g_point(60, 3, 2.25, 0.0);
  EXPECT_NEAR(a[0], 27.75, 1e-12);
  EXPECT_NEAR(a[1], 0.0, 1e-12);
  const Vec3 b = p3g_point(60, 3, 2.25, kPi / 3);
  EXPECT_NEAR(std::hypot(b[0], b[1]), 32.25, 1e-12);
  // Three-fold symmetry.
  const Vec3 c = p3g_point(60, 3, 2.25, 0.3), d = p3g_point(60, 3, 2.25, 0.3 + 2 * kPi / 3);
  EXPECT_NEAR(std::hypot(c[0], c[1]), std::hypot(d[0], d[1]), 1e-12);
}

TEST(Profiles, SplineRadiusHasTipsFlanksAndRoots) {
  // SPEC §4.4: 6 splines, D = 67, d = 61.18, w = 12.48.
  EXPECT_DOUBLE_EQ(spline_radius(67, 61.18, 12.48, 6, 0.0), 33.5);       // tip centre
  EXPECT_DOUBLE_EQ(spline_radius(67, 61.18, 12.48, 6, kPi / 6), 30.59);  // between splines
  const double flank = std::asin(6.24 / 32.0);                           // r = 32 on a flank
  EXPECT_NEAR(spline_radius(67, 61.18, 12.48, 6, flank), 32.0, 1e-9);
  EXPECT_NEAR(spline_radius(67, 61.18, 12.48, 6, -flank + 2 * kPi), 32.0, 1e-9);
}

}  // namespace
}  // namespace styk::mesher
