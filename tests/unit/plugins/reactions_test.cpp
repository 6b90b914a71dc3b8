// The thesis' single-element tests, SPEC section 2.2-2.4 / Tab. 2.6-2.8, as reproduced in
// elements-ref/README.md section 6 ("Comparison with the thesis tables"): reference cube
// [-1, 1]^3, nu = 0.3 (E drops out; E = 1), full integration, bottom nodes supported in z only
// plus the minimal in-plane rigid-body removal (node 1: x, y; node 2: y), the top face loaded with
// the thesis' CF3 values; the bottom reactions RF3 are compared with the tables.
#include <map>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "plugin_fixtures.hpp"

namespace styk {
namespace {

// Solves K u = f with u = 0 on the constrained dofs (a tiny dense solve) and returns the
// reactions R = K u - f (non-zero only on constrained dofs, up to round-off).
Eigen::VectorXd reactions(const Eigen::MatrixXd& K, const Eigen::VectorXd& f,
                          const std::vector<bool>& fixed) {
  std::vector<int> free;
  for (int i = 0; i < K.rows(); ++i)
    if (!fixed[i]) free.push_back(i);
  const int m = static_cast<int>(free.size());
  Eigen::MatrixXd Kff(m, m);
  Eigen::VectorXd ff(m);
  for (int a = 0; a < m; ++a) {
    ff(a) = f(free[a]);
    for (int b = 0; b < m; ++b) Kff(a, b) = K(free[a], free[b]);
  }
  const Eigen::VectorXd uf = Kff.ldlt().solve(ff);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(K.rows());
  for (int a = 0; a < m; ++a) u(free[a]) = uf(a);
  EXPECT_LT((Kff * uf - ff).norm(), 1e-12 * ff.norm());
  return K * u - f;
}

// Bottom RF3 per node (1-based) for the given top CF3 (1-based node -> force).
std::map<int, double> bottom_reactions(const TElement& e, const std::map<int, double>& top_cf3) {
  Eigen::MatrixXd K;
  e.stiffness(test::reference_geometry(e), test::unit_material(), RuleKind::Full, K);
  const int n = e.node_count();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
  for (const auto& [node, force] : top_cf3) f(3 * (node - 1) + 2) = force;
  std::vector<bool> fixed(3 * n, false);
  for (int node : e.faces()[0].nodes) fixed[3 * node + 2] = true;  // z on S1
  fixed[0] = fixed[1] = true;                                      // node 1: x, y
  fixed[3 + 1] = true;                                             // node 2: y
  const Eigen::VectorXd R = reactions(K, f, fixed);
  std::map<int, double> out;
  double sum = 0.0;
  for (int node : e.faces()[0].nodes) {
    out[node + 1] = R(3 * node + 2);
    sum += R(3 * node + 2);
  }
  // Equilibrium: the reactions carry the applied load (sum 4); no in-plane reactions.
  double applied = 0.0;
  for (const auto& kv : top_cf3) applied -= kv.second;
  EXPECT_NEAR(sum, applied, 1e-10) << e.name();
  for (int dof : {0, 1, 4}) EXPECT_NEAR(R(dof), 0.0, 1e-10) << e.name() << " dof " << dof;
  return out;
}

// Top CF3 of Tab. 2.7/2.8 (C3D21, C3D28): corners +1/3, top mid-edges -4/3 (= -A_i of the
// serendipity top face; 1-based node numbers of the element).
std::map<int, double> serendipity_top_loads(const std::vector<int>& mid_edges) {
  std::map<int, double> cf3;
  for (int corner = 5; corner <= 8; ++corner) cf3[corner] = 1.0 / 3.0;
  for (int node : mid_edges) cf3[node] = -4.0 / 3.0;
  return cf3;
}

// Tab. 2.6 (C3D14): top CF3 corners -1/3, centre (node 10) -8/3; bottom RF3 corners 0.627497,
// centre (node 9) 1.490013 (elements-ref section 6, 6 decimals printed: tolerance 1e-6).
TEST(SingleElementReactions, C3D14Table2_6) {
  auto plugins = test::load_build_plugins();
  const TElement& e = *plugins->registry.find("C3D14");
  const auto rf3 = bottom_reactions(
      e, {{5, -1.0 / 3}, {6, -1.0 / 3}, {7, -1.0 / 3}, {8, -1.0 / 3}, {10, -8.0 / 3}});
  ASSERT_EQ(rf3.size(), 5u);
  for (int corner = 1; corner <= 4; ++corner) EXPECT_NEAR(rf3.at(corner), 0.627497, 1e-6);
  EXPECT_NEAR(rf3.at(9), 1.490013, 1e-6);
}

// Tab. 2.7 (C3D21): bottom RF3 corners 1/9, mid-edges 4/9, centre 16/9 (exact: the load is
// consistent, the stress uniform; tolerance 1e-10).
TEST(SingleElementReactions, C3D21Table2_7) {
  auto plugins = test::load_build_plugins();
  const TElement& e = *plugins->registry.find("C3D21");
  const auto rf3 = bottom_reactions(e, serendipity_top_loads({13, 14, 15, 16}));
  ASSERT_EQ(rf3.size(), 9u);
  for (int node = 1; node <= 4; ++node) EXPECT_NEAR(rf3.at(node), 1.0 / 9.0, 1e-10);
  for (int node = 9; node <= 12; ++node) EXPECT_NEAR(rf3.at(node), 4.0 / 9.0, 1e-10);
  EXPECT_NEAR(rf3.at(21), 16.0 / 9.0, 1e-10);
}

// Tab. 2.8 (C3D28): bottom RF3 corners 1/36 (printed 0.027788, a misprint), edge nodes 17-24
// 5/36, interior 25-28 25/36 (exact, tolerance 1e-10).
TEST(SingleElementReactions, C3D28Table2_8) {
  auto plugins = test::load_build_plugins();
  const TElement& e = *plugins->registry.find("C3D28");
  const auto rf3 = bottom_reactions(e, serendipity_top_loads({13, 14, 15, 16}));
  ASSERT_EQ(rf3.size(), 16u);
  for (int node = 1; node <= 4; ++node) EXPECT_NEAR(rf3.at(node), 1.0 / 36.0, 1e-10);
  for (int node = 17; node <= 24; ++node) EXPECT_NEAR(rf3.at(node), 5.0 / 36.0, 1e-10);
  for (int node = 25; node <= 28; ++node) EXPECT_NEAR(rf3.at(node), 25.0 / 36.0, 1e-10);
}

}  // namespace
}  // namespace styk
