// DER of the plug-in elements C3D14, C3D21, C3D28 (loaded through the loader): the closed forms
// of elements-ref/README.md, interpolation and completeness properties, derivatives, node tables
// and faces.
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plugin_fixtures.hpp"
#include "reference_formulas.hpp"

namespace styk {
namespace {

using test::random_points;

class ShapeFunctions : public test::PluginElementTest {};

Eigen::MatrixXd natural_matrix(const TElement& e) {
  Eigen::MatrixXd X(e.node_count(), 3);
  for (int i = 0; i < e.node_count(); ++i)
    for (int j = 0; j < 3; ++j) X(i, j) = e.natural_nodes()[i][j];
  return X;
}

// elements-ref section 1 node tables, checked through a few defining nodes of each element
// (1-based in the comments): C3D14 9 (0,0,-1), 11 (0,-1,0), 14 (1,0,0); C3D21 21 (0,0,-1);
// C3D28 9 (-1,-1,0), 13 (0,-1,1), 17 (-a,-1,-1), 20 (1,a,-1), 27 (a,a,-1). Exact to 1e-15.
TEST_P(ShapeFunctions, NodeTableMatchesElementsRef) {
  const TElement& e = element();
  const auto& n = e.natural_nodes();
  ASSERT_EQ(static_cast<int>(n.size()), e.node_count());
  auto expect_node = [&](int one_based, Vec3 x) {
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(n[one_based - 1][j], x[j], 1e-15) << e.name() << " node " << one_based;
  };
  const double a = 1.0 / std::sqrt(5.0);
  expect_node(1, {-1, -1, -1});
  expect_node(7, {1, 1, 1});
  if (e.name() == "C3D14") {
    EXPECT_EQ(e.node_count(), 14);
    expect_node(9, {0, 0, -1});
    expect_node(10, {0, 0, 1});
    expect_node(11, {0, -1, 0});
    expect_node(12, {0, 1, 0});
    expect_node(13, {-1, 0, 0});
    expect_node(14, {1, 0, 0});
  } else if (e.name() == "C3D21") {
    EXPECT_EQ(e.node_count(), 21);
    expect_node(9, {0, -1, -1});
    expect_node(17, {-1, -1, 0});
    expect_node(21, {0, 0, -1});
  } else {
    EXPECT_EQ(e.node_count(), 28);
    expect_node(9, {-1, -1, 0});
    expect_node(12, {-1, 1, 0});
    expect_node(13, {0, -1, 1});
    expect_node(16, {-1, 0, 1});
    expect_node(17, {-a, -1, -1});
    expect_node(20, {1, a, -1});
    expect_node(24, {-1, -a, -1});
    expect_node(25, {-a, -a, -1});
    expect_node(27, {a, a, -1});
  }
}

// The implementation (compact / blending forms) equals the printed formulas of elements-ref
// sections 2-4 at random points: all 14 of C3D14, N5-N8 and N21 of C3D21, all 28 of C3D28.
// Tolerance 1e-14 (round-off of O(1) polynomials).
TEST_P(ShapeFunctions, EqualsPrintedFormulas) {
  const TElement& e = element();
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  int compared = 0;
  for (const Vec3& p : random_points(41, 20)) {
    e.der(p, N, dN);
    for (int i = 0; i < n; ++i) {
      double expected = NAN;
      if (e.name() == "C3D14") expected = test::c3d14_printed(i, p);
      if (e.name() == "C3D21") expected = test::c3d21_printed(i, p);
      if (e.name() == "C3D28") expected = test::c3d28_closed_form(i, e.natural_nodes()[i], p);
      if (std::isnan(expected)) continue;
      EXPECT_NEAR(N(i), expected, 1e-14) << e.name() << " N" << i + 1;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 20 * (e.name() == "C3D21" ? 5 : n));
}

// elements-ref section 5: Kronecker delta at every node; tolerance 1e-14.
TEST_P(ShapeFunctions, KroneckerDeltaAtNodes) {
  const TElement& e = element();
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (int j = 0; j < n; ++j) {
    e.der(e.natural_nodes()[j], N, dN);
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(N(i), i == j ? 1.0 : 0.0, 1e-14)
          << e.name() << " N" << i + 1 << " at node " << j + 1;
  }
}

// elements-ref section 5: partition of unity (sum N = 1, sum dN = 0) and linear completeness
// (sum N_i x_i = x, sum dN_i x_i = I) at random points; tolerance 1e-13.
TEST_P(ShapeFunctions, PartitionOfUnityAndLinearCompleteness) {
  const TElement& e = element();
  const int n = e.node_count();
  const Eigen::MatrixXd X = natural_matrix(e);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (const Vec3& xi : random_points(11, 25)) {
    e.der(xi, N, dN);
    EXPECT_NEAR(N.sum(), 1.0, 1e-13) << e.name();
    EXPECT_LT(dN.colwise().sum().cwiseAbs().maxCoeff(), 1e-13) << e.name();
    const Eigen::RowVector3d x = N.transpose() * X;
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(x(j), xi[j], 1e-13) << e.name();
    const Eigen::Matrix3d grad = dN.transpose() * X;
    EXPECT_LT((grad - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-13) << e.name();
  }
}

// elements-ref section 5: C3D21 and C3D28 interpolate every quadratic monomial exactly
// (tolerance 1e-13); C3D14 does not: at the centre its interpolant of xi^2 is 8 x (-1/4) (corners)
// + 2 x 1/2 (the centres of the faces xi = +-1) = -1 instead of 0.
TEST_P(ShapeFunctions, QuadraticCompletenessOnlyForC3D21AndC3D28) {
  const TElement& e = element();
  const int n = e.node_count();
  const Eigen::MatrixXd X = natural_matrix(e);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  double worst = 0.0;
  for (const Vec3& xi : random_points(5, 15)) {
    e.der(xi, N, dN);
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        const double interpolated = N.dot(X.col(a).cwiseProduct(X.col(b)));
        worst = std::max(worst, std::abs(interpolated - xi[a] * xi[b]));
      }
  }
  if (e.name() == "C3D14") {
    e.der(Vec3{0.0, 0.0, 0.0}, N, dN);
    EXPECT_NEAR(N.dot(X.col(0).cwiseProduct(X.col(0))), -1.0, 1e-14);
    EXPECT_GT(worst, 0.1);
  } else
    EXPECT_LT(worst, 1e-13) << e.name();
}

// dN against central differences of N, step 1e-6: truncation ~1e-11 for these polynomials and
// round-off ~1e-10, so agreement to 1e-8 is required.
TEST_P(ShapeFunctions, DerivativesMatchCentralDifferences) {
  const TElement& e = element();
  const double h = 1e-6;
  const int n = e.node_count();
  Eigen::VectorXd N(n), Np(n), Nm(n);
  Eigen::MatrixXd dN(n, 3), scratch(n, 3);
  for (const Vec3& xi : random_points(29, 10)) {
    e.der(xi, N, dN);
    for (int j = 0; j < 3; ++j) {
      Vec3 plus = xi, minus = xi;
      plus[j] += h;
      minus[j] -= h;
      e.der(plus, Np, scratch);
      e.der(minus, Nm, scratch);
      const Eigen::VectorXd fd = (Np - Nm) / (2.0 * h);
      EXPECT_LT((fd - dN.col(j)).cwiseAbs().maxCoeff(), 1e-8) << e.name() << " d/dxi" << j;
    }
  }
}

// Faces (Abaqus S1..S6, elements-ref section 1): six faces; each lists every node lying on its
// plane and no other, without repeats, corners first (the 4 corners of the face), and every
// off-face shape function vanishes on the face (elements-ref section 5); tolerance 1e-14.
TEST_P(ShapeFunctions, FacesListExactlyTheNodesOnThem) {
  const TElement& e = element();
  const int n = e.node_count();
  ASSERT_EQ(e.faces().size(), 6u);
  const int expected_axis[6] = {2, 2, 1, 0, 1, 0};
  const double expected_value[6] = {-1, 1, -1, 1, 1, -1};
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (int f = 0; f < 6; ++f) {
    const FaceDef& face = e.faces()[f];
    EXPECT_EQ(face.axis, expected_axis[f]) << e.name() << " S" << f + 1;
    EXPECT_EQ(face.value, expected_value[f]) << e.name() << " S" << f + 1;
    EXPECT_EQ(std::set<int>(face.nodes.begin(), face.nodes.end()).size(), face.nodes.size());
    std::vector<bool> on_face(n, false);
    for (int node : face.nodes) {
      ASSERT_GE(node, 0);
      ASSERT_LT(node, n);
      on_face[node] = true;
    }
    for (int i = 0; i < n; ++i)
      EXPECT_EQ(on_face[i], e.natural_nodes()[i][face.axis] == face.value)
          << e.name() << " S" << f + 1 << " node " << i + 1;
    for (int k = 0; k < 4; ++k) {  // corners first: |xi| = |eta| = |zeta| = 1
      const Vec3& x = e.natural_nodes()[face.nodes[k]];
      EXPECT_EQ(std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]), 3.0)
          << e.name() << " S" << f + 1 << " entry " << k;
    }
    for (const Vec3& p : random_points(static_cast<unsigned>(f + 100), 5)) {
      Vec3 xi = p;
      xi[face.axis] = face.value;
      e.der(xi, N, dN);
      for (int i = 0; i < n; ++i)
        if (!on_face[i]) {
          EXPECT_NEAR(N(i), 0.0, 1e-14) << e.name() << " N" << i + 1 << " on S" << f + 1;
        }
    }
  }
}

// The exact face node lists (1-based) of elements-ref section 1 for the contact faces.
TEST(ContactHexahedronFaces, NodeListsAsInElementsRef) {
  auto plugins = test::load_build_plugins();
  auto one_based = [&](const std::string& name, int face) {
    std::vector<int> out;
    for (int node : plugins->registry.find(name)->faces()[face].nodes) out.push_back(node + 1);
    return out;
  };
  EXPECT_EQ(one_based("C3D14", 0), (std::vector<int>{1, 2, 3, 4, 9}));
  EXPECT_EQ(one_based("C3D14", 1), (std::vector<int>{5, 8, 7, 6, 10}));
  EXPECT_EQ(one_based("C3D14", 2), (std::vector<int>{1, 5, 6, 2, 11}));
  EXPECT_EQ(one_based("C3D14", 3), (std::vector<int>{2, 6, 7, 3, 14}));
  EXPECT_EQ(one_based("C3D14", 4), (std::vector<int>{3, 7, 8, 4, 12}));
  EXPECT_EQ(one_based("C3D14", 5), (std::vector<int>{4, 8, 5, 1, 13}));
  EXPECT_EQ(one_based("C3D21", 0), (std::vector<int>{1, 2, 3, 4, 9, 10, 11, 12, 21}));
  EXPECT_EQ(one_based("C3D21", 3), (std::vector<int>{2, 6, 7, 3, 18, 14, 19, 10}));
  EXPECT_EQ(one_based("C3D28", 0),
            (std::vector<int>{1, 2, 3, 4, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28}));
  EXPECT_EQ(one_based("C3D28", 1), (std::vector<int>{5, 8, 7, 6, 16, 15, 14, 13}));
  EXPECT_EQ(one_based("C3D28", 2), (std::vector<int>{1, 5, 6, 2, 9, 13, 10, 18, 17}));
  EXPECT_EQ(one_based("C3D28", 3), (std::vector<int>{2, 6, 7, 3, 10, 14, 11, 20, 19}));
  EXPECT_EQ(one_based("C3D28", 4), (std::vector<int>{3, 7, 8, 4, 11, 15, 12, 22, 21}));
  EXPECT_EQ(one_based("C3D28", 5), (std::vector<int>{4, 8, 5, 1, 12, 16, 9, 24, 23}));
}

// face_rule_order (brief): 3 for C3D14/C3D21, 4 for C3D28; rules per elements-ref section 7.
TEST_P(ShapeFunctions, IntegrationRules) {
  const TElement& e = element();
  const bool c3d28 = e.name() == "C3D28";
  EXPECT_EQ(e.face_rule_order(), c3d28 ? 4 : 3);
  EXPECT_EQ(e.rule(RuleKind::Full).size(), c3d28 ? 48 : 27);
  EXPECT_EQ(e.rule(RuleKind::Reduced).size(), c3d28 ? 27 : 8);
  EXPECT_FALSE(e.description().empty());
  EXPECT_EQ(e.description().find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(ContactHexahedra, ShapeFunctions,
                         ::testing::ValuesIn(test::contact_hexahedra()), test::element_name);

}  // namespace
}  // namespace styk
