// SPEC §3.2.3 two cantilevers (docs/contact.md "Iteration, diagnostics, failure"): the front
// predictor (ActiveSetOptions::predictor_sweeps), the slip-front anticipation at the kink
// (front_kink_band, anticipate_on_cone) and the full step after a cycle only change the
// active-set iteration's path. The beams' linear contact system (S = B K^-1 B^T, d0 = B u of the
// pressure alone) is built from the solver's pieces and solved by solve_increment with and
// without each; the paths reach the same statuses and, converged further, the same multipliers.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "assembly.hpp"
#include "contact_model_kit.hpp"
#include "contact_operator.hpp"
#include "contact_spec_models.hpp"
#include "element_states.hpp"
#include "linear_solver.hpp"
#include "model_constraints.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"
#include "styk/contact/active_set.hpp"
#include "styk/solver/analysis.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk {
namespace {

using namespace solver_detail;

// The contact system of a model with one step and supports only (no body held by contact alone):
// the compliance with the supports held, and the contact rows of the displacements the loads give
// without contact (a run of the same model with its contact pairs removed).
struct BeamSystem {
  std::vector<contact::ContactConstraint> constraints;
  contact::LinearContactSystem system;
};

BeamSystem beam_system(const Model& model, const ElementRegistry& registry) {
  BeamSystem out;
  const PreparedModel prepared = prepare_model(model, registry);
  out.constraints = contact::build_contact_constraints(model, registry, nullptr);
  const ContactOperator B(prepared, out.constraints);
  const int dofs = prepared.active_dofs();
  std::vector<int> held;
  for (const Boundary& b : model.boundaries)
    if (prepared.active_of_node[b.node] >= 0)
      held.push_back(3 * prepared.active_of_node[b.node] + b.dof - 1);
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());

  const PhaseRecorder phases(nullptr, nullptr);
  const SolverContext context{model, prepared, phases, 1};
  StiffnessMatrix K(model, prepared, 1);
  const ElementStates states(model, prepared, 0, nullptr);
  assemble_stiffness(model, prepared, states, K, 1);
  const std::unique_ptr<LinearSolver> solver = make_cholmod_solver(context);
  solver->prepare(K, partition_dofs(dofs, held));
  out.system.S = B.compliance(*solver, dofs, ModelConstraints{});

