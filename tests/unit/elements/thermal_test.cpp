// Thermal strain in the TElement template methods (thermal_load, strains_stresses with nodal
// temperature changes, internal_force), for every built-in solid type, both rules, with and without
// B-bar.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "styk/elements/c3d20.hpp"
#include "styk/elements/c3d20r.hpp"
#include "styk/elements/c3d27.hpp"
#include "styk/elements/c3d8.hpp"
#include "styk/elements/c3d8i.hpp"
#include "styk/elements/c3d8r.hpp"

namespace styk {
namespace {

using test::distorted_geometry;
using test::linear_field;
using test::reference_geometry;

constexpr double kAlpha = 1.2e-5;

Material thermal_material() {
  Material m = test::unit_material();  // E = 1, nu = 0.3
  m.expansion = kAlpha;
  m.expansion_reference = 20.0;  // irrelevant for a constant alpha: dT = T - T_initial
  return m;
}

std::vector<std::unique_ptr<TElement>> family() {
  std::vector<std::unique_ptr<TElement>> elements;
  elements.push_back(std::make_unique<C3D8>());
  elements.push_back(std::make_unique<C3D8R>());
  elements.push_back(std::make_unique<C3D8R>(0.0));
  elements.push_back(std::make_unique<C3D8I>());
  elements.push_back(std::make_unique<C3D20>());
  elements.push_back(std::make_unique<C3D20R>());
  elements.push_back(std::make_unique<C3D27>());
  return elements;
}

struct Case {
  const TElement* element;
  RuleKind kind;
  bool b_bar;
  std::string label() const {
    return element->name() + (kind == RuleKind::Full ? " full" : " reduced") +
           (b_bar ? " B-bar" : "");
  }
};

template <typename Check>
void for_every_case(Check&& check) {
  const auto elements = family();
  for (const auto& e : elements)
    for (RuleKind kind : {RuleKind::Full, RuleKind::Reduced})
      for (bool b_bar : {false, true}) check(Case{e.get(), kind, b_bar});
}

// A free element heated uniformly by dT expands freely: u = alpha dT x gives strain alpha dT
// (normal components, tensor shear 0) and zero stress, to 1e-12 (E = 1, strain 1.2e-3); the
// thermal load is exactly what that field needs (K u = f_th, relative 1e-12) and the internal
// force vanishes (1e-12 |f_th|).
TEST(ThermalStrain, FreeExpansionIsStressFree) {
  const double dT = 100.0;
  for_every_case([&](const Case& c) {
    const TElement& e = *c.element;
    const ElementGeometry g = distorted_geometry(e, 31);
    const ElementOptions options{c.b_bar};
    const Eigen::VectorXd nodal_dT = Eigen::VectorXd::Constant(e.node_count(), dT);
    const Eigen::VectorXd u =
        linear_field(g, kAlpha * dT * Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.1, 0, 0));
    Eigen::MatrixXd strain, stress;
    e.strains_stresses(g, thermal_material(), c.kind, u, strain, stress, options, &nodal_dT);
    for (int k = 0; k < strain.rows(); ++k)
      for (int m = 0; m < 6; ++m) {
        EXPECT_NEAR(strain(k, m), m < 3 ? kAlpha * dT : 0.0, 1e-12) << c.label();
        EXPECT_NEAR(stress(k, m), 0.0, 1e-12) << c.label();
      }
    Eigen::MatrixXd K;
    Eigen::VectorXd f_th, f_int;
    e.stiffness(g, thermal_material(), c.kind, K, options);
    e.thermal_load(g, thermal_material(), c.kind, nodal_dT, f_th, options);
    EXPECT_GT(f_th.norm(), 0.0) << c.label();
    EXPECT_LT((K * u - f_th).norm(), 1e-12 * f_th.norm()) << c.label();
    e.internal_force(g, thermal_material(), c.kind, u, f_int, options, &nodal_dT);
    EXPECT_LT(f_int.norm(), 1e-12 * f_th.norm()) << c.label();
  });
}

// A fully constrained element (u = 0) heated by dT: sigma_ii = -E alpha dT / (1 - 2 nu), no
// shear, at every integration point (relative 1e-12).
TEST(ThermalStrain, FullyConstrainedStress) {
  const double dT = -40.0, E = 1.0, nu = 0.3;
  const double expected = -E * kAlpha * dT / (1.0 - 2.0 * nu);
  for_every_case([&](const Case& c) {
    const TElement& e = *c.element;
    const ElementGeometry g = distorted_geometry(e, 32);
    const Eigen::VectorXd nodal_dT = Eigen::VectorXd::Constant(e.node_count(), dT);
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * e.node_count());
    Eigen::MatrixXd strain, stress;
    e.strains_stresses(g, thermal_material(), c.kind, u, strain, stress, ElementOptions{c.b_bar},
                       &nodal_dT);
    for (int k = 0; k < stress.rows(); ++k)
      for (int m = 0; m < 6; ++m) {
        EXPECT_NEAR(stress(k, m), m < 3 ? expected : 0.0, 1e-12 * std::abs(expected)) << c.label();
        EXPECT_NEAR(strain(k, m), 0.0, 1e-15) << c.label();  // reported strain = total strain
      }
  });
}

