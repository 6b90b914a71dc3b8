// The axisymmetric rings CAX4/CAX4R/CAX8/CAX8R and the reduced plane quadrilaterals CPS8R/CPE8R:
// the ring's measure (2 pi r), hoop strain u_r / r, the constant-strain patch of a uniform
// expansion, pressure on an edge (the whole circumference, as CalculiX counts loads), the
// stiffness against its own strain energy, zero-energy modes, and input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include <Eigen/Dense>

#include "element_checks.hpp"
#include "element_fixtures.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

const TElement& element(const std::string& type) {
  return *test::shared_builtin_registry().find(type);
}

// The section r in [2, 4], z in [0, 1] (x = r, y = z), nodes moved in-plane by up to
// `amplitude` (seeded).
ElementGeometry ring_section(const TElement& e, unsigned seed = 0, double amplitude = 0.0) {
  ElementGeometry g = test::reference_geometry(e);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-amplitude, amplitude);
  for (int i = 0; i < g.X.rows(); ++i) {
    g.X(i, 0) = 3.0 + g.X(i, 0) + shift(rng);
    g.X(i, 1) = 0.5 + 0.5 * g.X(i, 1) + shift(rng);
  }
  return g;
}

class AxisymmetricFamily : public ::testing::TestWithParam<std::string> {};

// The measure integrates the ring: sum of w dV = 2 pi r_mean A = 2 pi 3 x 2 = 12 pi, exact (r is
// linear on the rectangle).
TEST_P(AxisymmetricFamily, MeasureIsTheRingVolume) {
  const TElement& e = element(GetParam());
  EXPECT_EQ(e.form(), ElementForm::Axisymmetric);
  const ElementGeometry g = ring_section(e);
  const IntegrationRule rule = e.rule(RuleKind::Full);
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  double volume = 0.0;
  for (int k = 0; k < rule.size(); ++k) {
    e.der(rule.points[k], N, dN);
    volume += rule.weights[k] * e.point_measure(g, N, dN, dNdx, k + 1);
  }
  EXPECT_NEAR(volume, 12.0 * kPi, 1e-12);
}

// u_r = a r, u_z = b z: e_rr = e_hoop = a, e_zz = b, g_rz = 0 at every point of a distorted
// section, stresses by Hooke's law (S33 the hoop stress), to 1e-12.
TEST_P(AxisymmetricFamily, UniformExpansionIsReproducedExactly) {
  const TElement& e = element(GetParam());
  const ElementGeometry g = ring_section(e, 3, 0.1);
  const double a = 1e-3, b = -4e-4;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * e.node_count());
  for (int i = 0; i < e.node_count(); ++i) {
    u[3 * i] = a * g.X(i, 0);
    u[3 * i + 1] = b * g.X(i, 1);
  }
  Eigen::MatrixXd strain, stress;
  const Material m = test::unit_material();  // E = 1, nu = 0.3
  e.strains_stresses(g, m, RuleKind::Full, u, strain, stress);
  const double lambda = 0.3 / (1.3 * 0.4), mu = 1.0 / 2.6;
  for (int k = 0; k < strain.rows(); ++k) {
    EXPECT_NEAR(strain(k, 0), a, 1e-13);
    EXPECT_NEAR(strain(k, 1), b, 1e-13);
    EXPECT_NEAR(strain(k, 2), a, 1e-13);
    EXPECT_NEAR(strain(k, 3), 0.0, 1e-13);
    EXPECT_NEAR(stress(k, 2), lambda * (2 * a + b) + 2 * mu * a, 1e-12);
  }
}

// A unit pressure on the outer edge r = 4 (P2, from corner 2 to 3; z from 0 to 1) pushes the ring
// inwards with its whole circumference: the radial forces sum to -2 pi 4 x 1 = -8 pi, nothing
// axial.
TEST_P(AxisymmetricFamily, EdgePressureActsOnTheWholeCircumference) {
  const TElement& e = element(GetParam());
  Eigen::VectorXd f;
  e.pressure_load(ring_section(e), 1, 1.0, f);
  double fr = 0.0, fz = 0.0;
  for (int i = 0; i < e.node_count(); ++i) fr += f[3 * i], fz += f[3 * i + 1];
  EXPECT_NEAR(fr, -8.0 * kPi, 1e-12);
  EXPECT_NEAR(fz, 0.0, 1e-12);
}

