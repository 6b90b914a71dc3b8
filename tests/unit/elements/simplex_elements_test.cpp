// The tetrahedra C3D4/C3D10 and wedges C3D6/C3D15: shape functions (Kronecker, completeness,
// derivatives), CalculiX's integration points, faces and their consistent pressure loads, the
// stiffness against its own strain energy (finite differences), zero-energy modes of the full and
// reduced rules, the constant-strain patch on a distorted element, and their self-description.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <Eigen/Dense>

#include "element_checks.hpp"
#include "element_fixtures.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/face_param.hpp"
#include "styk/elements/builtin.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

const TElement& element(const std::string& type) {
  return *test::shared_builtin_registry().find(type);
}

// The reference element with every node moved by up to `amplitude` (mid-edge nodes too: curved
// edges for the quadratic types).
ElementGeometry distorted(const TElement& e, unsigned seed, double amplitude = 0.06) {
  ElementGeometry g = test::reference_geometry(e);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-amplitude, amplitude);
  for (int i = 0; i < g.X.rows(); ++i)
    for (int j = 0; j < 3; ++j) g.X(i, j) += shift(rng);
  return g;
}

class SimplexFamily : public ::testing::TestWithParam<std::string> {};

TEST_P(SimplexFamily, ShapeFunctionsAreKroneckerCompleteAndDifferentiated) {
  const TElement& e = element(GetParam());
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (int i = 0; i < n; ++i) {
    e.der(e.natural_nodes()[i], N, dN);
    for (int j = 0; j < n; ++j) EXPECT_NEAR(N(j), i == j ? 1.0 : 0.0, 1e-14) << i << "," << j;
  }
  const bool quadratic = n > static_cast<int>(corner_nodes(e).size());
  for (const Vec3& xi : {Vec3{0.2, 0.15, 0.3}, Vec3{0.05, 0.6, -0.4}, Vec3{0.3, 0.3, 0.1}}) {
    e.der(xi, N, dN);
    EXPECT_NEAR(N.sum(), 1.0, 1e-14);
    // Linear completeness: sum N_i x_i = x; quadratic types reproduce x y and z^2 too.
    for (int d = 0; d < 3; ++d) {
      double x = 0.0;
      for (int i = 0; i < n; ++i) x += N(i) * e.natural_nodes()[i][d];
      EXPECT_NEAR(x, xi[d], 1e-14);
    }
    if (quadratic) {
      double xy = 0.0, zz = 0.0;
      for (int i = 0; i < n; ++i) {
        const Vec3& p = e.natural_nodes()[i];
        xy += N(i) * p[0] * p[1];
        zz += N(i) * p[2] * p[2];
      }
      EXPECT_NEAR(xy, xi[0] * xi[1], 1e-14);
      EXPECT_NEAR(zz, xi[2] * xi[2], 1e-14);
    }
    // dN against central differences (step 1e-6; the functions are polynomials of degree <= 3).
    for (int d = 0; d < 3; ++d) {
      Vec3 plus = xi, minus = xi;
      plus[d] += 1e-6;
      minus[d] -= 1e-6;
      Eigen::VectorXd Np(n), Nm(n);
      Eigen::MatrixXd scratch(n, 3);
      e.der(plus, Np, scratch);
      e.der(minus, Nm, scratch);
      EXPECT_LT(((Np - Nm) / 2e-6 - dN.col(d)).cwiseAbs().maxCoeff(), 1e-8) << d;
    }
  }
}

// Off-face shape functions vanish on every face (so faces conform), and every face is named as
// CalculiX does (checked: the face's corners first, the right count of nodes).
TEST_P(SimplexFamily, ShapeFunctionsOffAFaceVanishOnIt) {
  const TElement& e = element(GetParam());
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (const FaceDef& face : e.faces()) {
    EXPECT_EQ(face.axis, -1);
    const FaceParam param(e, face);
    const FaceRule rule = face_rule(param.triangle(), 3);
    for (const auto& pq : rule.points) {
      e.der(param.point(pq[0], pq[1]), N, dN);
      for (int k = 0; k < n; ++k)
        if (std::find(face.nodes.begin(), face.nodes.end(), k) == face.nodes.end()) {
          EXPECT_NEAR(N(k), 0.0, 1e-14) << "node " << k + 1;
        }
    }
  }
}

