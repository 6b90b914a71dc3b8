// T3D2: the bar stiffness EA/L t t^T, its single axial mode, axial stress and thermal force.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "element_fixtures.hpp"
#include "styk/elements/t3d2.hpp"

namespace styk {
namespace {

ElementGeometry bar(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double area) {
  ElementGeometry g;
  g.X.resize(2, 3);
  g.X.row(0) = a.transpose();
  g.X.row(1) = b.transpose();
  g.id = 9;
  g.where = SourceLoc{"truss.inp", 12};
  g.cross_section = area;
  return g;
}

TEST(T3D2, StiffnessIsEAOverLAlongTheBar) {
  const T3D2 element;
  const Eigen::Vector3d a(0.3, -1.0, 2.0), b(2.3, 0.5, -0.25);
  const double area = 0.04, E = 1.0;  // unit material
  const ElementGeometry g = bar(a, b, area);
  Eigen::MatrixXd K;
  element.stiffness(g, test::unit_material(), RuleKind::Full, K);
  const double L = (b - a).norm();
  const Eigen::Vector3d t = (b - a) / L;
  Eigen::MatrixXd expected(6, 6);
  const Eigen::Matrix3d k = E * area / L * t * t.transpose();
  expected << k, -k, -k, k;
  EXPECT_LT((K - expected).cwiseAbs().maxCoeff(), 1e-15);
  // One axial mode, five zero eigenvalues (3 translations, 2 rotations... and the spin about the
  // bar's own axis is a rotation of the nodes perpendicular to it: all zero energy).
  EXPECT_EQ(test::zero_eigenvalue_count(K), 5);
  EXPECT_EQ(element.section_measure(), SectionMeasure::Area);
  EXPECT_EQ(element.active_dofs(), (DofSet{true, true, true, false, false, false}));
  EXPECT_EQ(element.node_dofs(), 3);
  EXPECT_TRUE(element.faces().empty());
}

TEST(T3D2, AxialStressAndThermalForce) {
  const T3D2 element;
  Material material = test::unit_material();
  material.young = 200.0;
  material.expansion = 1e-5;
  const ElementGeometry g = bar({0, 0, 0}, {3, 4, 0}, 2.0);  // L = 5, t = (0.6, 0.8, 0)
  // Stretch by 0.01 along the bar: eps = 0.002, S11 = 0.4.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  u.segment<3>(3) = 0.01 * Eigen::Vector3d(0.6, 0.8, 0.0);
  u.segment<3>(3) += Eigen::Vector3d(0.8, -0.6, 0.0) * 0.5;  // a perpendicular (rotation) part
  Eigen::MatrixXd strain, stress;
  element.strains_stresses(g, material, RuleKind::Full, u, strain, stress);
  ASSERT_EQ(stress.rows(), 1);
  EXPECT_NEAR(strain(0, 0), 0.002, 1e-16);
  EXPECT_NEAR(stress(0, 0), 0.4, 1e-14);
  for (int c = 1; c < 6; ++c) EXPECT_EQ(stress(0, c), 0.0);
  // A heated bar pushes its ends apart with E A alpha dT = 200 * 2 * 1e-5 * 10 = 0.04.
  Eigen::VectorXd f;
  element.thermal_load(g, material, RuleKind::Full, Eigen::Vector2d(10.0, 10.0), f);
  EXPECT_LT((f.segment<3>(3) - 0.04 * Eigen::Vector3d(0.6, 0.8, 0.0)).norm(), 1e-16);
  EXPECT_LT((f.head<3>() + f.segment<3>(3)).norm(), 1e-18);
}

TEST(T3D2, NonPositiveAreaAndZeroLengthAreInputErrorsAtTheElement) {
  const T3D2 element;
  Eigen::MatrixXd K;
  try {
    element.stiffness(bar({0, 0, 0}, {1, 0, 0}, 0.0), test::unit_material(), RuleKind::Full, K);
    FAIL() << "zero area accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 12);
    EXPECT_NE(std::string(error.what()).find("element 9 (T3D2): cross-section area 0"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(
      element.stiffness(bar({1, 1, 1}, {1, 1, 1}, 1.0), test::unit_material(), RuleKind::Full, K),
      InputError);
}

}  // namespace
}  // namespace styk
