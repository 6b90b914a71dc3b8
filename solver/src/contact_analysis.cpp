#include "contact_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "assembly.hpp"
#include "contact_operator.hpp"
#include "floating_bodies.hpp"
#include "linear_solver.hpp"
#include "mechanism_check.hpp"
#include "parallel.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "recovery.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"
#include "stress_averaging.hpp"
#include "styk/contact/active_set.hpp"
#include "styk/contact/contact_results.hpp"

namespace styk::solver_detail {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

std::vector<double> lerp(const std::vector<double>& a, const std::vector<double>& b, double t) {
  std::vector<double> out(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = (1.0 - t) * a[i] + t * b[i];
  return out;
}

// K factorised with the prescribed dofs plus the dofs pinning the bodies held only by contact,
// and the structure-side pieces of the contact system that depend on it.
struct ContactFactor {
  std::vector<int> prescribed;  // the model's (without the fixing dofs)
  FloatingBodies floating;
  std::unique_ptr<LinearSolver> solver;
  Eigen::MatrixXd S, G;
};

// Sums of a nodal field on active dofs.
Vec3 dof_sum(const std::vector<double>& f) {
  Vec3 sum{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < f.size(); ++i) sum[i % 3] += f[i];
  return sum;
}

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

std::string node_ids(const Model& model, const std::vector<contact::ContactConstraint>& constraints,
                     const std::vector<int>& which) {
  std::string list;
  const std::size_t shown = std::min<std::size_t>(which.size(), 20);
  for (std::size_t i = 0; i < shown; ++i) {
    if (i > 0) list += ", ";
    list += std::to_string(model.node_ids[constraints[which[i]].slave]);
  }
  if (which.size() > shown) list += ", ... (" + std::to_string(which.size()) + " nodes)";
  return list;
}

void check_equilibrium(const std::vector<double>& applied, const IncrementResult& increment,
                       const std::vector<contact::ContactConstraint>& constraints,
                       const contact::ContactState& state, ContactEquilibrium& out) {
  out.valid = true;
  out.applied = dof_sum(applied);
  out.reactions = Vec3{0.0, 0.0, 0.0};
  for (const Vec3& rf : increment.RF)
    for (int d = 0; d < 3; ++d) out.reactions[d] += rf[d];
  out.contact_slave = out.contact_master = Vec3{0.0, 0.0, 0.0};
  for (std::size_t j = 0; j < constraints.size(); ++j) {
    const Eigen::Vector3d f = contact::slave_force(constraints[j], state.nodes[j]);
    for (const contact::MasterTerm& t : constraints[j].master)
      for (int d = 0; d < 3; ++d) out.contact_master[d] -= t.weight * f[d];
    for (int d = 0; d < 3; ++d) out.contact_slave[d] += f[d];
  }
  Vec3 imbalance;
  for (int d = 0; d < 3; ++d) imbalance[d] = out.applied[d] + out.reactions[d];
  const double scale =
      std::max({norm(out.applied), norm(out.reactions), norm(out.contact_slave), 1e-300});
  out.relative_residual = norm(imbalance) / scale;
}

}  // namespace

Results run_contact_analysis(const Model& model, const ElementRegistry& registry,
                             const SolveOptions& options, ProgressSink* progress,
                             AnalysisReport* report) {
  if (report != nullptr) *report = AnalysisReport{};
  const PhaseRecorder phases(progress, report);
  const int threads = resolve_threads(options.threads);
  const SourceLoc whole_model{model.source, 0};
  const std::string direct_only =
      "contact analysis needs the direct solver (CHOLMOD): the "
      "iterative solver cannot supply the contact compliance";
  if (options.force == LinearSolverKind::Iterative) throw InputError(whole_model, direct_only);
  for (const Step& step : model.steps)
    if (step.procedure.solver == LinearSolverKind::Iterative)
      throw InputError(step.procedure.where, direct_only);

  PreparedModel prepared;
  std::vector<StepConditions> conditions;
  std::vector<contact::ContactConstraint> constraints;
  {
    const PhaseRecorder::Scope phase(phases, "check");
    if (model.steps.empty())
      throw InputError(whole_model, "the model has no *STEP: there is nothing to analyse");
    if (model.element_count() == 0) throw InputError(whole_model, "the model has no elements");
    prepared = prepare_model(model, registry);
    conditions = accumulate_step_conditions(model, prepared);
    std::vector<std::string> notes;
    constraints = contact::build_contact_constraints(model, registry, &notes);
    for (const std::string& note : notes) phases.info(note);
    if (constraints.empty())
      throw InputError(model.contact_pairs.front().where,
                       "no slave node of any contact pair reaches its master surface");
    for (const contact::ContactConstraint& c : constraints)
      if (prepared.active_of_node[c.slave] < 0)
        throw InputError(
            model.contact_pairs[c.pair].where,
            "slave node " + std::to_string(model.node_ids[c.slave]) + " belongs to no element");
    phases.info("contact: " + std::to_string(constraints.size()) + " constraints in " +
                std::to_string(model.contact_pairs.size()) + " pairs");
  }
  const StressAveraging averaging(model, prepared.formulation, RuleKind::Full);
  StiffnessMatrix K(model, prepared, threads);
  {
    const PhaseRecorder::Scope phase(phases, "assemble");
    assemble_stiffness(model, prepared, K, threads);
  }
  const SolverContext context{model, prepared, phases, threads};
  const ContactOperator B(prepared, constraints);
  const std::vector<char> touches_contact = contact_nodes(prepared, constraints);

  ContactFactor factor;
  auto set_up = [&](const std::vector<int>& prescribed) {
    factor.solver.reset();
    factor.prescribed = prescribed;
    factor.floating = find_floating_bodies(model, prepared, K.graph(), prescribed, touches_contact);
    std::vector<int> pinned = prescribed;
    pinned.insert(pinned.end(), factor.floating.fixing_dofs.begin(),
                  factor.floating.fixing_dofs.end());
    std::sort(pinned.begin(), pinned.end());
    pinned.erase(std::unique(pinned.begin(), pinned.end()), pinned.end());
    {
      const PhaseRecorder::Scope phase(phases, "check");
      check_rigid_body_modes(model, prepared, K.graph(), pinned);
    }
    if (!K.pristine()) {
      const PhaseRecorder::Scope phase(phases, "assemble");
      assemble_stiffness(model, prepared, K, threads);
    }
    factor.solver = make_cholmod_solver(context);
    factor.solver->prepare(K, partition_dofs(prepared.active_dofs(), pinned));
    {
      const PhaseRecorder::Scope phase(phases, "contact compliance");
      factor.S = B.compliance(*factor.solver, prepared.active_dofs());
      factor.G = B.apply_columns(factor.floating.modes);
    }
    phases.info("contact: " + std::to_string(factor.floating.count()) +
                " rigid motions held only by contact");
    if (report != nullptr && report->linear_solver.empty()) {
      report->linear_solver = factor.solver->description() + " + dense contact active set";
      report->dofs = prepared.active_dofs() - static_cast<long long>(pinned.size());
    }
  };

  Results results;
  contact::ContactState state;
  std::vector<double> f_previous(prepared.active_dofs(), 0.0);
  std::vector<double> u_previous(prepared.active_dofs(), 0.0);
  double total_time = 0.0;
  for (std::size_t k = 0; k < model.steps.size(); ++k) {
    const Step& step = model.steps[k];
    const std::vector<int> prescribed = prescribed_dofs(conditions[k]);
    if (!factor.solver || prescribed != factor.prescribed) set_up(prescribed);
    const Eigen::MatrixXd& R = factor.floating.modes;

    // Loads and prescribed values ramp linearly from the end of the previous step (newly
    // prescribed dofs from where they are) to this step's values.
    const std::vector<double> f_end = assemble_loads(model, prepared, conditions[k]);
    std::vector<double> up_end(prepared.active_dofs(), 0.0);
    for (const DofValue& p : conditions[k].prescribed) up_end[p.dof] = p.value;
    const std::vector<double> f_start = f_previous, up_start = u_previous;
    contact::LinearContactSystem system;
    system.S = factor.S;
    system.G = factor.G;
    const Eigen::VectorXd d0_start = B.apply(factor.solver->solve(f_start, up_start));
    const Eigen::VectorXd d0_end = B.apply(factor.solver->solve(f_end, up_end));
    const Eigen::Map<const Eigen::VectorXd> fs(f_start.data(), prepared.active_dofs());
    const Eigen::Map<const Eigen::VectorXd> fe(f_end.data(), prepared.active_dofs());
    const Eigen::VectorXd h_start = R.transpose() * fs, h_end = R.transpose() * fe;

    const double period = step.procedure.total_time;
    const bool fixed = step.procedure.fixed_increments;
    const double max_increment = step.procedure.max_increment.value_or(period);
    const double min_increment = step.procedure.min_increment.value_or(1e-5 * period);
    double dt = std::min(step.procedure.initial_increment, max_increment);
    double t = 0.0;
    int increment_number = 0, quick = 0;
    while (t < period * (1.0 - 1e-12)) {
      dt = std::min(dt, period - t);
      const double tau = (t + dt) / period;
      system.d0 = (1.0 - tau) * d0_start + tau * d0_end;
      system.h = (1.0 - tau) * h_start + tau * h_end;
      contact::ContactState trial = state;
      const std::string where = "contact step " + std::to_string(k + 1) + " increment " +
                                std::to_string(increment_number + 1) +
                                format(" (t = %.4g)", t + dt);
      auto log = [&](const contact::IterationRecord& r) {
        phases.info(where + format(": iteration %.0f: %.0f stick, ", r.iteration, r.stick) +
                    format("%.0f slip, %.0f open, ", r.slip, r.open) +
                    format("%.0f changes, residual %.2e", r.changes, r.residual) +
                    (r.cycle ? format(", cycle detected: step length %.3g", r.damping) : ""));
      };
      const contact::IncrementOutcome outcome =
          contact::solve_increment(constraints, system, trial, contact::ActiveSetOptions{}, log);
      if (!outcome.converged) {
        const std::string message =
            where + " did not converge: " + outcome.reason +
            (outcome.offending.empty()
                 ? std::string()
                 : "; nodes changing status: " + node_ids(model, constraints, outcome.offending));
        if (fixed || dt * 0.25 < min_increment)
          throw NotConvergedError(message + (fixed ? " (fixed increments: *STATIC, DIRECT)"
                                                   : format("; the increment %.3g reached the "
                                                            "minimum",
                                                            dt)));
        phases.info(message + format("; cutting the increment to %.4g", dt * 0.25));
        dt *= 0.25;
        quick = 0;
        continue;
      }
      state = std::move(trial);
      t += dt;
      ++increment_number;
      quick = outcome.iterations <= 5 ? quick + 1 : 0;

      // Displacements: the contact forces act on the structure as loads.
      const std::vector<double> f_t = lerp(f_start, f_end, tau);
      const std::vector<double> up_t = lerp(up_start, up_end, tau);
      Eigen::VectorXd lambda(3 * constraints.size());
      for (std::size_t j = 0; j < constraints.size(); ++j)
        lambda.segment<3>(3 * j) = state.nodes[j].lambda;
      std::vector<double> loads = f_t;
      B.add_transpose(lambda, -1.0, loads);
      std::vector<double> u = factor.solver->solve(loads, up_t);
      if (R.cols() > 0) {
        const Eigen::VectorXd rigid = R * state.alpha;
        for (std::size_t i = 0; i < u.size(); ++i) u[i] += rigid[i];
      }
      IncrementResult increment;
      increment.step = static_cast<int>(k) + 1;
      increment.increment = increment_number;
      increment.step_time = t;
      increment.total_time = total_time + t;
      {
        const PhaseRecorder::Scope phase(phases, "recover");
        recover_increment(model, prepared, prescribed, u, loads, threads, increment);
        averaging.apply(threads, increment);
        contact::fill_contact_results(model, constraints, state, increment);
        check_equilibrium(f_t, increment, constraints, state, increment.contact_equilibrium);
      }
      phases.info(where + format(": converged in %.0f iterations, equilibrium residual %.2e",
                                 outcome.iterations,
                                 increment.contact_equilibrium.relative_residual));
      results.increments.push_back(std::move(increment));
      u_previous = u;
      if (!fixed && quick >= 2) dt = std::min(dt * 1.5, max_increment);
    }
    total_time += period;
    f_previous = f_end;
  }
  return results;
}

}  // namespace styk::solver_detail
