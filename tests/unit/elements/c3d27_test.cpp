// C3D27 (27-node Lagrange hexahedron): DER, node layout, faces and face loads.
#include <cmath>

#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "styk/elements/c3d27.hpp"

namespace styk {
namespace {

using test::reference_geometry;

Vec3 sample_point(int k) {
  // Deterministic points inside and on the cube (not only Gauss points).
  const double t = 0.37 * k;
  return Vec3{std::sin(1.3 * t + 0.2), std::cos(0.7 * t) * 0.9, std::sin(2.1 * t - 0.4)};
}

// N_i(x_j) = delta_ij at the 27 nodes, to round-off (1e-14).
TEST(C3D27Shapes, KroneckerDeltaAtNodes) {
  C3D27 e;
  Eigen::VectorXd N(27);
  Eigen::MatrixXd dN(27, 3);
  ASSERT_EQ(e.natural_nodes().size(), 27u);
  for (int j = 0; j < 27; ++j) {
    e.der(e.natural_nodes()[j], N, dN);
    for (int i = 0; i < 27; ++i) EXPECT_NEAR(N(i), i == j ? 1.0 : 0.0, 1e-14) << i << " " << j;
  }
}

// Partition of unity (sum N = 1, sum dN = 0) and completeness to the full triquadratic space:
// sum N_i p(x_i) = p(x) for p in {xi^2 eta^2 zeta^2, xi eta^2, ...}; tolerance 1e-13.
TEST(C3D27Shapes, PartitionOfUnityAndTriquadraticCompleteness) {
  C3D27 e;
  Eigen::VectorXd N(27);
  Eigen::MatrixXd dN(27, 3);
  auto poly = [](const Vec3& x) {
    return 0.3 + x[0] - 2.0 * x[1] * x[2] + x[0] * x[0] * x[1] * x[1] * x[2] * x[2] +
           0.5 * x[0] * x[1] * x[1];
  };
  for (int k = 0; k < 20; ++k) {
    const Vec3 xi = sample_point(k);
    e.der(xi, N, dN);
    EXPECT_NEAR(N.sum(), 1.0, 1e-13);
    EXPECT_LT(dN.colwise().sum().cwiseAbs().maxCoeff(), 1e-13);
    double interpolated = 0.0;
    for (int i = 0; i < 27; ++i) interpolated += N(i) * poly(e.natural_nodes()[i]);
    EXPECT_NEAR(interpolated, poly(xi), 1e-13);
  }
}

// dN matches central differences of N (step 1e-6, tolerance 1e-8).
TEST(C3D27Shapes, DerivativesMatchCentralDifferences) {
  C3D27 e;
  Eigen::VectorXd N(27), Np(27), Nm(27);
  Eigen::MatrixXd dN(27, 3), scratch(27, 3);
  const double h = 1e-6;
  for (int k = 0; k < 10; ++k) {
    const Vec3 xi = sample_point(k);
    e.der(xi, N, dN);
    for (int d = 0; d < 3; ++d) {
      Vec3 plus = xi, minus = xi;
      plus[d] += h;
      minus[d] -= h;
      e.der(plus, Np, scratch);
      e.der(minus, Nm, scratch);
      const Eigen::VectorXd fd = (Np - Nm) / (2 * h);
      EXPECT_LT((fd - dN.col(d)).cwiseAbs().maxCoeff(), 1e-8) << "point " << k << " dir " << d;
    }
  }
}

// Node numbering (docs/elements.md): 1-20 as C3D20, 21-26 face centres on S1..S6, 27 centre.
TEST(C3D27Shapes, FaceCentresFollowFaceOrder) {
  C3D27 e;
  const auto& nodes = e.natural_nodes();
  const Vec3 expected[7] = {{0, 0, -1}, {0, 0, 1},  {0, -1, 0}, {1, 0, 0},
                            {0, 1, 0},  {-1, 0, 0}, {0, 0, 0}};
  for (int k = 0; k < 7; ++k)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(nodes[20 + k][d], expected[k][d]) << 21 + k;
  // Every face lists 9 nodes: exactly the nodes on its plane, with its own centre last.
  ASSERT_EQ(e.faces().size(), 6u);
  for (int f = 0; f < 6; ++f) {
    const FaceDef& face = e.faces()[f];
    ASSERT_EQ(face.nodes.size(), 9u);
    EXPECT_EQ(face.nodes.back(), 20 + f);
    int on_plane = 0;
    for (int i = 0; i < 27; ++i) on_plane += nodes[i][face.axis] == face.value;
    EXPECT_EQ(on_plane, 9);
    for (int i : face.nodes) EXPECT_EQ(nodes[i][face.axis], face.value) << "S" << f + 1;
  }
}

// Consistent loads of a unit pressure on a reference face (area 4): 9-node Lagrange weights
// corners 4/36, mid-edges 16/36, centre 64/36 (all positive), exact to 1e-14.
TEST(C3D27Shapes, FaceLoadsArePositiveLagrangeWeights) {
  C3D27 e;
  const ElementGeometry g = reference_geometry(e);
  for (int face = 0; face < 6; ++face) {
    Eigen::VectorXd area;
    e.nodal_areas(g, face, area);
    const auto& nodes = e.faces()[face].nodes;
    for (int k = 0; k < 9; ++k) {
      const double expected = k < 4 ? 4.0 / 36.0 : (k < 8 ? 16.0 / 36.0 : 64.0 / 36.0);
      EXPECT_NEAR(area(nodes[k]), expected, 1e-14) << "S" << face + 1 << " node " << nodes[k] + 1;
    }
    EXPECT_NEAR(area.sum(), 4.0, 1e-13);
  }
}

}  // namespace
}  // namespace styk