TEST_P(SimplexFamily, VolumeAndRigidMotionsOnADistortedElement) {
  const TElement& e = element(GetParam());
  const ElementGeometry ref = test::reference_geometry(e);
  const IntegrationRule rule = e.rule(RuleKind::Full);
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  double volume = 0.0;
  for (int k = 0; k < rule.size(); ++k) {
    e.der(rule.points[k], N, dN);
    volume += rule.weights[k] * e.point_measure(ref, N, dN, dNdx, k + 1);
  }
  // The reference tetrahedron 1/6, the reference wedge (triangle 1/2 x height 2) 1.
  EXPECT_NEAR(volume, n == 4 || n == 10 ? 1.0 / 6.0 : 1.0, 1e-14);
  const ElementGeometry g = distorted(e, 5);
  Eigen::MatrixXd K;
  e.stiffness(g, test::unit_material(), RuleKind::Full, K);
  EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0);
  Eigen::VectorXd translation(K.rows()), rotation(K.rows());
  for (int i = 0; i < n; ++i) {
    translation.segment<3>(3 * i) << 0.3, -0.2, 0.7;
    rotation.segment<3>(3 * i) << -g.X(i, 1), g.X(i, 0), 0.0;
  }
  const double scale = K.cwiseAbs().maxCoeff();
  EXPECT_LT((K * translation).norm(), 1e-12 * scale * translation.norm());
  EXPECT_LT((K * rotation).norm(), 1e-12 * scale * rotation.norm());
}

// A linear displacement field gives its constant strain at every integration point of a
// distorted element, and the stresses of Hooke's law (the patch test of one element), to 1e-12.
TEST_P(SimplexFamily, ConstantStrainIsReproducedOnADistortedElement) {
  const TElement& e = element(GetParam());
  const ElementGeometry g = distorted(e, 11);
  Eigen::Matrix3d G;
  G << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, 0.0, 3e-4, 1.5e-3;
  const Eigen::VectorXd u = test::linear_field(g, G, Eigen::Vector3d(0.1, -0.2, 0.3));
  Eigen::MatrixXd strain, stress;
  e.strains_stresses(g, test::unit_material(), RuleKind::Full, u, strain, stress);
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const double expected[6] = {eps(0, 0), eps(1, 1), eps(2, 2), eps(0, 1), eps(0, 2), eps(1, 2)};
  for (int k = 0; k < strain.rows(); ++k)
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(strain(k, c), expected[c], 1e-12) << k << "," << c;
}

