// Penalty laws in the active-set iteration (penalty_law.hpp, friction_law.hpp): a spring of
// compliance e = 1 / (K A) in series with the structure. Hand values on one node on springs: the
// structure's normal compliance sn and the spring's e add, so a node pushed by w (its free motion
// into the gap) carries lambda_n = (w - gap0) / (sn + e) with the overclosure e lambda_n; pulled it
// opens (LINEAR) or carries the same tension (TIED).
#include <cmath>

#include <gtest/gtest.h>

#include "slip_rows_check.hpp"
#include "styk/contact/active_set.hpp"
#include "styk/contact/friction_law.hpp"
#include "styk/contact/penalty_law.hpp"
#include "styk/core/diagnostics.hpp"

namespace styk::contact {
namespace {

ContactConstraint spring_node(FrictionLaw::Kind kind, double mu, double stiffness, bool bonded) {
  ContactConstraint c;
  c.law.kind = kind;
  c.law.mu1 = c.law.mu2 = mu;
  c.area = 1.0;
  c.penalty_stiffness = stiffness;
  c.bonded = bonded;
  return c;
}

// One node on springs (structure compliance sn normal, st tangential), free motion w.
LinearContactSystem one_node(const ContactConstraint& c, double sn, double st,
                             const Eigen::Vector3d& w) {
  LinearContactSystem s;
  s.S = Eigen::MatrixXd::Zero(3, 3);
  s.S(0, 0) = sn;
  s.S(1, 1) = c.scale(1) * c.scale(1) * st;
  s.S(2, 2) = c.scale(2) * c.scale(2) * st;
  s.d0 = Eigen::Vector3d(w[0], c.scale(1) * w[1], c.scale(2) * w[2]);
  s.G.resize(3, 0);
  s.h.resize(0);
  return s;
}

TEST(PenaltyLaw, LinearSpringInSeriesCarriesTheHandForce) {
  // sn = 2, K A = 0.5 (e = 2): lambda_n = (1 - 0.2) / (2 + 2) = 0.2, overclosure 0.4.
  const std::vector<ContactConstraint> cs{
      spring_node(FrictionLaw::Kind::Frictionless, 0.0, 0.5, false)};
  const Eigen::Vector3d w(1.0, 0.0, 0.0);
  LinearContactSystem s = one_node(cs[0], 2.0, 1.0, w);
  ContactState state;
  ContactConstraint gap = cs[0];
  gap.gap0 = 0.2;
  const std::vector<ContactConstraint> with_gap{gap};
  const IncrementOutcome out = solve_increment(with_gap, s, state, ActiveSetOptions{}, {});
  ASSERT_TRUE(out.converged) << out.reason;
  EXPECT_NE(state.nodes[0].status, NodeStatus::Open);
  EXPECT_NEAR(state.nodes[0].lambda[0], 0.2, 1e-14);
  EXPECT_NEAR(state.nodes[0].d[0] - gap.gap0, 0.4, 1e-14);  // overclosure = lambda_n / (K A)
  // Pulled away it opens: no tension in LINEAR.
  s.d0[0] = -1.0;
  ContactState pulled;
  const IncrementOutcome open = solve_increment(with_gap, s, pulled, ActiveSetOptions{}, {});
  ASSERT_TRUE(open.converged) << open.reason;
  EXPECT_EQ(pulled.nodes[0].status, NodeStatus::Open);
  EXPECT_EQ(pulled.nodes[0].lambda[0], 0.0);
}

TEST(PenaltyLaw, TiedSpringCarriesTensionAndShear) {
  // sn = st = 1, K A = 1 (e = 1), free motion (-1, 0.5, -0.3): every component halves,
  // lambda = w / (s + e), tension included.
  const std::vector<ContactConstraint> cs{spring_node(FrictionLaw::Kind::Tied, 1.0, 1.0, true)};
  const LinearContactSystem s = one_node(cs[0], 1.0, 1.0, {-1.0, 0.5, -0.3});
  ContactState state;
  const IncrementOutcome out = solve_increment(cs, s, state, ActiveSetOptions{}, {});
  ASSERT_TRUE(out.converged) << out.reason;
  EXPECT_EQ(state.nodes[0].status, NodeStatus::Stick);
  EXPECT_NEAR(state.nodes[0].lambda[0], -0.5, 1e-14);
  EXPECT_NEAR(state.nodes[0].lambda[1], 0.25, 1e-14);
  EXPECT_NEAR(state.nodes[0].lambda[2], -0.15, 1e-14);
}

TEST(PenaltyLaw, CoulombSlipOnAPenaltyNormal) {
  // sn = 1, e = 1, mu = 0.3, free motion (2, 3, 0): lambda_n = 2 / 2 = 1 whatever the tangent
  // does (uncoupled springs), and the node slips with |lambda_t| = mu lambda_n = 0.3.
  const std::vector<ContactConstraint> cs{spring_node(FrictionLaw::Kind::Coulomb, 0.3, 1.0, false)};
  const LinearContactSystem s = one_node(cs[0], 1.0, 1.0, {2.0, 3.0, 0.0});
  ContactState state;
  const IncrementOutcome out = solve_increment(cs, s, state, ActiveSetOptions{}, {});
  ASSERT_TRUE(out.converged) << out.reason;
  EXPECT_EQ(state.nodes[0].status, NodeStatus::Slip);
  EXPECT_NEAR(state.nodes[0].lambda[0], 1.0, 1e-12);
  EXPECT_NEAR(0.3 * state.nodes[0].lambda.tail<2>().norm(), 0.3, 1e-12);
}

// With a penalty compliance the slip rows still are the derivatives of F_t (the compliance enters
// b = lambda_n + c_n (d_n - gap0 - e lambda_n)): central finite differences, as for exact contact.
TEST(PenaltyLaw, SlipTangentWithPenaltyMatchesFiniteDifferences) {
  LocalPoint p;
  p.lambda = {2.0, 0.7, -0.4};
  p.d = {0.9, 0.9, 0.25};
  p.d_ref = {0.0, 0.1, -0.2};
  p.gap0 = 0.3;
  p.c_n = 0.3;
  p.c_t = 2.3;
  p.compliance = 0.2;
  p.live = {true, true, true};
  ASSERT_EQ(classify(p), NodeStatus::Slip);
  const LocalRows rows = linearise(p, NodeStatus::Slip);
  test::expect_slip_rows_match_finite_differences(p, rows, 1e-6, 1e-7);
  // The normal row is the spring: d_n - e lambda_n = gap0.
  EXPECT_EQ(rows.Q(0, 0), 1.0);
  EXPECT_EQ(rows.D(0, 0), -0.2);
  EXPECT_EQ(rows.r[0], 0.3);
}

// The spring of one node is K A (A = 1 for a node surface, whose "pressure" is a force); a face
// node with a non-positive area (a C3D20 face corner, -1/12 of the unit square) is refused by name.
TEST(PenaltyLaw, SpringStiffnessIsSlopeTimesArea) {
  SurfaceInteraction interaction;
  interaction.name = "PEN";
  interaction.behavior.law = PressureOverclosure::Law::Linear;
  interaction.behavior.slope = 4e5;
  interaction.behavior.where = {"deck.inp", 12};
  Surface faces;
  faces.name = "SLAVE";
  ContactConstraint c;
  c.area = 0.25;
  apply_penalty_law(interaction, faces, "7", c);
  EXPECT_EQ(c.penalty_stiffness, 1e5);
  EXPECT_EQ(c.penalty_compliance(), 1e-5);
  EXPECT_FALSE(c.bonded);
  Surface nodes = faces;
  nodes.kind = Surface::Kind::Nodes;
  c.area = 0.0;
  apply_penalty_law(interaction, nodes, "7", c);
  EXPECT_EQ(c.penalty_stiffness, 4e5);
  c.area = -1.0 / 12.0;
  try {
    apply_penalty_law(interaction, faces, "7", c);
    ADD_FAILURE() << "a negative area was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 12);
    EXPECT_NE(e.message().find("slave node 7 of surface SLAVE has the nodal area"),
              std::string::npos)
        << e.what();
  }
  interaction.behavior.law = PressureOverclosure::Law::Tied;
  c.area = 1.0;
  apply_penalty_law(interaction, faces, "7", c);
  EXPECT_TRUE(c.bonded);
  EXPECT_EQ(normal_law_label(interaction.behavior), "penalty TIED K=400000");
  EXPECT_EQ(normal_law_label(PressureOverclosure{}), "exact (hard)");
}

}  // namespace
}  // namespace styk::contact
