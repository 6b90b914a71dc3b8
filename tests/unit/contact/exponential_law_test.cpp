// The EXPONENTIAL pressure-overclosure law in the active-set iteration (penalty_law.hpp,
// friction_law.hpp; docs/contact.md, "Penalty laws"). CalculiX 2.20's law: a slave node closer
// than c0 to the master carries A p0 exp(-beta g), g the clearance (negative when overclosed),
// beta = ln(100) / c0; beyond c0 it carries nothing. Hand values on one node on a spring: the law's
// root is chosen (lambda) and the free motion w that has it as its equilibrium derived from it,
// w = gap0 + H(lambda) + sn lambda, H(lambda) = ln(lambda / (A p0)) / beta the overclosure.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "slip_rows_check.hpp"
#include "styk/contact/active_set.hpp"
#include "styk/contact/friction_law.hpp"
#include "styk/contact/penalty_law.hpp"

namespace styk::contact {
namespace {

constexpr double kC0 = 1e-3;    // clearance at which the pressure is 1 % of p0
constexpr double kForce0 = 10;  // A p0
const double kBeta = std::log(100.0) / kC0;

ContactConstraint exponential_node(double gap0) {
  ContactConstraint c;
  c.area = 1.0;
  c.gap0 = gap0;
  c.exponential_force0 = kForce0;
  c.exponential_beta = kBeta;
  return c;
}

double overclosure_of(double lambda) { return std::log(lambda / kForce0) / kBeta; }

// One node on a spring of normal compliance sn with free motion w (no body held by contact).
LinearContactSystem on_spring(double sn, double w) {
  LinearContactSystem s;
  s.S = Eigen::MatrixXd::Zero(3, 3);
  s.S(0, 0) = sn;
  s.S(1, 1) = s.S(2, 2) = sn;
  s.d0 = Eigen::Vector3d(w, 0.0, 0.0);
  s.G.resize(3, 0);
  s.h.resize(0);
  return s;
}

// One node of a body held only by the contact, pressed towards the master by the force F: the
// node carries F whatever the law, and the law sets where the body rests.
LinearContactSystem pressed_by(double force) {
  LinearContactSystem s = on_spring(1e-4, 0.0);
  s.G = Eigen::MatrixXd::Zero(3, 1);
  s.G(0, 0) = 1.0;
  s.h = Eigen::VectorXd::Constant(1, force);
  return s;
}

IncrementOutcome solve_one(const ContactConstraint& c, const LinearContactSystem& s,
                           ContactState& state) {
  return solve_increment({c}, s, state, ActiveSetOptions{}, {});
}

// Hand value: lambda chosen, w derived. Open by 0.26 c0 (lambda = 3, 30 % of A p0), overclosed
// (lambda = 40) and open by 0.65 c0 (lambda = 0.5, the node held back by the structure while the
// spring pushes it off): lambda to 1e-8 relative, the clearance to 1e-12 absolute (c0 = 1e-3).
TEST(ExponentialLaw, NodeOnASpringFindsTheLawsRoot) {
  const double sn = 1e-4, gap0 = 2e-4;
  for (const double lambda : {3.0, 40.0, 0.5}) {
    const ContactConstraint c = exponential_node(gap0);
    const double w = gap0 + overclosure_of(lambda) + sn * lambda;
    ContactState state;
    const IncrementOutcome out = solve_one(c, on_spring(sn, w), state);
    ASSERT_TRUE(out.converged) << lambda << ": " << out.reason;
    EXPECT_NE(state.nodes[0].status, NodeStatus::Open) << lambda;
    EXPECT_NEAR(state.nodes[0].lambda[0], lambda, 1e-8 * lambda);
    EXPECT_NEAR(gap0 - state.nodes[0].d[0], -overclosure_of(lambda), 1e-12) << lambda;
    std::printf("lambda %g: %d iterations\n", lambda, out.iterations);
    EXPECT_LE(out.iterations, 6) << lambda;  // Newton on the law (docs/contact.md)
  }
}

// The block pressed with force F over area A (SPEC-free hand value, the brief's formula): it rests
// at the clearance g = -(1/beta) ln(F / (A p0)): open by c0 / 2 for F = A p0 / 10, overclosed by
// ln(2) / beta for F = 2 A p0; to 1e-8 of c0.
TEST(ExponentialLaw, PressedBodyRestsAtTheLawsClearance) {
  for (const double force : {1.0, 20.0}) {
    ContactState state;
    const IncrementOutcome out = solve_one(exponential_node(0.0), pressed_by(force), state);
    ASSERT_TRUE(out.converged) << force << ": " << out.reason;
    EXPECT_NEAR(state.nodes[0].lambda[0], force, 1e-12 * force);
    const double clearance = -state.nodes[0].d[0];
    EXPECT_NEAR(clearance, -std::log(force / kForce0) / kBeta, 1e-8 * kC0) << force;
  }
  ContactState state;
  solve_one(exponential_node(0.0), pressed_by(1.0), state);
  EXPECT_NEAR(-state.nodes[0].d[0], kC0 / 2.0, 1e-8 * kC0);
}

// Friction on top, as with LINEAR: sn = st = 1e-4, mu = 0.3, the normal root chosen (lambda_n = 3),
// a tangential free motion far beyond what friction holds: the node slips with |lambda_t| =
// mu lambda_n = 0.9 and the normal force is the law's (uncoupled springs).
TEST(ExponentialLaw, CoulombSlipOnTheExponentialNormal) {
  ContactConstraint c = exponential_node(0.0);
  c.law.kind = FrictionLaw::Kind::Coulomb;
  c.law.mu1 = c.law.mu2 = 0.3;
  const double sn = 1e-4, lambda = 3.0;
  LinearContactSystem s = on_spring(sn, overclosure_of(lambda) + sn * lambda);
  s.S(1, 1) = s.S(2, 2) = 0.3 * 0.3 * sn;  // scaled tangential components (ContactConstraint::row)
  s.d0[1] = 0.3 * 1.0;
  ContactState state;
  const IncrementOutcome out = solve_one(c, s, state);
  ASSERT_TRUE(out.converged) << out.reason;
  EXPECT_EQ(state.nodes[0].status, NodeStatus::Slip);
  EXPECT_NEAR(state.nodes[0].lambda[0], lambda, 1e-8 * lambda);
  EXPECT_NEAR(0.3 * state.nodes[0].lambda.tail<2>().norm(), 0.9, 1e-8);
}

// Pulled apart beyond c0 (ccx generates no spring there): the node is open and carries nothing,
// while at a free clearance just inside c0 it carries at least A p0 / 100.
TEST(ExponentialLaw, BeyondC0TheNodeCarriesNothing) {
  ContactState beyond;
  const IncrementOutcome open =
      solve_one(exponential_node(0.0), on_spring(1e-6, -1.5 * kC0), beyond);
  ASSERT_TRUE(open.converged) << open.reason;
  EXPECT_EQ(beyond.nodes[0].status, NodeStatus::Open);
  EXPECT_EQ(beyond.nodes[0].lambda[0], 0.0);
  ContactState inside;
  const IncrementOutcome closed =
      solve_one(exponential_node(0.0), on_spring(1e-6, -0.99 * kC0), inside);
  ASSERT_TRUE(closed.converged) << closed.reason;
  EXPECT_NE(inside.nodes[0].status, NodeStatus::Open);
  EXPECT_GE(inside.nodes[0].lambda[0], kForce0 / 100.0);
}

// Pressed with less than the law's least force A p0 / 100: no equilibrium (the spring pushes the
// node beyond c0, where nothing holds it off; ccx diverges, "too many cutbacks"). The increment
// fails saying so and naming the node, and the state is left as it was.
TEST(ExponentialLaw, ForceBelowTheLeastForceHasNoEquilibrium) {
  ContactState state;
  const IncrementOutcome out = solve_one(exponential_node(0.0), pressed_by(0.05), state);
  EXPECT_FALSE(out.converged);
  EXPECT_TRUE(out.no_equilibrium);
  EXPECT_NE(out.reason.find("EXPONENTIAL"), std::string::npos) << out.reason;
  ASSERT_EQ(out.offending.size(), 1u);
  EXPECT_EQ(out.offending[0], 0);
  EXPECT_FALSE(state.started);
}

// The normal row is the law's tangent at the iterate, d_n - lambda_n / (beta lambda_n*) =
// gap0 + H(lambda_n*) - 1 / beta, lambda_n* = max(lambda_n, A p0 / 100), and the slip rows are the
// derivatives of F_t with it (central finite differences).
TEST(ExponentialLaw, RowsAreTheLawsTangent) {
  LocalPoint p;
  p.lambda = {2.0, 0.7, -0.4};
  p.d = {0.6, 0.9, 0.25};
  p.d_ref = {0.0, 0.1, -0.2};
  p.gap0 = 0.3;
  p.c_n = 0.3;
  p.c_t = 2.3;
  p.exponential_force0 = kForce0;
  p.exponential_beta = kBeta;
  p.live = {true, true, true};
  ASSERT_EQ(classify(p), NodeStatus::Slip);
  const LocalRows rows = linearise(p, NodeStatus::Slip);
  EXPECT_EQ(rows.Q(0, 0), 1.0);
  EXPECT_NEAR(rows.D(0, 0), -1.0 / (kBeta * 2.0), 1e-18);
  EXPECT_NEAR(rows.r[0], 0.3 + overclosure_of(2.0) - 1.0 / kBeta, 1e-15);
  test::expect_slip_rows_match_finite_differences(p, rows, 1e-7, 1e-6);
  // Below the least force the tangent is the one at A p0 / 100 (overclosure -c0 there).
  p.lambda[0] = 0.01;
  const SpringTangent low = spring_tangent(p);
  EXPECT_NEAR(low.compliance, 1.0 / (kBeta * kForce0 / 100.0), 1e-12 * low.compliance);
  EXPECT_NEAR(low.offset + low.compliance * kForce0 / 100.0, -kC0, 1e-15);
  EXPECT_NEAR(spring_overclosure(p, 0.0), -kC0, 1e-15);
}

// apply_penalty_law: the node's spring is A p0 at zero clearance with beta = ln(100) / c0 (A = 1
// for a node surface); no linear stiffness.
TEST(ExponentialLaw, ConstraintCarriesTheLawsParameters) {
  SurfaceInteraction interaction;
  interaction.name = "EXPO";
  interaction.behavior.law = PressureOverclosure::Law::Exponential;
  interaction.behavior.c0 = 2e-3;
  interaction.behavior.p0 = 8.0;
  Surface faces;
  faces.name = "SLAVE";
  ContactConstraint c;
  c.area = 0.25;
  check_penalty_law(interaction);
  apply_penalty_law(interaction, faces, "7", c);
  EXPECT_EQ(c.exponential_force0, 2.0);
  EXPECT_NEAR(c.exponential_beta, std::log(100.0) / 2e-3, 1e-12);
  EXPECT_EQ(c.penalty_stiffness, 0.0);
  EXPECT_FALSE(c.bonded);
  EXPECT_EQ(normal_law_label(interaction.behavior), "penalty EXPONENTIAL c0=0.002 p0=8");
  Surface nodes = faces;
  nodes.kind = Surface::Kind::Nodes;
  c.area = 0.0;
  apply_penalty_law(interaction, nodes, "7", c);
  EXPECT_EQ(c.exponential_force0, 8.0);  // a node surface's "pressure" is a force: A = 1
}

}  // namespace
}  // namespace styk::contact