  Model free = model;
  free.contact_pairs.clear();
  const Results loads_alone = run_static_analysis(free, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& u = loads_alone.increments.back();
  Eigen::VectorXd u_active = Eigen::VectorXd::Zero(dofs);
  for (std::size_t n = 0; n < prepared.active_of_node.size(); ++n)
    if (prepared.active_of_node[n] >= 0)
      for (int d = 0; d < 3; ++d) u_active[3 * prepared.active_of_node[n] + d] = u.U[n][d];
  out.system.d0 = B.apply(Eigen::Ref<const Eigen::VectorXd>(u_active));
  out.system.G = Eigen::MatrixXd::Zero(out.system.d0.size(), 0);
  out.system.h = Eigen::VectorXd::Zero(0);
  return out;
}

struct Solved {
  contact::IncrementOutcome outcome;
  contact::ContactState state;
  bool cycled = false;  // some iteration detected a cycle
};

Solved solve(const BeamSystem& beams, const contact::ActiveSetOptions& options) {
  Solved out;
  out.outcome =
      contact::solve_increment(beams.constraints, beams.system, out.state, options,
                               [&](const contact::IterationRecord& r) { out.cycled |= r.cycle; });
  return out;
}

class IterationPath : public test::PluginRegistrySuite<> {};

// Largest difference of the multipliers of two solutions, relative to the largest multiplier of
// the first, and the number of constraints whose statuses differ.
struct Difference {
  double lambda = 0.0;
  int statuses = 0;
};

Difference difference(const contact::ContactState& a, const contact::ContactState& b) {
  double largest = 0.0, worst = 0.0;
  Difference out;
  for (std::size_t j = 0; j < a.nodes.size(); ++j) {
    out.statuses += a.nodes[j].status != b.nodes[j].status;
    largest = std::max(largest, a.nodes[j].lambda.cwiseAbs().maxCoeff());
    worst = std::max(worst, (a.nodes[j].lambda - b.nodes[j].lambda).cwiseAbs().maxCoeff());
  }
  out.lambda = worst / largest;
  return out;
}

// SPEC §3.2.3, mu = 10, one increment from the elastic trial: 116 of the 243 constraints slip at
// the solution. Before the anticipation at the kink: 10 iterations (bench/contact/README.md);
// with it: 9. The same statuses; the multipliers of both paths within 1e-8 of the solution
// converged to a residual of 1e-13 (the old path's are 2.0e-8 from it: its last Newton step ends
// at a residual of 6.3e-11, the new path's at 8.3e-13), and the two paths converged that far agree
// to 1e-9 (8.2e-11).
TEST_F(IterationPath, TwoCantileversMu10SameSolutionInFewerIterations) {
  const BeamSystem beams =
      beam_system(test::two_cantilevers_model(test::coulomb(10.0)), registry());
  // The front predictor does the anticipation's work in this increment (4 iterations with it):
  // off in both paths, as in increments it does not serve.
  contact::ActiveSetOptions now;
  now.predictor_sweeps = 0;
  contact::ActiveSetOptions before = now;
  before.front_kink_band = 0.0;
  before.anticipate_on_cone = false;
  const Solved old_path = solve(beams, before);
  const Solved new_path = solve(beams, now);
  ASSERT_TRUE(old_path.outcome.converged) << old_path.outcome.reason;
  ASSERT_TRUE(new_path.outcome.converged) << new_path.outcome.reason;
  std::printf("mu = 10 beams: %d iterations before, %d with the anticipation at the kink\n",
              old_path.outcome.iterations, new_path.outcome.iterations);
  EXPECT_EQ(old_path.outcome.iterations, 10);
  EXPECT_LE(new_path.outcome.iterations, 9);

  contact::ActiveSetOptions before_tight = before, now_tight = now;
  before_tight.tolerance = now_tight.tolerance = 1e-13;
  const Solved old_tight = solve(beams, before_tight);
  const Solved new_tight = solve(beams, now_tight);
  ASSERT_TRUE(old_tight.outcome.converged && new_tight.outcome.converged);

  int slipping = 0;
  for (const contact::ConstraintState& s : new_path.state.nodes)
    slipping += s.status == contact::NodeStatus::Slip;
  EXPECT_EQ(slipping, 116);
  const Difference paths = difference(old_path.state, new_path.state);
  const Difference old_error = difference(old_tight.state, old_path.state);
  const Difference new_error = difference(old_tight.state, new_path.state);
  const Difference tight = difference(old_tight.state, new_tight.state);
  std::printf(
      "multipliers: paths %.2e apart; from the 1e-13 solution old %.2e, new %.2e; "
      "both paths at 1e-13 %.2e apart\n",
      paths.lambda, old_error.lambda, new_error.lambda, tight.lambda);
  EXPECT_EQ(paths.statuses, 0);
  EXPECT_EQ(tight.statuses, 0);
  EXPECT_LE(new_error.lambda, 1e-8);
  EXPECT_LE(old_error.lambda, 1e-7);
  EXPECT_LE(tight.lambda, 1e-9);
}

// The beams' tables across the friction coefficient (bench/contact/README.md, "The beams across
// mu"; `styk_bench_contact beams_mu<mu>` gives the same counts through the whole analysis).
const std::vector<double> beam_frictions = {1.0, 2.0, 2.5, 3.0, 3.8,  4.0,  4.2,  4.8, 5.0,
                                            5.5, 7.0, 8.0, 9.5, 10.0, 12.0, 13.0, 20.0};

struct BeamSolve {
  Solved solved;
  int slipping = 0;
};

BeamSolve solve_beams(double mu, const contact::ActiveSetOptions& options,
                      const ElementRegistry& registry) {
  // Built for each mu: the tangential rows are mu times the tangent (ContactConstraint::row), so
  // the compliance and d0 depend on it.
  const BeamSystem beams = beam_system(test::two_cantilevers_model(test::coulomb(mu)), registry);
  BeamSolve out;
  out.solved = solve(beams, options);
  for (const contact::ConstraintState& s : out.solved.state.nodes)
    out.slipping += s.status == contact::NodeStatus::Slip;
  return out;
}

// SPEC §3.2.3 beams across the friction coefficient, one increment from the elastic trial, without
// the front predictor (as in increments it does not serve: bodies held by contact alone, S not
// held, increments from an extrapolated predictor). Between mu 2.5 and 13 the slip front crosses
// most of the 81 node rows along the beams and the Newton steps move it a few rows per iteration:
// 13 of these 17 coefficients take 9-18 iterations. The worst, 18 at mu 4.8, ends with every
// closed node slipping and five Newton steps on steady statuses while the tip nodes' tangential
// multipliers, which the stick state left at up to 45 degrees to the slip, turn onto it. Asserted
// exactly so that the table quoted in the docs follows any change of the iteration.
TEST_F(IterationPath, TwoCantileversIterationsAcrossFrictionWithoutThePredictor) {
  const std::vector<int> measured = {6, 8, 10, 12, 13, 14, 12, 18, 13, 15, 14, 12, 12, 9, 8, 11, 5};
  contact::ActiveSetOptions options;
  options.predictor_sweeps = 0;
  int over_budget = 0, most = 0;
  for (std::size_t i = 0; i < beam_frictions.size(); ++i) {
    const double mu = beam_frictions[i];
    const BeamSolve beams = solve_beams(mu, options, registry());
    const contact::IncrementOutcome& outcome = beams.solved.outcome;
    ASSERT_TRUE(outcome.converged) << "mu = " << mu << ": " << outcome.reason;
    std::printf("mu = %g: %d iterations, %d of %zu slipping\n", mu, outcome.iterations,
                beams.slipping, beams.solved.state.nodes.size());
    EXPECT_EQ(outcome.iterations, measured[i]) << "mu = " << mu;
    over_budget += outcome.iterations > 8;
    most = std::max(most, outcome.iterations);
  }
  EXPECT_EQ(over_budget, 13);
  EXPECT_EQ(most, 18);
}

// The same beams with the defaults: after the elastic trial's solve, Gauss-Seidel sweeps on the
// condensed problem move the front (ActiveSetOptions::predictor_sweeps), and every coefficient
// converges within the budget of 8 iterations (issue target: frictional increments in at most 8).
// Measured 3-6 iterations after 4-11 sweeps; asserted exactly. The solution is the one without
// the predictor: the same statuses, and the multipliers of both, each converged to a residual of
// 1e-13, agree to 1e-9 of the largest.
TEST_F(IterationPath, TwoCantileversFrontPredictorWithinTheBudget) {
  const std::vector<int> measured = {3, 3, 3, 3, 3, 3, 3, 4, 6, 5, 5, 5, 4, 4, 4, 3, 3};
  contact::ActiveSetOptions tight, tight_without;
  tight.tolerance = tight_without.tolerance = 1e-13;
  tight_without.predictor_sweeps = 0;
  int most = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < beam_frictions.size(); ++i) {
    const double mu = beam_frictions[i];
    const BeamSolve beams = solve_beams(mu, contact::ActiveSetOptions{}, registry());
    const contact::IncrementOutcome& outcome = beams.solved.outcome;
    ASSERT_TRUE(outcome.converged) << "mu = " << mu << ": " << outcome.reason;
    ASSERT_FALSE(outcome.history.empty());
    const BeamSolve with = solve_beams(mu, tight, registry());
    const BeamSolve without = solve_beams(mu, tight_without, registry());
    ASSERT_TRUE(with.solved.outcome.converged && without.solved.outcome.converged) << mu;
    const Difference apart = difference(without.solved.state, with.solved.state);
    std::printf("mu = %g: %d iterations after %d sweeps, %d slipping; at 1e-13 %.2e apart\n", mu,
                outcome.iterations, outcome.history.front().sweeps, beams.slipping, apart.lambda);
    EXPECT_EQ(outcome.iterations, measured[i]) << "mu = " << mu;
    EXPECT_GT(outcome.history.front().sweeps, 0) << "mu = " << mu;
    EXPECT_EQ(apart.statuses, 0) << "mu = " << mu;
    EXPECT_EQ(beams.slipping, without.slipping) << "mu = " << mu;
    most = std::max(most, outcome.iterations);
    worst = std::max(worst, apart.lambda);
  }
  EXPECT_LE(most, 8);
  EXPECT_LE(worst, 1e-9);
}

