// DER of C3D8 and C3D20: interpolation properties, derivatives, and the face node lists.
#include <cmath>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "styk/elements/c3d20.hpp"
#include "styk/elements/c3d8.hpp"

namespace styk {
namespace {

std::vector<std::unique_ptr<TElement>> hexahedra() {
  std::vector<std::unique_ptr<TElement>> out;
  out.push_back(std::make_unique<C3D8>());
  out.push_back(std::make_unique<C3D20>());
  return out;
}

std::vector<Vec3> random_points(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(Vec3{u(rng), u(rng), u(rng)});
  return points;
}

// elements-ref/README.md section 5: Kronecker delta for C3D8 and C3D20; tolerance 1e-14.
TEST(HexShapeFunctions, KroneckerDeltaAtNodes) {
  for (const auto& e : hexahedra()) {
    const int n = e->node_count();
    ASSERT_EQ(static_cast<int>(e->natural_nodes().size()), n);
    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3);
    for (int j = 0; j < n; ++j) {
      e->der(e->natural_nodes()[j], N, dN);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(N(i), i == j ? 1.0 : 0.0, 1e-14)
            << e->name() << " N" << i + 1 << " at node " << j + 1;
    }
  }
}

// elements-ref/README.md section 5: partition of unity (sum N = 1, sum dN = 0) and linear
// completeness (sum N_i x_i = x, sum dN_i x_i = I) at random points; tolerance 1e-13.
TEST(HexShapeFunctions, PartitionOfUnityAndLinearCompleteness) {
  for (const auto& e : hexahedra()) {
    const int n = e->node_count();
    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3), X(n, 3);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 3; ++j) X(i, j) = e->natural_nodes()[i][j];
    for (const Vec3& xi : random_points(11, 25)) {
      e->der(xi, N, dN);
      EXPECT_NEAR(N.sum(), 1.0, 1e-13) << e->name();
      EXPECT_LT(dN.colwise().sum().cwiseAbs().maxCoeff(), 1e-13) << e->name();
      const Eigen::RowVector3d x = N.transpose() * X;
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(x(j), xi[j], 1e-13) << e->name();
      const Eigen::Matrix3d grad = dN.transpose() * X;
      EXPECT_LT((grad - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-13) << e->name();
    }
  }
}

// C3D20 is quadratically complete (elements-ref section 5): sum N_i xi_i eta_i = xi eta and
// sum N_i xi_i^2 = xi^2; C3D8 is not (xi^2 fails). Tolerance 1e-13.
TEST(HexShapeFunctions, QuadraticCompletenessOfC3D20Only) {
  C3D20 c3d20;
  C3D8 c3d8;
  Eigen::VectorXd N20(20), N8(8);
  Eigen::MatrixXd dN20(20, 3), dN8(8, 3);
  for (const Vec3& xi : random_points(5, 10)) {
    c3d20.der(xi, N20, dN20);
    double xy = 0.0, xx = 0.0;
    for (int i = 0; i < 20; ++i) {
      const Vec3& node = c3d20.natural_nodes()[i];
      xy += N20(i) * node[0] * node[1];
      xx += N20(i) * node[0] * node[0];
    }
    EXPECT_NEAR(xy, xi[0] * xi[1], 1e-13);
    EXPECT_NEAR(xx, xi[0] * xi[0], 1e-13);
    c3d8.der(xi, N8, dN8);
    double xx8 = 0.0;
    for (int i = 0; i < 8; ++i)
      xx8 += N8(i) * c3d8.natural_nodes()[i][0] * c3d8.natural_nodes()[i][0];
    EXPECT_NEAR(xx8, 1.0, 1e-13);  // trilinear interpolation of xi^2 is the constant 1
  }
}

// dN against central differences of N, step 1e-6: truncation O(h^2) ~ 1e-12 and round-off
// ~ 1e-16 / 1e-6 = 1e-10, so agreement to 1e-8 is required.
TEST(HexShapeFunctions, DerivativesMatchCentralDifferences) {
  const double h = 1e-6;
  for (const auto& e : hexahedra()) {
    const int n = e->node_count();
    Eigen::VectorXd N(n), Np(n), Nm(n);
    Eigen::MatrixXd dN(n, 3), scratch(n, 3);
    for (const Vec3& xi : random_points(29, 10)) {
      e->der(xi, N, dN);
      for (int j = 0; j < 3; ++j) {
        Vec3 plus = xi, minus = xi;
        plus[j] += h;
        minus[j] -= h;
        e->der(plus, Np, scratch);
        e->der(minus, Nm, scratch);
        const Eigen::VectorXd fd = (Np - Nm) / (2.0 * h);
        EXPECT_LT((fd - dN.col(j)).cwiseAbs().maxCoeff(), 1e-8) << e->name() << " d/dxi" << j;
      }
    }
  }
}

// Abaqus faces (task brief, elements-ref section 1): each listed node lies on the face plane, the
// list holds every node on it, and every shape function of a node off the face vanishes there
// (elements-ref section 5, "off-face N_i = 0"); tolerance 1e-14.
TEST(HexShapeFunctions, FacesListExactlyTheNodesOnThem) {
  for (const auto& e : hexahedra()) {
    const int n = e->node_count();
    ASSERT_EQ(e->faces().size(), 6u);
    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3);
    for (std::size_t f = 0; f < 6; ++f) {
      const FaceDef& face = e->faces()[f];
      EXPECT_EQ(static_cast<int>(face.nodes.size()), n == 8 ? 4 : 8);
      std::vector<bool> on_face(n, false);
      for (int node : face.nodes) on_face[node] = true;
      for (int i = 0; i < n; ++i)
        EXPECT_EQ(on_face[i], e->natural_nodes()[i][face.axis] == face.value)
            << e->name() << " S" << f + 1 << " node " << i + 1;
      for (const Vec3& p : random_points(static_cast<unsigned>(f), 5)) {
        Vec3 xi = p;
        xi[face.axis] = face.value;
        e->der(xi, N, dN);
        for (int i = 0; i < n; ++i)
          if (!on_face[i]) {
            EXPECT_NEAR(N(i), 0.0, 1e-14) << e->name() << " S" << f + 1;
          }
      }
    }
  }
}

// The exact Abaqus node lists of the brief (1-based): S1 1-2-3-4 (+9,10,11,12), S4 2-6-7-3
// (+18,14,19,10), S6 4-8-5-1 (+20,16,17,12).
TEST(HexShapeFunctions, C3D20FaceNodeOrderIsAbaqus) {
  C3D20 e;
  auto one_based = [&](int face) {
    std::vector<int> out;
    for (int node : e.faces()[face].nodes) out.push_back(node + 1);
    return out;
  };
  EXPECT_EQ(one_based(0), (std::vector<int>{1, 2, 3, 4, 9, 10, 11, 12}));
  EXPECT_EQ(one_based(1), (std::vector<int>{5, 8, 7, 6, 16, 15, 14, 13}));
  EXPECT_EQ(one_based(2), (std::vector<int>{1, 5, 6, 2, 17, 13, 18, 9}));
  EXPECT_EQ(one_based(3), (std::vector<int>{2, 6, 7, 3, 18, 14, 19, 10}));
  EXPECT_EQ(one_based(4), (std::vector<int>{3, 7, 8, 4, 19, 15, 20, 11}));
  EXPECT_EQ(one_based(5), (std::vector<int>{4, 8, 5, 1, 20, 16, 17, 12}));
  C3D8 e8;
  EXPECT_EQ(e8.faces()[5].nodes, (std::vector<int>{3, 7, 4, 0}));
}

}  // namespace
}  // namespace styk
