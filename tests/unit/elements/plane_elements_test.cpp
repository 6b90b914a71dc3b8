// CPS4/CPE4/CPS8/CPE8: shape functions, rigid modes, the plane stress / plane strain relations,
// edge loads, thickness and thermal strain, and the input checks of the plane kinematics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Dense>

#include "element_fixtures.hpp"
#include "styk/elements/plane_quads.hpp"

namespace styk {
namespace {

using test::unit_material;

std::unique_ptr<PlaneElement> make(int nodes, PlaneKind kind) {
  if (nodes == 4) return std::make_unique<PlaneQuad4>(kind);
  return std::make_unique<PlaneQuad8>(kind);
}

// The reference square with every in-plane node coordinate moved by up to 0.15 (z stays 0;
// mid-edge nodes move too, so the 8-node edges are curved).
ElementGeometry distorted(const TElement& e, unsigned seed, double thickness = 1.0) {
  ElementGeometry g = test::reference_geometry(e);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-0.15, 0.15);
  for (int i = 0; i < g.X.rows(); ++i)
    for (int j = 0; j < 2; ++j) g.X(i, j) += shift(rng);
  g.cross_section = thickness;
  return g;
}

// The in-plane dofs (ux, uy of every node) of a 3n vector / matrix.
std::vector<int> in_plane_dofs(int n) {
  std::vector<int> dofs;
  for (int a = 0; a < n; ++a) {
    dofs.push_back(3 * a);
    dofs.push_back(3 * a + 1);
  }
  return dofs;
}

Eigen::MatrixXd in_plane_block(const Eigen::MatrixXd& K) {
  const std::vector<int> dofs = in_plane_dofs(static_cast<int>(K.rows() / 3));
  Eigen::MatrixXd block(dofs.size(), dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i)
    for (std::size_t j = 0; j < dofs.size(); ++j) block(i, j) = K(dofs[i], dofs[j]);
  return block;
}

class PlaneFamily : public ::testing::TestWithParam<std::tuple<int, PlaneKind>> {};

TEST_P(PlaneFamily, ShapeFunctionsAreKroneckerAndAPartitionOfUnity) {
  const auto element = make(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const int n = element->node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (int i = 0; i < n; ++i) {
    element->der(element->natural_nodes()[i], N, dN);
    for (int j = 0; j < n; ++j) EXPECT_NEAR(N(j), i == j ? 1.0 : 0.0, 1e-15) << i << "," << j;
  }
  // Partition of unity and its derivative, and dN = d/dxi N by central differences.
  for (const Vec3& xi : {Vec3{0.3, -0.7, 0.0}, Vec3{-0.55, 0.2, 0.0}}) {
    element->der(xi, N, dN);
    EXPECT_NEAR(N.sum(), 1.0, 1e-14);
    EXPECT_NEAR(dN.col(0).sum(), 0.0, 1e-14);
    EXPECT_NEAR(dN.col(1).sum(), 0.0, 1e-14);
    EXPECT_EQ(dN.col(2).cwiseAbs().maxCoeff(), 0.0);
    for (int d = 0; d < 2; ++d) {
      Vec3 plus = xi, minus = xi;
      plus[d] += 1e-6;
      minus[d] -= 1e-6;
      Eigen::VectorXd Np(n), Nm(n);
      Eigen::MatrixXd scratch(n, 3);
      element->der(plus, Np, scratch);
      element->der(minus, Nm, scratch);
      EXPECT_LT(((Np - Nm) / 2e-6 - dN.col(d)).cwiseAbs().maxCoeff(), 1e-8);
    }
  }
}

TEST_P(PlaneFamily, ThreeInPlaneRigidModesAndNoStiffnessOnUz) {
  // Full integration (2x2 for 4 nodes, 3x3 for 8): exactly the 3 in-plane rigid-body modes.
  const auto element = make(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const ElementGeometry g = distorted(*element, 11, 0.7);
  Eigen::MatrixXd K;
  element->stiffness(g, unit_material(), RuleKind::Full, K);
  EXPECT_EQ(test::zero_eigenvalue_count(in_plane_block(K)), 3);
  for (int a = 0; a < element->node_count(); ++a) {
    EXPECT_EQ(K.row(3 * a + 2).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(K.col(3 * a + 2).cwiseAbs().maxCoeff(), 0.0);
  }
  EXPECT_EQ(element->active_dofs(), (DofSet{true, true, false, false, false, false}));
  EXPECT_EQ(element->section_measure(), SectionMeasure::Thickness);
  // The stiffness is linear in the thickness.
  Eigen::MatrixXd K1;
  ElementGeometry unit = g;
  unit.cross_section = 1.0;
  element->stiffness(unit, unit_material(), RuleKind::Full, K1);
  EXPECT_LT((K - 0.7 * K1).cwiseAbs().maxCoeff(), 1e-14 * K1.cwiseAbs().maxCoeff());
}

TEST_P(PlaneFamily, ConstantStrainIsReproducedOnADistortedElement) {
  // Single-element patch test: a linear in-plane field gives its constant strain at every point.
  const auto element = make(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const ElementGeometry g = distorted(*element, 5);
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  G.topLeftCorner<2, 2>() << 2e-3, 1e-3, -0.5e-3, -1e-3;
  const Eigen::VectorXd u = test::linear_field(g, G, Eigen::Vector3d(0.1, -0.2, 0.0));
  Eigen::MatrixXd strain, stress;
  element->strains_stresses(g, unit_material(), RuleKind::Full, u, strain, stress);
  for (int k = 0; k < strain.rows(); ++k) {
    EXPECT_NEAR(strain(k, 0), 2e-3, 1e-15);
    EXPECT_NEAR(strain(k, 1), -1e-3, 1e-15);
    EXPECT_NEAR(strain(k, 3), 0.25e-3, 1e-15);
    EXPECT_EQ(strain(k, 4), 0.0);
    EXPECT_EQ(strain(k, 5), 0.0);
  }
  // And K u = 0 for the rigid part: internal forces of a rigid rotation vanish.
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  W(0, 1) = -1e-3;
  W(1, 0) = 1e-3;
  Eigen::MatrixXd K;
  element->stiffness(g, unit_material(), RuleKind::Full, K);
  const Eigen::VectorXd rigid = test::linear_field(g, W, Eigen::Vector3d(1, 2, 3));
  EXPECT_LT((K * rigid).cwiseAbs().maxCoeff(),
            1e-14 * K.cwiseAbs().maxCoeff() * rigid.cwiseAbs().maxCoeff());
}

TEST_P(PlaneFamily, EdgePressureResultantIsPressureTimesLengthTimesThickness) {
  const auto element = make(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const ElementGeometry g = distorted(*element, 3, 2.5);
  for (int edge = 0; edge < 4; ++edge) {
    const FaceDef& fd = element->faces()[edge];
    Eigen::VectorXd f, area;
    element->pressure_load(g, edge, 3.0, f);
    element->nodal_areas(g, edge, area);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int a = 0; a < element->node_count(); ++a) total += f.segment<3>(3 * a);
    // Straight edges for the 4-node element; the 8-node edge is curved (moved mid node), so
    // compare with the integrated area vector instead: |F| = p * sum(area).
    const Eigen::Vector2d from = g.X.row(fd.nodes[0]).head<2>(),
                          to = g.X.row(fd.nodes[1]).head<2>();
    if (element->node_count() == 4) {
      const double length = (to - from).norm();
      EXPECT_NEAR(area.sum(), length * 2.5, 1e-13);
      // Inward: the edge runs counter-clockwise, the inward normal is its left side.
      const Eigen::Vector2d left(-(to - from).y(), (to - from).x());
      EXPECT_NEAR(total.head<2>().dot(left.normalized()), 3.0 * length * 2.5, 1e-12);
      EXPECT_NEAR(f(3 * fd.nodes[0]), f(3 * fd.nodes[1]), 1e-14);  // half to each end
    } else {
      // The resultant of a uniform pressure on any curve is p t (chord rotated inward).
      const Eigen::Vector2d left(-(to - from).y(), (to - from).x());
      EXPECT_LT((total.head<2>() - 3.0 * 2.5 * left).norm(), 1e-12);
    }
    EXPECT_EQ(total.z(), 0.0);
    for (int a = 0; a < element->node_count(); ++a) {
      if (std::find(fd.nodes.begin(), fd.nodes.end(), a) == fd.nodes.end()) {
        EXPECT_EQ(f.segment<3>(3 * a).norm(), 0.0);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Elements, PlaneFamily,
    ::testing::Combine(::testing::Values(4, 8),
                       ::testing::Values(PlaneKind::Stress, PlaneKind::Strain)),
    [](const auto& test_info) {
      return (std::get<1>(test_info.param) == PlaneKind::Stress ? std::string("CPS") : "CPE") +
             std::to_string(std::get<0>(test_info.param));
    });

TEST(PlaneElements, NamesRulesAndEdges) {
  EXPECT_EQ(PlaneQuad4(PlaneKind::Stress).name(), "CPS4");
  EXPECT_EQ(PlaneQuad4(PlaneKind::Strain).name(), "CPE4");
  EXPECT_EQ(PlaneQuad8(PlaneKind::Stress).name(), "CPS8");
  EXPECT_EQ(PlaneQuad8(PlaneKind::Strain).name(), "CPE8");
  EXPECT_EQ(PlaneQuad4(PlaneKind::Stress).rule(RuleKind::Full).size(), 4);
  EXPECT_EQ(PlaneQuad8(PlaneKind::Strain).rule(RuleKind::Full).size(), 9);
  EXPECT_NEAR(PlaneQuad8(PlaneKind::Strain).rule(RuleKind::Full).weights[4], 64.0 / 81.0, 1e-15);
  // P3 of the 8-node element: corner 3 to corner 4 (0-based 2, 3), then mid node 7 (0-based 6).
  const PlaneQuad8 cps8(PlaneKind::Stress);
  const FaceDef& p3 = cps8.faces()[2];
  EXPECT_EQ(p3.nodes, (std::vector<int>{2, 3, 6}));
  EXPECT_EQ(p3.axis, 1);
  EXPECT_EQ(p3.value, 1.0);
}

TEST(PlaneElements, PlaneStrainIsPlaneStressWithTheConvertedConstants) {
  // Exact identity: plane strain (E, nu) = plane stress (E / (1 - nu^2), nu / (1 - nu)).
  const double nu = 0.3;
  Material strain_material = unit_material();
  Material stress_material = unit_material();
  stress_material.young = 1.0 / (1.0 - nu * nu);
  stress_material.poisson = nu / (1.0 - nu);
  for (int nodes : {4, 8}) {
    const auto cpe = make(nodes, PlaneKind::Strain);
    const auto cps = make(nodes, PlaneKind::Stress);
    const ElementGeometry g = distorted(*cpe, 17);
    Eigen::MatrixXd Ke, Ks;
    cpe->stiffness(g, strain_material, RuleKind::Full, Ke);
    cps->stiffness(g, stress_material, RuleKind::Full, Ks);
    EXPECT_LT((Ke - Ks).cwiseAbs().maxCoeff(), 1e-14 * Ke.cwiseAbs().maxCoeff()) << nodes;
  }
}

TEST(PlaneElements, UniaxialStressInPlaneStressAndPlaneStrain) {
  // sigma22 = 0 under eps11 = e: plane stress eps22 = -nu e, S11 = E e, S33 = 0,
  // E33 = -nu e; plane strain eps22 = -nu/(1-nu) e, S11 = E e/(1-nu^2), S33 = nu S11, E33 = 0.
  const double E = 1.0, nu = 0.3, e = 1e-3;
  for (PlaneKind kind : {PlaneKind::Stress, PlaneKind::Strain}) {
    const PlaneQuad4 element(kind);
    const ElementGeometry g = distorted(element, 23);
    const bool stress_state = kind == PlaneKind::Stress;
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    G(0, 0) = e;
    G(1, 1) = stress_state ? -nu * e : -nu / (1.0 - nu) * e;
    Eigen::MatrixXd strain, stress;
    element.strains_stresses(g, unit_material(), RuleKind::Full,
                             test::linear_field(g, G, Eigen::Vector3d::Zero()), strain, stress);
    const double s11 = stress_state ? E * e : E * e / (1.0 - nu * nu);
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(stress(k, 0), s11, 1e-15);
      EXPECT_NEAR(stress(k, 1), 0.0, 1e-15);
      EXPECT_NEAR(stress(k, 2), stress_state ? 0.0 : nu * s11, 1e-15);
      EXPECT_NEAR(strain(k, 2), stress_state ? -nu * e : 0.0, 1e-15);
      EXPECT_EQ(stress(k, 4), 0.0);
      EXPECT_EQ(stress(k, 5), 0.0);
    }
  }
}

TEST(PlaneElements, FreeThermalExpansion) {
  // Free in-plane expansion (S11 = S22 = 0). Plane stress: eps11 = eps22 = alpha dT, stress-free,
  // E33 = alpha dT. Plane strain (eps33 = 0): S33 = -E alpha dT, so eps11 = eps22 =
  // -nu S33 / E + alpha dT = (1 + nu) alpha dT.
  Material material = unit_material();
  material.expansion = 1e-5;
  const double nu = 0.3, dT = 50.0, a = 1e-5 * dT;
  for (PlaneKind kind : {PlaneKind::Stress, PlaneKind::Strain}) {
    const PlaneQuad8 element(kind);
    const ElementGeometry g = distorted(element, 29, 3.0);
    const double in_plane = kind == PlaneKind::Stress ? a : (1.0 + nu) * a;
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    G(0, 0) = G(1, 1) = in_plane;
    const Eigen::VectorXd u = test::linear_field(g, G, Eigen::Vector3d::Zero());
    const Eigen::VectorXd nodal_dT = Eigen::VectorXd::Constant(8, dT);
    Eigen::MatrixXd strain, stress;
    element.strains_stresses(g, material, RuleKind::Full, u, strain, stress, {}, &nodal_dT);
    // The thermal load balances exactly: K u = f_th.
    Eigen::MatrixXd K;
    Eigen::VectorXd f;
    element.stiffness(g, material, RuleKind::Full, K);
    element.thermal_load(g, material, RuleKind::Full, nodal_dT, f);
    EXPECT_LT((K * u - f).cwiseAbs().maxCoeff(), 1e-15 * f.cwiseAbs().maxCoeff() + 1e-18);
    for (int k = 0; k < stress.rows(); ++k) {
      EXPECT_NEAR(stress(k, 0), 0.0, 1e-15);
      EXPECT_NEAR(stress(k, 1), 0.0, 1e-15);
      EXPECT_NEAR(stress(k, 2), kind == PlaneKind::Stress ? 0.0 : -a, 1e-15);
      EXPECT_NEAR(strain(k, 2), kind == PlaneKind::Stress ? a : 0.0, 1e-17);
    }
  }
}

TEST(PlaneElements, BadThicknessAndClockwiseNodesAreInputErrorsAtTheElement) {
  const PlaneQuad4 element(PlaneKind::Stress);
  ElementGeometry g = test::reference_geometry(element, 42);
  g.cross_section = -1.0;
  Eigen::MatrixXd K;
  try {
    element.stiffness(g, unit_material(), RuleKind::Full, K);
    FAIL() << "negative thickness accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 7);
    EXPECT_NE(std::string(error.what()).find("element 42 (CPS4): thickness -1"), std::string::npos)
        << error.what();
  }
  g.cross_section = 1.0;
  g.X.row(1).swap(g.X.row(3));  // clockwise
  EXPECT_THROW(element.stiffness(g, unit_material(), RuleKind::Full, K), InputError);
}

}  // namespace
}  // namespace styk
