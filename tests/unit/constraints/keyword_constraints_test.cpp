// *TIE, *COUPLING (*KINEMATIC, *DISTRIBUTING), *MPC, *PRE-TENSION SECTION and *EQUATION with
// node sets or on nodes without elements (issue 15 item 1) against hand values: homogeneous
// states the elements reproduce exactly, equilibrium of the loads carried, and the constraint
// equations themselves.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "keyword_test_support.hpp"

namespace styk {
namespace {

using test::max_deviation;
using test::solve_text;

// Two blocks stacked along z with their own nodes: the lower one 2 x 2 x 1 elements on
// [0,1]^2 x [0,1], the upper one n x n x 1 on [0,1]^2 x [1,2] (nodes from 1001, elements from
// 101). Sets LBASE (z = 0), UTOP (z = 2); surfaces LTOP (lower top faces), UBOT (upper bottom).
std::string stacked_blocks(int n) {
  std::string d = "*NODE, NSET=NALL\n";
  auto lower = [](int i, int j, int k) { return 1 + i + 3 * j + 9 * k; };
  auto upper = [n](int i, int j, int k) { return 1001 + i + (n + 1) * j + (n + 1) * (n + 1) * k; };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        d += std::to_string(lower(i, j, k)) + ", " + std::to_string(0.5 * i) + ", " +
             std::to_string(0.5 * j) + ", " + std::to_string(1.0 * k) + "\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        d += std::to_string(upper(i, j, k)) + ", " + std::to_string(double(i) / n) + ", " +
             std::to_string(double(j) / n) + ", " + std::to_string(1.0 + k) + "\n";
  d += "*ELEMENT, TYPE=C3D8, ELSET=ELOW\n";
  int e = 1;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      d += std::to_string(e++) + ", " + std::to_string(lower(i, j, 0)) + ", " +
           std::to_string(lower(i + 1, j, 0)) + ", " + std::to_string(lower(i + 1, j + 1, 0)) +
           ", " + std::to_string(lower(i, j + 1, 0)) + ", " + std::to_string(lower(i, j, 1)) +
           ", " + std::to_string(lower(i + 1, j, 1)) + ", " +
           std::to_string(lower(i + 1, j + 1, 1)) + ", " + std::to_string(lower(i, j + 1, 1)) +
           "\n";
  d += "*ELEMENT, TYPE=C3D8, ELSET=EUP\n";
  e = 101;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      d += std::to_string(e++) + ", " + std::to_string(upper(i, j, 0)) + ", " +
           std::to_string(upper(i + 1, j, 0)) + ", " + std::to_string(upper(i + 1, j + 1, 0)) +
           ", " + std::to_string(upper(i, j + 1, 0)) + ", " + std::to_string(upper(i, j, 1)) +
           ", " + std::to_string(upper(i + 1, j, 1)) + ", " +
           std::to_string(upper(i + 1, j + 1, 1)) + ", " + std::to_string(upper(i, j + 1, 1)) +
           "\n";
  d += "*ELSET, ELSET=EALL\nELOW, EUP\n*NSET, NSET=LBASE\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) d += std::to_string(lower(i, j, 0)) + "\n";
  d += "*NSET, NSET=UTOP\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) d += std::to_string(upper(i, j, 1)) + "\n";
  d += "*SURFACE, NAME=LTOP\n1, S2\n2, S2\n3, S2\n4, S2\n*SURFACE, NAME=UBOT\n";
  for (int k = 101; k < 101 + n * n; ++k) d += std::to_string(k) + ", S1\n";
  d += "*SURFACE, NAME=UTOPF\n";
  for (int k = 101; k < 101 + n * n; ++k) d += std::to_string(k) + ", S2\n";
  d += "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n";
  return d;
}

// A fine block (4 x 4) tied onto a coarse one (2 x 2) and pulled by a uniform traction of 50
// on its top: every integration point of both blocks carries sigma_zz = 50; the lower block
// stands on its base with free lateral contraction. 1e-10 relative. The homogeneous state is
// exact only when the fine face nests in the coarse one: the slave forces reach the master
// nodes with the master shape functions taken at the slave nodes, which add up to the coarse
// consistent load only if every fine face lies inside one coarse face (with 3 x 3 on 2 x 2 the
// kink of the coarse shape functions at 0.5 cuts fine faces, and CalculiX 2.20 gives the same
// 5 % scatter of sigma_zz as Styk).
TEST(KeywordConstraints, TieTransmitsAHomogeneousStress) {
  const std::string deck = stacked_blocks(4) +
                           "*TIE, NAME=T\nUBOT, LTOP\n*BOUNDARY\nLBASE, 3\n1, 1, 2\n3, 2\n"
                           "*STEP\n*STATIC\n*DSLOAD\nUTOPF, P, -50.\n*END STEP\n";
  const test::Solved s = solve_text("tie_homogeneous.inp", deck);
  const IncrementResult& inc = s.results.increments[0];
  EXPECT_LT(max_deviation(inc.S, 2, 50.0), 1e-10 * 50.0);
  EXPECT_LT(max_deviation(inc.S, 0, 0.0), 1e-10 * 50.0);
  // The slave node at (1/4, 0, 1), inside a coarse face edge, follows the master face: its uz is
  // the strain times the lower block's height 1.
  const double eps = 50.0 / 210000.0;
  EXPECT_NEAR(test::displacement(s, 1002)[2], eps, 1e-10 * eps);
}

// *COUPLING with *KINEMATIC 1, 1: the end face of a bar keeps its x motion rigid with the
// reference node (lateral contraction free), which takes the force F = 30: the bar carries
// sigma_xx = F / A = 30 everywhere and the reference node moves with the face. 1e-10 relative.
TEST(KeywordConstraints, KinematicCouplingPullsABar) {
  const std::string deck =
      test::unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
      "*NODE\n900, 1.5, 0.5, 0.5\n*SURFACE, NAME=END\n2, S4\n4, S4\n6, S4\n8, S4\n"
      "*COUPLING, REF NODE=900, SURFACE=END, CONSTRAINT NAME=KC\n*KINEMATIC\n1, 1\n" +
      test::kSymmetricSupports + "*STEP\n*STATIC\n*CLOAD\n900, 1, 30.\n*END STEP\n";
  const test::Solved s = solve_text("kinematic_bar.inp", deck);
  const IncrementResult& inc = s.results.increments[0];
  EXPECT_LT(max_deviation(inc.S, 0, 30.0), 1e-10 * 30.0);
  EXPECT_NEAR(test::displacement(s, 900)[0], 30.0 / 210000.0, 1e-10 * 30.0 / 210000.0);
}

// *DISTRIBUTING: forces (3, -2, 5) and moments (1, -4, 2) on a reference node off the end face
// of a cantilever reach the structure with the same resultant: the supports react -F and the
// moment about the origin -(M + x_ref x F). 1e-10 of the largest term.
TEST(KeywordConstraints, DistributingCouplingKeepsResultantAndMoment) {
  const std::string deck =
      test::unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
      "*NODE\n900, 1.6, 0.3, 0.7\n*SURFACE, NAME=END\n2, S4\n4, S4\n6, S4\n8, S4\n"
      "*COUPLING, REF NODE=900, SURFACE=END, CONSTRAINT NAME=DC\n*DISTRIBUTING\n4, 6\n"
      "*BOUNDARY\nX0, 1, 3\n*STEP\n*STATIC\n*CLOAD\n900, 1, 3.\n900, 2, -2.\n900, 3, 5.\n"
      "900, 4, 1.\n900, 5, -4.\n900, 6, 2.\n*END STEP\n";
  const test::Solved s = solve_text("distributing.inp", deck);
  const IncrementResult& inc = s.results.increments[0];
  Eigen::Vector3d R = Eigen::Vector3d::Zero(), MR = Eigen::Vector3d::Zero();
  for (int n = 0; n < s.model.node_count(); ++n) {
    const Eigen::Vector3d rf(inc.RF[n][0], inc.RF[n][1], inc.RF[n][2]);
    const Eigen::Vector3d x(s.model.coords[n][0], s.model.coords[n][1], s.model.coords[n][2]);
    R += rf;
    MR += x.cross(rf);
  }
  const Eigen::Vector3d F(3.0, -2.0, 5.0), M(1.0, -4.0, 2.0), xref(1.6, 0.3, 0.7);
  EXPECT_LT((R + F).norm(), 1e-10 * F.norm());
  EXPECT_LT((MR + M + xref.cross(F)).norm(), 1e-10 * (M.norm() + xref.cross(F).norm()));
  // The reference node is not connected: CalculiX prints 0 for it, and so does Styk.
  EXPECT_EQ(test::displacement(s, 900)[0], 0.0);
}

// *MPC: the linearised BEAM, STRAIGHT and PLANE conditions (first order variations of the
// distance, of the cross product with the line and of the distance to the plane) hold exactly in
// the solution.
TEST(KeywordConstraints, MpcConditionsHold) {
  const std::string deck =
      test::unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
      // BEAM 21-27 (top face, y 0 -> 1 at x = 0, 1): their distance stays; STRAIGHT: 19, 21
      // define a line along x at y = z = 1... (top-left edge), 20 stays on it; PLANE: 1, 3, 7
      // (the base), node 5 (base centre) stays in it.
      "*MPC\nBEAM, 21, 27\nSTRAIGHT, 19, 21, 20\nPLANE, 1, 3, 7, 5\n"
      "*BOUNDARY\nX0, 1, 3\n*STEP\n*STATIC\n*CLOAD\n27, 2, 4.\n20, 3, -3.\n5, 3, 2.\n21, 1, 1.\n"
      "*END STEP\n";
  const test::Solved s = solve_text("mpc.inp", deck);
  auto u = [&](Id n) {
    const Vec3 v = test::displacement(s, n);
    return Eigen::Vector3d(v[0], v[1], v[2]);
  };
  auto x = [&](Id n) {
    const Vec3 v = s.model.coords[s.model.node_index(n)];
    return Eigen::Vector3d(v[0], v[1], v[2]);
  };
  const double scale = u(27).norm();
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(std::abs((x(27) - x(21)).dot(u(27) - u(21))), 1e-12 * scale);
  const Eigen::Vector3d t = x(21) - x(19);
  EXPECT_LT(((u(20) - u(19)).cross(t) + (x(20) - x(19)).cross(u(21) - u(19))).norm(),
            1e-12 * scale);
  // PLANE: the first order variation of (x5 - x1) . n with n = (x3 - x1) x (x7 - x1); node 3
  // moves, so the plane turns and the n . (u5 - u1) term alone is not zero.
  const Eigen::Vector3d r = x(5) - x(1), b = x(3) - x(1), c = x(7) - x(1);
  EXPECT_LT(std::abs((u(5) - u(1)).dot(b.cross(c)) + (u(3) - u(1)).dot(c.cross(r)) +
                     (u(7) - u(1)).dot(r.cross(b))),
            1e-12 * scale);
}

// A bolt 1 x 1 x 4 along z (2 x 2 x 8 C3D8) held at both ends along z with free lateral
// contraction and cut at z = 2 by a *PRE-TENSION SECTION: a force F = 800 on the reference node
// puts the whole bolt in tension sigma_zz = F / A = 800; a shortening d = 0.002 gives
// sigma_zz = E d / L = 105. 1e-10 relative.
TEST(KeywordConstraints, PretensionForceAndShortening) {
  std::string mesh = "*NODE, NSET=NALL\n";
  auto id = [](int i, int j, int k) { return 1 + i + 3 * j + 9 * k; };
  for (int k = 0; k <= 8; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        mesh += std::to_string(id(i, j, k)) + ", " + std::to_string(0.5 * i) + ", " +
                std::to_string(0.5 * j) + ", " + std::to_string(0.5 * k) + "\n";
  mesh += "9000, 0., 0., 0.\n*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
  int e = 1;
  std::string cut = "*SURFACE, NAME=CUT\n";
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        mesh += std::to_string(e) + ", " + std::to_string(id(i, j, k)) + ", " +
                std::to_string(id(i + 1, j, k)) + ", " + std::to_string(id(i + 1, j + 1, k)) +
                ", " + std::to_string(id(i, j + 1, k)) + ", " + std::to_string(id(i, j, k + 1)) +
                ", " + std::to_string(id(i + 1, j, k + 1)) + ", " +
                std::to_string(id(i + 1, j + 1, k + 1)) + ", " +
                std::to_string(id(i, j + 1, k + 1)) + "\n";
        if (k == 3) cut += std::to_string(e) + ", S2\n";
        ++e;
      }
  mesh += "*NSET, NSET=ENDS\n";
  for (int k : {0, 8})
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) mesh += std::to_string(id(i, j, k)) + "\n";
  mesh += "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n" +
          cut +
          "*PRE-TENSION SECTION, SURFACE=CUT, NODE=9000\n0., 0., 1.\n"
          "*BOUNDARY\nENDS, 3\n1, 1, 2\n3, 2\n73, 1, 2\n75, 2\n";
  const test::Solved force = solve_text(
      "pretension_force.inp", mesh + "*STEP\n*STATIC\n*CLOAD\n9000, 1, 800.\n*END STEP\n");
  EXPECT_LT(max_deviation(force.results.increments[0].S, 2, 800.0), 1e-10 * 800.0);
  const test::Solved shortening =
      solve_text("pretension_shortening.inp",
                 mesh + "*STEP\n*STATIC\n*BOUNDARY\n9000, 1, 1, 0.002\n*END STEP\n");
  const double sigma = 210000.0 * 0.002 / 4.0;
  EXPECT_LT(max_deviation(shortening.results.increments[0].S, 2, sigma), 1e-10 * sigma);
  EXPECT_NEAR(test::displacement(shortening, 9000)[0], 0.002, 1e-15);
}

// *EQUATION with a node set (Abaqus): every node of TIP moves along z with node 900, which
// belongs to no element and takes the load; and a plain equation on that node alone.
TEST(KeywordConstraints, EquationWithNodeSetAndElementlessNode) {
  const std::string deck =
      test::unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
      "*NODE\n900, 1.5, 0.5, 0.5\n*NSET, NSET=TIP\n3, 6, 9, 12, 15, 18, 21, 24, 27\n"
      "*EQUATION\n2\nTIP, 3, 1., 900, 3, -1.\n*BOUNDARY\nX0, 1, 3\n"
      "*STEP\n*STATIC\n*CLOAD\n900, 3, -6.\n*END STEP\n";
  const test::Solved s = solve_text("equation_sets.inp", deck);
  const double u900 = test::displacement(s, 900)[2];
  ASSERT_LT(u900, 0.0);
  for (Id n : {3, 6, 9, 12, 15, 18, 21, 24, 27})
    EXPECT_NEAR(test::displacement(s, n)[2], u900, 1e-12 * std::abs(u900)) << n;
  // The reference node's force reaches the clamped face: the reactions sum to +6.
  double rz = 0.0;
  for (const Vec3& rf : s.results.increments[0].RF) rz += rf[2];
  EXPECT_NEAR(rz, 6.0, 1e-10);
}

}  // namespace
}  // namespace styk
