// The one local-axes routine and its validity rule (core/local_axes.hpp), shared by the reader,
// the GUI dialogs, the solver and the contact frames: axes as CalculiX defines them for
// *ORIENTATION / *TRANSFORM (rectangular: 1 along a, 2 in the plane of a and b; cylindrical: 3
// along a -> b, 1 radial), degeneracy judged relative to the points' scale.
#include <gtest/gtest.h>

#include "styk/core/local_axes.hpp"

namespace styk {
namespace {

LocalAxes axes(CoordinateSystem system, const Vec3& a, const Vec3& b) {
  LocalAxes out;
  out.system = system;
  out.a = a;
  out.b = b;
  return out;
}

TEST(LocalAxes, RectangularAxesFollowAAndThePlaneOfAAndB) {
  Eigen::Matrix3d R;
  ASSERT_TRUE(
      local_axes_at(axes(CoordinateSystem::Rectangular, {0, 2, 0}, {-3, 1, 0}), {5, 5, 5}, R));
  // e1 = a/|a| = y, e2 = the part of b normal to a = -x, e3 = e1 x e2 = z; exact to round-off.
  EXPECT_NEAR((R.col(0) - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((R.col(1) - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((R.col(2) - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-15);
}

TEST(LocalAxes, CylindricalAxesAreRadialTangentialAxial) {
  Eigen::Matrix3d R;
  // Axis along z through (1, 1, 0); the point (1, 3, 7) lies 2 away along +y.
  ASSERT_TRUE(
      local_axes_at(axes(CoordinateSystem::Cylindrical, {1, 1, 0}, {1, 1, 4}), {1, 3, 7}, R));
  EXPECT_NEAR((R.col(0) - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-15);   // radial
  EXPECT_NEAR((R.col(1) - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, 1e-15);  // e3 x e1
  EXPECT_NEAR((R.col(2) - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-15);   // axial
}

TEST(LocalAxes, DegenerateSystemsAreNamedWithOneRule) {
  EXPECT_EQ(axes_defect(axes(CoordinateSystem::Rectangular, {0, 0, 0}, {0, 1, 0})),
            "point a must not be the origin (it gives local x)");
  EXPECT_EQ(axes_defect(axes(CoordinateSystem::Rectangular, {1, 2, 3}, {-2, -4, -6})),
            "point b must not lie on the line of a (it gives the local x-y plane)");
  EXPECT_EQ(axes_defect(axes(CoordinateSystem::Rectangular, {1, 0, 0}, {0, 0, 0})),
            "point b must not lie on the line of a (it gives the local x-y plane)");
  EXPECT_EQ(axes_defect(axes(CoordinateSystem::Cylindrical, {0, 0, 5}, {0, 0, 5})),
            "the two axis points a and b must differ");
  Eigen::Matrix3d R = Eigen::Matrix3d::Constant(7.0);
  EXPECT_FALSE(
      local_axes_at(axes(CoordinateSystem::Cylindrical, {0, 0, 5}, {0, 0, 5}), {1, 0, 0}, R));
  EXPECT_EQ(R(0, 0), 7.0);  // untouched
}

// The rule is relative: the same geometry in micrometres or in kilometres is judged alike, and
// a point on the axis is refused whatever the unit, a point slightly off it accepted.
TEST(LocalAxes, TheRuleDoesNotDependOnTheUnitOfLength) {
  for (const double unit : {1e-6, 1.0, 1e6}) {
    const LocalAxes cylinder = axes(CoordinateSystem::Cylindrical, {0, 0, 0}, {0, 0, 10 * unit});
    EXPECT_EQ(axes_defect(cylinder), "") << unit;
    EXPECT_EQ(axes_defect_at(cylinder, {0, 0, 3 * unit}),
              "lies on the axis: it has no radial direction")
        << unit;
    EXPECT_EQ(axes_defect_at(cylinder, {1e-9 * unit, 0, 3 * unit}), "") << unit;
    EXPECT_EQ(
        axes_defect(axes(CoordinateSystem::Rectangular, {unit, 0, 0}, {unit, 1e-13 * unit, 0})),
        "point b must not lie on the line of a (it gives the local x-y plane)")
        << unit;
    EXPECT_EQ(
        axes_defect(axes(CoordinateSystem::Rectangular, {unit, 0, 0}, {unit, 1e-9 * unit, 0})), "")
        << unit;
  }
}

}  // namespace
}  // namespace styk