TEST_P(AxisymmetricFamily, StiffnessIsTheGradientOfTheStrainEnergy) {
  const TElement& e = element(GetParam());
  const ElementGeometry g = ring_section(e, 9, 0.1);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * e.node_count());
  for (int i = 0; i < e.node_count(); ++i)
    u[3 * i] = 1e-3 * value(rng), u[3 * i + 1] = 1e-3 * value(rng);
  EXPECT_LT(test::stiffness_gradient_error(e, g, test::unit_material(), RuleKind::Full, u), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Rings, AxisymmetricFamily,
                         ::testing::Values("CAX4", "CAX4R", "CAX8", "CAX8R"));

// Zero eigenvalues on (ur, uz) of one section at r in [2, 4] (E = 1, nu = 0.3): the ring's only
// rigid motion is the axial translation. CAX4 (2x2) and CAX8 (3x3): 1. CAX4R: one point gives 4
// strains, 8 - 4 = 4 zeros, and the hourglass control restores the two hourglass modes (gamma on
// ur and uz): 2, the rigid one and the rotation of the section about its centre, whose hoop strain
// vanishes only at the centre (a mesh suppresses it: model_warnings_test). CAX8R (2x2): 2, the
// rigid motion and the single-element mode of the reduced 8-node quadrilateral, as CPS8R/CPE8R
// (3 rigid + 1).
TEST(AxisymmetricRules, ZeroEnergyModes) {
  const auto zeros = [](const std::string& type) {
    const TElement& e = element(type);
    Eigen::MatrixXd K;
    const ElementGeometry g =
        e.form() == ElementForm::Axisymmetric ? ring_section(e) : test::reference_geometry(e);
    e.stiffness(g, test::unit_material(), RuleKind::Full, K);
    return test::active_zero_eigenvalues(e, K);
  };
  EXPECT_EQ(zeros("CAX4"), 1);
  EXPECT_EQ(zeros("CAX4R"), 2);
  EXPECT_EQ(zeros("CAX8"), 1);
  EXPECT_EQ(zeros("CAX8R"), 2);
  EXPECT_EQ(zeros("CPS8R"), 4);
  EXPECT_EQ(zeros("CPE8R"), 4);
  EXPECT_EQ(zeros("CPS8"), 3);
}

// The reduced plane quadrilaterals are the 8-node ones with the 2x2 rule whatever is asked (the
// name fixes the rule, as in CalculiX).
TEST(ReducedPlaneQuads, NameFixesTheRule) {
  for (const char* type : {"CPS8R", "CPE8R", "CAX8R"}) {
    EXPECT_EQ(element(type).rule(RuleKind::Full).size(), 4) << type;
    EXPECT_EQ(element(type).rule(RuleKind::Reduced).size(), 4) << type;
    EXPECT_EQ(element(type).vtk_cell().type, vtk::kQuadraticQuad) << type;
  }
  EXPECT_EQ(element("CAX4R").rule(RuleKind::Full).size(), 1);
  EXPECT_EQ(element("CAX4").rule(RuleKind::Full).size(), 4);
  EXPECT_EQ(element("CAX8").rule(RuleKind::Full).size(), 9);
  EXPECT_EQ(element("CPS8R").form(), ElementForm::Planar);
  EXPECT_EQ(element("CAX4").vtk_cell().type, vtk::kQuad);
}

// A section reaching x < 0 (r must be >= 0) and one whose nodes run clockwise are refused at the
// element, naming it.
TEST(AxisymmetricRules, NegativeRadiusAndClockwiseSectionsAreRefused) {
  const TElement& e = element("CAX4");
  ElementGeometry g = ring_section(e);
  g.X.col(0).array() -= 5.0;  // r from -3 to -1
  Eigen::MatrixXd K;
  try {
    e.stiffness(g, test::unit_material(), RuleKind::Full, K);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("element 1 (CAX4): integration point 1 lies at r"),
              std::string::npos)
        << error.what();
  }
  g = ring_section(e);
  g.X.col(1) = -g.X.col(1);  // mirrored: clockwise
  EXPECT_THROW(e.stiffness(g, test::unit_material(), RuleKind::Full, K), InputError);
}

}  // namespace
}  // namespace styk