// K against the derivative of the element's own strain energy (strains and stresses at the
// points), by central differences: agreement to 1e-9 of |K u|, full and reduced rules.
TEST_P(SimplexFamily, StiffnessIsTheGradientOfTheStrainEnergy) {
  const TElement& e = element(GetParam());
  const ElementGeometry g = distorted(e, 17);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd u(3 * e.node_count());
  for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = 1e-3 * value(rng);
  for (RuleKind kind : {RuleKind::Full, RuleKind::Reduced})
    EXPECT_LT(test::stiffness_gradient_error(e, g, test::unit_material(), kind, u), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(TetsAndWedges, SimplexFamily,
                         ::testing::Values("C3D4", "C3D10", "C3D6", "C3D15"));

// CalculiX 2.20's integration points on the reference elements (*EL PRINT, COORD, printed with
// the deck's coordinates = natural ones), in its order: C3D4 the centroid; C3D10 (a,a,a),
// (b,a,a), (a,b,a), (a,a,b) with a = 0.1381966, b = 0.5854102; C3D6 the triangle's centroid at
// zeta = -+1/sqrt3 (z 2.211325 / 2.788675 on a wedge from z = 2 to 3); C3D15 the triangle points
// (1/6,1/6), (2/3,1/6), (1/6,2/3), fastest, at zeta = -sqrt(0.6), 0, +sqrt(0.6).
TEST(SimplexRules, PointsAreCalculixs) {
  const auto points = [](const std::string& type) { return element(type).rule(RuleKind::Full); };
  EXPECT_EQ(points("C3D4").size(), 1);
  EXPECT_NEAR(points("C3D4").points[0][0], 0.25, 1e-15);
  const IntegrationRule c3d10 = points("C3D10");
  ASSERT_EQ(c3d10.size(), 4);
  const double a = 0.1381966, b = 0.5854102;
  const double expected10[4][3] = {{a, a, a}, {b, a, a}, {a, b, a}, {a, a, b}};
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(c3d10.points[k][d], expected10[k][d], 5e-8);
  const IntegrationRule c3d6 = points("C3D6");
  ASSERT_EQ(c3d6.size(), 2);
  EXPECT_NEAR(2.5 + 0.5 * c3d6.points[0][2], 2.211325, 5e-7);
  EXPECT_NEAR(2.5 + 0.5 * c3d6.points[1][2], 2.788675, 5e-7);
  EXPECT_NEAR(c3d6.points[0][0], 1.0 / 3.0, 1e-15);
  const IntegrationRule c3d15 = points("C3D15");
  ASSERT_EQ(c3d15.size(), 9);
  const double tri[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
  const double z[3] = {2.112702, 2.5, 2.887298};
  for (int k = 0; k < 9; ++k) {
    EXPECT_NEAR(c3d15.points[k][0], tri[k % 3][0], 1e-15);
    EXPECT_NEAR(c3d15.points[k][1], tri[k % 3][1], 1e-15);
    EXPECT_NEAR(2.5 + 0.5 * c3d15.points[k][2], z[k / 3], 5e-7);
  }
}

// Zero eigenvalues of one reference element (E = 1, nu = 0.3, relative 1e-9). A point gives at
// most 6 independent strains, so P points leave at least 3n - 6P zero modes: C3D10 reduced (1
// point) 30 - 6 = 24, C3D6 reduced (1 point) 18 - 6 = 12, C3D15 reduced (6 points) at least 9.
// With the full rules: 6 (rigid motions) except C3D6: its 2 points on the triangle's centroid
// line leave the twist u = zeta (-eta, xi, 0) about that line strain-free (7 = 6 + 1); the twist
// does not survive a patch (model_warnings_test: no hourglass warning for C3D6).
TEST(SimplexRules, ZeroEnergyModesOfFullAndReducedRules) {
  const auto zeros = [](const std::string& type, RuleKind kind) {
    const TElement& e = element(type);
    Eigen::MatrixXd K;
    e.stiffness(test::reference_geometry(e), test::unit_material(), kind, K);
    return test::active_zero_eigenvalues(e, K);
  };
  EXPECT_EQ(zeros("C3D4", RuleKind::Full), 6);
  EXPECT_EQ(zeros("C3D4", RuleKind::Reduced), 6);
  EXPECT_EQ(zeros("C3D10", RuleKind::Full), 6);
  EXPECT_EQ(zeros("C3D10", RuleKind::Reduced), 24);
  EXPECT_EQ(zeros("C3D6", RuleKind::Full), 7);
  EXPECT_EQ(zeros("C3D6", RuleKind::Reduced), 12);
  EXPECT_EQ(zeros("C3D15", RuleKind::Full), 6);
  EXPECT_GE(zeros("C3D15", RuleKind::Reduced), 9);
}

// Consistent loads of a unit pressure on flat faces of the reference elements (exact integrals
// of N_i over the face): linear triangle A/3 per corner; quadratic triangle 0 at the corners and
// A/3 at the mid-edges; bilinear quadrilateral A/4; 8-node quadrilateral -A/12 at the corners and
// A/3 at the mid-edges (as C3D20). The force pushes into the element: along minus the outward
// normal, which for the slanted tetrahedron face 3 is (1, 1, 1)/sqrt3 (area sqrt3/2).
TEST(SimplexFaces, ConsistentPressureLoads) {
  struct Case {
    const char* type;
    int face;             // 0-based
    double area;          // of the face
    Eigen::Vector3d out;  // outward unit normal
    double corner, mid;   // load per corner and per mid-edge node, over p A
  };
  const double s3 = std::sqrt(3.0);
  const Case cases[] = {
      {"C3D4", 0, 0.5, {0, 0, -1}, 1.0 / 3, 0},
      {"C3D4", 2, s3 / 2, {1 / s3, 1 / s3, 1 / s3}, 1.0 / 3, 0},
      {"C3D10", 0, 0.5, {0, 0, -1}, 0, 1.0 / 3},
      {"C3D10", 2, s3 / 2, {1 / s3, 1 / s3, 1 / s3}, 0, 1.0 / 3},
      {"C3D6", 0, 0.5, {0, 0, -1}, 1.0 / 3, 0},
      {"C3D6", 1, 0.5, {0, 0, 1}, 1.0 / 3, 0},
      {"C3D6", 2, 2.0, {0, -1, 0}, 0.25, 0},
      {"C3D6", 3, 2 * std::sqrt(2.0), {1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0}, 0.25, 0},
      {"C3D15", 1, 0.5, {0, 0, 1}, 0, 1.0 / 3},
      {"C3D15", 4, 2.0, {-1, 0, 0}, -1.0 / 12, 1.0 / 3},
  };
  for (const Case& c : cases) {
    const TElement& e = element(c.type);
    const ElementGeometry g = test::reference_geometry(e);
    Eigen::VectorXd f;
    e.pressure_load(g, c.face, 1.0, f);
    const FaceDef& face = e.faces()[c.face];
    const std::vector<int> corners = corner_nodes(e);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int k = 0; k < e.node_count(); ++k) {
      const Eigen::Vector3d fk = f.segment<3>(3 * k);
      total += fk;
      const bool on_face = std::find(face.nodes.begin(), face.nodes.end(), k) != face.nodes.end();
      const bool corner = std::binary_search(corners.begin(), corners.end(), k);
      const double expected = !on_face ? 0.0 : (corner ? c.corner : c.mid) * c.area;
      EXPECT_LT((fk + expected * c.out).norm(), 1e-13)
          << c.type << " face " << c.face + 1 << " node " << k + 1;
    }
    EXPECT_LT((total + c.area * c.out).norm(), 1e-13) << c.type << " face " << c.face + 1;
  }
}

// How the types describe themselves (element_description.hpp): solids, the VTK cells of the VTU
// export (VTK's wedge base turns the other way round), no conversion (they are split from bricks).
TEST(SimplexDescription, FormAndVtkCells) {
  for (const char* type : {"C3D4", "C3D10", "C3D6", "C3D15"}) {
    EXPECT_EQ(element(type).form(), ElementForm::Solid) << type;
    EXPECT_FALSE(element(type).conversion()) << type;
  }
  EXPECT_EQ(element("C3D4").vtk_cell().type, vtk::kTetra);
  EXPECT_EQ(element("C3D4").vtk_cell().nodes, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(element("C3D10").vtk_cell().type, vtk::kQuadraticTetra);
  EXPECT_EQ(element("C3D10").vtk_cell().nodes.size(), 10u);
  EXPECT_EQ(element("C3D6").vtk_cell().type, vtk::kWedge);
  EXPECT_EQ(element("C3D6").vtk_cell().nodes, (std::vector<int>{0, 2, 1, 3, 5, 4}));
  EXPECT_EQ(element("C3D15").vtk_cell().type, vtk::kQuadraticWedge);
  EXPECT_EQ(natural_centroid(element("C3D10"))[0], 0.25);
  EXPECT_NEAR(natural_centroid(element("C3D15"))[1], 1.0 / 3.0, 1e-15);
}

}  // namespace
}  // namespace styk