// After a cycle the iteration damps its steps (ActiveSetOptions::cycle_damping). At mu = 3.8 the
// beams cycle at iteration 8 with every closed node slipping; the statuses then stay put, and
// damped steps halved the residual per iteration to the tolerance: 33 iterations. With the
// full step once a damped step changes no status (full_step_on_steady_statuses): 13, the same
// statuses and multipliers (1e-8 of the largest, both against the solution converged to 1e-13).
TEST_F(IterationPath, TwoCantileversMu38FullStepAfterACycle) {
  const BeamSystem beams = beam_system(test::two_cantilevers_model(test::coulomb(3.8)), registry());
  // Without the front predictor (with it: 3 iterations, no cycle), as in the increments it does
  // not serve.
  contact::ActiveSetOptions now;
  now.predictor_sweeps = 0;
  contact::ActiveSetOptions damped = now;
  damped.full_step_on_steady_statuses = false;
  const Solved new_path = solve(beams, now);
  const Solved old_path = solve(beams, damped);
  ASSERT_TRUE(new_path.outcome.converged) << new_path.outcome.reason;
  ASSERT_TRUE(old_path.outcome.converged) << old_path.outcome.reason;
  std::printf("mu = 3.8 beams: %d iterations damped to the end, %d with the full step\n",
              old_path.outcome.iterations, new_path.outcome.iterations);
  EXPECT_TRUE(new_path.cycled);
  EXPECT_EQ(old_path.outcome.iterations, 33);
  EXPECT_EQ(new_path.outcome.iterations, 13);

  contact::ActiveSetOptions tight = now;
  tight.tolerance = 1e-13;
  const Solved reference = solve(beams, tight);
  ASSERT_TRUE(reference.outcome.converged);
  const Difference old_error = difference(reference.state, old_path.state);
  const Difference new_error = difference(reference.state, new_path.state);
  std::printf("multipliers from the 1e-13 solution: damped %.2e, full step %.2e\n",
              old_error.lambda, new_error.lambda);
  EXPECT_EQ(old_error.statuses, 0);
  EXPECT_EQ(new_error.statuses, 0);
  EXPECT_LE(old_error.lambda, 1e-8);
  EXPECT_LE(new_error.lambda, 1e-8);
}

}  // namespace
}  // namespace styk