// A temperature varying linearly in space, dT = T0 + t . x, is a compatible thermal strain: the
// free body takes u_i = alpha (T0 x_i + (t . x) x_i - t_i |x|^2 / 2) without stress. The quadratic
// elements represent that field exactly on an affinely mapped cube: zero stress to 1e-12.
TEST(ThermalStrain, LinearTemperatureFieldIsStressFreeForQuadraticElements) {
  const C3D20 c3d20;
  const C3D20R c3d20r;
  const C3D27 c3d27;
  const double T0 = 30.0;
  const Eigen::Vector3d t(5.0, -8.0, 3.0);
  Eigen::Matrix3d A;
  A << 2.0, 0.3, 0.1, -0.2, 1.5, 0.2, 0.1, -0.3, 1.2;
  for (const TElement* e :
       {static_cast<const TElement*>(&c3d20), static_cast<const TElement*>(&c3d20r),
        static_cast<const TElement*>(&c3d27)}) {
    ElementGeometry g = reference_geometry(*e);
    g.X = (g.X * A.transpose()).rowwise() + Eigen::RowVector3d(1.0, 2.0, -1.0);
    Eigen::VectorXd nodal_dT(e->node_count()), u(3 * e->node_count());
    for (int i = 0; i < e->node_count(); ++i) {
      const Eigen::Vector3d x = g.X.row(i).transpose();
      nodal_dT(i) = T0 + t.dot(x);
      u.segment<3>(3 * i) = kAlpha * (T0 * x + t.dot(x) * x - 0.5 * x.squaredNorm() * t);
    }
    Eigen::MatrixXd strain, stress;
    e->strains_stresses(g, thermal_material(), RuleKind::Full, u, strain, stress, {}, &nodal_dT);
    EXPECT_LT(stress.cwiseAbs().maxCoeff(), 1e-12) << e->name();
    EXPECT_GT(strain.cwiseAbs().maxCoeff(), 1e-4) << e->name();
  }
}

// Two independent paths agree: the internal force K u - f_th (condensed stiffness and thermal
// load) equals the integral of B^T sigma with the stresses recovered by strains_stresses
// (incompatible modes recovered from u and dT), for an arbitrary u and a non-uniform dT on a
// distorted element (relative 1e-12). Checks the condensation of C3D8I against its recovery.
TEST(ThermalStrain, InternalForceMatchesRecoveredStresses) {
  const C3D8 c3d8;
  const C3D8I c3d8i;
  const C3D27 c3d27;
  for (const TElement* e :
       {static_cast<const TElement*>(&c3d8), static_cast<const TElement*>(&c3d8i),
        static_cast<const TElement*>(&c3d27)}) {
    const int n = e->node_count();
    const ElementGeometry g = distorted_geometry(*e, 33);
    Eigen::VectorXd u(3 * n), nodal_dT(n);
    for (int i = 0; i < 3 * n; ++i) u(i) = 1e-3 * std::sin(1.7 * i + 0.3);
    for (int i = 0; i < n; ++i) nodal_dT(i) = 50.0 + 20.0 * std::cos(0.9 * i);
    Eigen::VectorXd f_int;
    e->internal_force(g, thermal_material(), RuleKind::Full, u, f_int, {}, &nodal_dT);
    Eigen::MatrixXd strain, stress;
    e->strains_stresses(g, thermal_material(), RuleKind::Full, u, strain, stress, {}, &nodal_dT);
    const IntegrationRule rule = e->rule(RuleKind::Full);
    Eigen::VectorXd N(n), f = Eigen::VectorXd::Zero(3 * n);
    Eigen::MatrixXd dN(n, 3), dNdx(n, 3), B(6, 3 * n);
    for (int k = 0; k < rule.size(); ++k) {
      e->der(rule.points[k], N, dN);
      const double detJ = e->jacobian(g, dN, dNdx, k + 1);
      e->bee(dNdx, B);
      f += rule.weights[k] * detJ * B.transpose() * stress.row(k).transpose();
    }
    EXPECT_LT((f - f_int).norm(), 1e-12 * f_int.norm()) << e->name();
  }
}

// dT != 0 needs *EXPANSION: an InputError at the material; dT = 0 does not.
TEST(ThermalStrain, MissingExpansionIsAnInputError) {
  const C3D8 e;
  const ElementGeometry g = reference_geometry(e);
  const Material plain = test::unit_material();
  Eigen::VectorXd f;
  EXPECT_NO_THROW(e.thermal_load(g, plain, RuleKind::Full, Eigen::VectorXd::Zero(8), f));
  EXPECT_EQ(f.norm(), 0.0);
  try {
    e.thermal_load(g, plain, RuleKind::Full, Eigen::VectorXd::Constant(8, 1.0), f);
    FAIL() << "no InputError without *EXPANSION";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("test.inp:3: material UNIT", 0), 0u) << message;
    EXPECT_NE(message.find("*EXPANSION"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace styk
