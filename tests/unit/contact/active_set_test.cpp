// The active-set iteration on small systems with known solutions.
#include "styk/contact/active_set.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/LU>

#include <gtest/gtest.h>

namespace styk::contact {
namespace {

ContactConstraint constraint(FrictionLaw::Kind kind, double mu1, double mu2, double gap0) {
  ContactConstraint c;
  c.law.kind = kind;
  c.law.mu1 = mu1;
  c.law.mu2 = mu2;
  c.gap0 = gap0;
  c.area = 1.0;
  return c;
}

// One node on springs: normal compliance sn, tangential st (unscaled), loaded so that it would
// move by (wn, wt1, wt2) without contact. With friction mu the exact solution is
// lambda_n = (wn - gap0) / sn; stick if |wt| / st <= mu lambda_n, else lambda_t = mu lambda_n.
LinearContactSystem spring(const ContactConstraint& c, double sn, double st, Eigen::Vector3d w) {
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

TEST(ActiveSet, SingleNodeSlipsWithCoulombForce) {
  const std::vector<ContactConstraint> cs{constraint(FrictionLaw::Kind::Coulomb, 0.3, 0.3, 0.0)};
  const LinearContactSystem s = spring(cs[0], 2.0, 1.0, {1.0, 3.0, 4.0});
  ContactState state;
  const IncrementOutcome out = solve_increment(cs, s, state, ActiveSetOptions{}, {});
  ASSERT_TRUE(out.converged) << out.reason;
  EXPECT_LE(out.iterations, 8);
  const double ln = 0.5;
  EXPECT_EQ(state.nodes[0].status, NodeStatus::Slip);
  EXPECT_NEAR(state.nodes[0].lambda[0], ln, 1e-12);
  const Eigen::Vector2d lt = 0.3 * state.nodes[0].lambda.tail<2>();  // unscaled
  EXPECT_NEAR(lt.norm(), 0.3 * ln, 1e-12);
  EXPECT_NEAR(lt[0] / lt[1], 3.0 / 4.0, 1e-12);
  EXPECT_NEAR(state.nodes[0].d[0], 0.0, 1e-14);  // no penetration
  // Slip = free motion minus the spring's give under the friction force.
  EXPECT_NEAR(state.nodes[0].slip[0], 3.0 - lt[0], 1e-12);
}

TEST(ActiveSet, SingleNodeSticksBelowTheCone) {
  const std::vector<ContactConstraint> cs{constraint(FrictionLaw::Kind::Coulomb, 0.3, 0.3, 0.0)};
  const LinearContactSystem s = spring(cs[0], 2.0, 1.0, {1.0, 0.06, 0.08});
  ContactState state;
  const IncrementOutcome out = solve_increment(cs, s, state, ActiveSetOptions{}, {});
  ASSERT_TRUE(out.converged) << out.reason;
  EXPECT_EQ(state.nodes[0].status, NodeStatus::Stick);
  EXPECT_NEAR(0.3 * state.nodes[0].lambda[1], 0.06, 1e-12);
}

// Three frictionless constraints coupled through an SPD compliance for which the undamped
// primal-dual active-set (Newton-min) iteration cycles between status sets (found by a random
// search). The iteration must notice the cycle, damp, and still reach the exact solution of the
// complementarity problem, checked against all 2^3 candidate active sets.
LinearContactSystem cycling_system() {
  const double S[3][3] = {{0.46730409568758713, -0.6378937782690266, -0.61075370322140887},
                          {-0.6378937782690266, 0.95620959752347967, 1.0172713925131707},
                          {-0.61075370322140887, 1.0172713925131707, 1.714998173904813}};
  const double d0[3] = {-0.62530699336123563, 0.8233007695532486, 0.049934750985255683};
  LinearContactSystem s;
  s.S = Eigen::MatrixXd::Zero(9, 9);
  s.d0 = Eigen::VectorXd::Zero(9);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s.S(3 * i, 3 * j) = S[i][j];
    s.d0[3 * i] = d0[i];
  }
  s.G.resize(9, 0);
  s.h.resize(0);
  return s;
}

TEST(ActiveSet, CycleIsDetectedAndBroken) {
  const std::vector<ContactConstraint> cs(3, constraint(FrictionLaw::Kind::Frictionless, 0, 0, 0));
  const LinearContactSystem s = cycling_system();
  ContactState state;
  bool cycle = false;
  const IncrementOutcome out = solve_increment(cs, s, state, ActiveSetOptions{},
                                               [&](const IterationRecord& r) { cycle |= r.cycle; });
  EXPECT_TRUE(cycle);
  ASSERT_TRUE(out.converged) << out.reason;
  // The exact LCP solution: lambda >= 0, gap = -d >= 0, lambda gap = 0 for every node.
  Eigen::Vector3d lambda, d;
  for (int i = 0; i < 3; ++i) {
    lambda[i] = state.nodes[i].lambda[0];
    d[i] = state.nodes[i].d[0];
  }
  int solutions = 0;
  for (int mask = 0; mask < 8; ++mask) {
    std::vector<int> closed;
    for (int i = 0; i < 3; ++i)
      if (mask & (1 << i)) closed.push_back(i);
    Eigen::MatrixXd A(closed.size(), closed.size());
    Eigen::VectorXd b(closed.size());
    for (std::size_t r = 0; r < closed.size(); ++r) {
      for (std::size_t c = 0; c < closed.size(); ++c) A(r, c) = s.S(3 * closed[r], 3 * closed[c]);
      b[r] = s.d0[3 * closed[r]];
    }
    const Eigen::VectorXd x = closed.empty() ? Eigen::VectorXd() : Eigen::VectorXd(A.lu().solve(b));
    Eigen::Vector3d l = Eigen::Vector3d::Zero();
    for (std::size_t r = 0; r < closed.size(); ++r) l[closed[r]] = x[r];
    Eigen::Vector3d dd;
    for (int i = 0; i < 3; ++i) {
      dd[i] = s.d0[3 * i];
      for (int j = 0; j < 3; ++j) dd[i] -= s.S(3 * i, 3 * j) * l[j];
    }
    if ((l.array() >= -1e-12).all() && (dd.array() <= 1e-12).all()) {
      ++solutions;
      EXPECT_NEAR((lambda - l).norm(), 0.0, 1e-10);
      EXPECT_NEAR((d - dd).norm(), 0.0, 1e-10);
    }
  }
  EXPECT_EQ(solutions, 1);  // SPD compliance: the solution is unique
}

// The cycling system solved with `options`, every iteration recorded.
struct CyclingRun {
  IncrementOutcome outcome;
  ContactState state;
  std::vector<IterationRecord> records;
  // The record of the first iteration that detected a cycle (records.size() if none).
  std::size_t first_cycle() const {
    for (std::size_t i = 0; i < records.size(); ++i)
      if (records[i].cycle) return i;
    return records.size();
  }
};

CyclingRun solve_cycling_system(const ActiveSetOptions& options) {
  const std::vector<ContactConstraint> cs(3, constraint(FrictionLaw::Kind::Frictionless, 0, 0, 0));
  CyclingRun run;
  run.outcome = solve_increment(cs, cycling_system(), run.state, options,
                                [&](const IterationRecord& r) { run.records.push_back(r); });
  return run;
}

// The options without the early full step: damped steps from the first cycle to the end.
ActiveSetOptions damped_to_the_end() {
  ActiveSetOptions options;
  options.full_step_on_steady_statuses = false;
  return options;
}

// ActiveSetOptions::cycle_damping steers the damped steps after a cycle: on the cycling system
// above, damped to the end (no early full step), the step after the first detected cycle has the
// option's length (0.75 instead of the default 0.5), every step length is a power of it or a
// full step, and the solution is the defaults' (the LCP's unique one, 1e-10). Damped to the end
// the milder damping converges in fewer iterations (20 against 34 with 0.5; 0.25 does not
// converge in 50).
TEST(ActiveSet, CycleDampingFollowsTheOptions) {
  const CyclingRun by_default = solve_cycling_system(damped_to_the_end());
  ASSERT_TRUE(by_default.outcome.converged) << by_default.outcome.reason;
  EXPECT_EQ(by_default.outcome.iterations, 34);
  ActiveSetOptions options = damped_to_the_end();
  options.cycle_damping = 0.75;
  const CyclingRun milder = solve_cycling_system(options);
  ASSERT_TRUE(milder.outcome.converged) << milder.outcome.reason;
  EXPECT_LT(milder.outcome.iterations, by_default.outcome.iterations);
  for (const IterationRecord& record : milder.records) {
    const double powers = std::log(record.damping) / std::log(0.75);
    EXPECT_NEAR(powers, std::round(powers), 1e-9) << "step length " << record.damping;
  }
  const std::size_t first_cycle = milder.first_cycle();
  ASSERT_LT(first_cycle + 1, milder.records.size());
  EXPECT_EQ(milder.records[first_cycle + 1].damping, 0.75);
  EXPECT_EQ(milder.outcome.iterations, 20);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR((milder.state.nodes[i].lambda - by_default.state.nodes[i].lambda).norm(), 0.0,
                1e-10);
}

// ActiveSetOptions::full_step_on_steady_statuses: on the cycling system a damped step after the
// cycle changes no status, and the full step that follows solves that status set exactly, the
// LCP's solution: 6 iterations against 34 damped to the end, the same multipliers (1e-10).
TEST(ActiveSet, FullStepOnceADampedStepChangesNoStatus) {
  const CyclingRun reference = solve_cycling_system(damped_to_the_end());
  ASSERT_TRUE(reference.outcome.converged);
  const CyclingRun run = solve_cycling_system(ActiveSetOptions{});
  ASSERT_TRUE(run.outcome.converged) << run.outcome.reason;
  EXPECT_EQ(run.outcome.iterations, 6);
  // Iteration 3 cycles; 4 and 5 are damped (4 still changes a status), 5 changes none, 6 is the
  // full step with residual 0.
  const std::vector<IterationRecord>& records = run.records;
  ASSERT_EQ(run.first_cycle(), 2u);
  EXPECT_EQ(records[3].damping, 0.5);
  EXPECT_EQ(records[4].damping, 0.5);
  EXPECT_EQ(records[4].changes, 0);
  EXPECT_EQ(records[5].damping, 1.0);
  EXPECT_LE(records[5].residual, 1e-12);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR((run.state.nodes[i].lambda - reference.state.nodes[i].lambda).norm(), 0.0, 1e-10);
}

// A frictional patch of m nodes on a coupled compliance (the inverse of a chain stiffness), pressed
// in and sheared in a turning direction so that part of it sticks and part slips: the slip
// directions take Newton steps with the same closed unknowns.
LinearContactSystem sheared_patch(int m) {
  const int n = 3 * m;
  Eigen::MatrixXd K = Eigen::MatrixXd::Identity(n, n) * 4.0;
  for (int i = 0; i + 3 < n; ++i) K(i, i + 3) = K(i + 3, i) = -1.0;
  LinearContactSystem s;
  s.S = K.inverse();
  s.d0 = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < m; ++j) {
    const double a = 0.15 * j;
    s.d0[3 * j] = 1.0 + 0.01 * j;
    s.d0[3 * j + 1] = 0.05 * j * std::cos(a);
    s.d0[3 * j + 2] = 0.05 * j * std::sin(a);
  }
  s.G.resize(n, 0);
  s.h.resize(0);
  return s;
}

// ActiveSetOptions::reuse_factor_size: solving by GMRES with an earlier iteration's factor gives
// the increment of the plain factorisations (same iterations, same multipliers to 1e-10).
TEST(ActiveSet, ReusedFactorGivesTheSameIncrement) {
  const int m = 40;
  const std::vector<ContactConstraint> cs(m, constraint(FrictionLaw::Kind::Coulomb, 0.3, 0.3, 0));
  const LinearContactSystem s = sheared_patch(m);
  auto run = [&](int reuse_size, ContactState& state, int& reused, int& slipping) {
    ActiveSetOptions options;
    options.reuse_factor_size = reuse_size;
    reused = 0;
    const IncrementOutcome out =
        solve_increment(cs, s, state, options, [&](const IterationRecord& r) {
          reused += r.reused_factor ? 1 : 0;
          slipping = r.slip;
        });
    EXPECT_TRUE(out.converged) << out.reason;
    return out.iterations;
  };
  ContactState plain, reusing;
  int plain_reused = 0, reused = 0, plain_slipping = 0, slipping = 0;
  const int plain_iterations = run(1 << 30, plain, plain_reused, plain_slipping);
  const int iterations = run(1, reusing, reused, slipping);
  EXPECT_EQ(iterations, plain_iterations);
  EXPECT_EQ(plain_reused, 0);
  EXPECT_GE(reused, 1);
  EXPECT_GT(plain_slipping, 0);
  EXPECT_LT(plain_slipping, m);  // some stick: a mixed status set
  double largest = 0.0, difference = 0.0;
  for (int j = 0; j < m; ++j) {
    largest = std::max(largest, plain.nodes[j].lambda.cwiseAbs().maxCoeff());
    difference = std::max(difference,
                          (plain.nodes[j].lambda - reusing.nodes[j].lambda).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(difference, 1e-10 * largest);
}

// The front predictor (ActiveSetOptions::predictor_sweeps): Gauss-Seidel sweeps after the elastic
// trial's solve, on systems whose S is held and where no body is held by contact alone. On the
// sheared patch they change the path, not the solution (same statuses, multipliers to 1e-10 of
// the largest); they do not run when switched off or where a body is held by contact alone.
struct PatchRun {
  IncrementOutcome outcome;
  ContactState state;
};

PatchRun solve_patch(const LinearContactSystem& s, const ActiveSetOptions& options) {
  const int m = static_cast<int>(s.d0.size() / 3);
  const std::vector<ContactConstraint> cs(m, constraint(FrictionLaw::Kind::Coulomb, 0.3, 0.3, 0));
  PatchRun run;
  run.outcome = solve_increment(cs, s, run.state, options, {});
  EXPECT_TRUE(run.outcome.converged) << run.outcome.reason;
  return run;
}

// Expects the statuses of `a` and `b` equal; returns the largest difference of their multipliers
// relative to the largest multiplier of `a`.
double same_statuses_multipliers_apart(const ContactState& a, const ContactState& b) {
  double largest = 0.0, difference = 0.0;
  for (std::size_t j = 0; j < a.nodes.size(); ++j) {
    EXPECT_EQ(a.nodes[j].status, b.nodes[j].status) << j;
    largest = std::max(largest, a.nodes[j].lambda.cwiseAbs().maxCoeff());
    difference =
        std::max(difference, (a.nodes[j].lambda - b.nodes[j].lambda).cwiseAbs().maxCoeff());
  }
  return difference / largest;
}

TEST(ActiveSet, FrontPredictorChangesThePathNotTheSolution) {
  const LinearContactSystem s = sheared_patch(40);
  ActiveSetOptions off;
  off.predictor_sweeps = 0;
  const PatchRun with = solve_patch(s, ActiveSetOptions{});
  const PatchRun without = solve_patch(s, off);
  ASSERT_FALSE(with.outcome.history.empty() || without.outcome.history.empty());
  EXPECT_GT(with.outcome.history.front().sweeps, 0);
  EXPECT_EQ(without.outcome.history.front().sweeps, 0);
  EXPECT_LT(same_statuses_multipliers_apart(without.state, with.state), 1e-10);

  // A body held by contact alone (one free rigid motion along the normals, balanced by a load):
  // the sweeps would not move it, so they do not run.
  LinearContactSystem held = s;
  held.G = Eigen::MatrixXd::Zero(s.d0.size(), 1);
  for (Eigen::Index j = 0; j < held.G.rows(); j += 3) held.G(j, 0) = 1.0;
  held.h = Eigen::VectorXd::Constant(1, 20.0);
  const PatchRun body = solve_patch(held, ActiveSetOptions{});
  for (const IterationRecord& r : body.outcome.history) EXPECT_EQ(r.sweeps, 0);
}

// The sweeps alone solve the problem: run to the end (no early stop on settled statuses), the
// iterate they leave after the trial's solve satisfies the complementarity conditions to the
// tolerance. The statuses differ from the trial's (all sticking), so one Newton step on them
// follows and confirms it: two iterations, the Newton path's statuses and multipliers.
TEST(ActiveSet, GaussSeidelSweepsAloneReachTheSolution) {
  const LinearContactSystem s = sheared_patch(40);
  ActiveSetOptions sweeps_only;
  sweeps_only.predictor_sweeps = 3000;
  sweeps_only.predictor_settled_sweeps = 3000;
  ActiveSetOptions off;
  off.predictor_sweeps = 0;
  const PatchRun swept = solve_patch(s, sweeps_only);
  const PatchRun newton = solve_patch(s, off);
  EXPECT_EQ(swept.outcome.iterations, 2);
  EXPECT_EQ(swept.outcome.history.front().sweeps, 3000);
  EXPECT_GT(swept.outcome.history.front().changes, 0);
  EXPECT_LE(swept.outcome.history.front().residual, 1e-9);
  EXPECT_GT(newton.outcome.iterations, 1);
  EXPECT_LT(same_statuses_multipliers_apart(newton.state, swept.state), 1e-8);
}

TEST(ActiveSet, NonConvergenceIsReportedWithTheFlippingNodes) {
  const std::vector<ContactConstraint> cs(3, constraint(FrictionLaw::Kind::Frictionless, 0, 0, 0));
  ContactState state;
  ActiveSetOptions few;
  few.max_iterations = 4;
  const IncrementOutcome out = solve_increment(cs, cycling_system(), state, few, {});
  EXPECT_FALSE(out.converged);
  EXPECT_NE(out.reason.find("no convergence in 4 iterations"), std::string::npos) << out.reason;
  EXPECT_FALSE(out.offending.empty());
  EXPECT_FALSE(state.started);  // the state is left as it was
}

}  // namespace
}  // namespace styk::contact
