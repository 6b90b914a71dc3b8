#include "contact_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include <Eigen/Geometry>

#include "assembly.hpp"
#include "body_loads.hpp"
#include "contact_operator.hpp"
#include "element_states.hpp"
#include "floating_bodies.hpp"
#include "linear_solver.hpp"
#include "mechanism_check.hpp"
#include "model_constraints.hpp"
#include "model_warnings.hpp"
#include "output_quantities.hpp"
#include "parallel.hpp"
#include "penetration_steps.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "recovery.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"
#include "stress_averaging.hpp"
#include "styk/contact/active_set.hpp"
#include "styk/contact/contact_results.hpp"
#include "styk/core/vec3.hpp"
#include "thermal_load.hpp"

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
  std::vector<int> prescribed;  // the model's (nodal dofs, without the fixing dofs)
  FloatingBodies floating;
  std::unique_ptr<LinearSolver> solver;
  Eigen::MatrixXd S, G;
};

// Sums of the force part of a nodal field on active dofs (moments of rotational dofs left out).
Vec3 dof_sum(const PreparedModel& prepared, const std::vector<double>& f) {
  Vec3 sum{0.0, 0.0, 0.0};
  for (int a = 0; a < prepared.active_nodes(); ++a)
    for (int d = 0; d < 3; ++d) sum[d] += f[prepared.dof(a, d)];
  return sum;
}

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

void check_equilibrium(const PreparedModel& prepared, const std::vector<double>& applied,
                       const IncrementResult& increment,
                       const std::vector<contact::ContactConstraint>& constraints,
                       const contact::ContactState& state, ContactEquilibrium& out) {
  out.valid = true;
  out.applied = dof_sum(prepared, applied);
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
  // Relative to the forces involved, not only to their sums: in a self-balanced model (a full
  // shrink fit under heat) every sum is round-off and a ratio of sums would be meaningless.
  double magnitude = 0.0;
  for (const Vec3& rf : increment.RF) magnitude += as_eigen(rf).norm();
  for (std::size_t j = 0; j < constraints.size(); ++j)
    magnitude += contact::slave_force(constraints[j], state.nodes[j]).norm();
  for (double f : applied) magnitude += std::abs(f);
  const double scale = std::max({as_eigen(out.applied).norm(), as_eigen(out.reactions).norm(),
                                 as_eigen(out.contact_slave).norm(),
                                 magnitude / static_cast<double>(std::max<std::size_t>(
                                                 1, constraints.size() + increment.RF.size())),
                                 1e-300});
  out.relative_residual = as_eigen(imbalance).norm() / scale;
}

// The loads of one step end (or start): mechanical forces on the nodal dofs (what reactions are
// measured against), the thermal load of the step's temperature change (global components;
// empty without one) and the temperature change itself, which recovery needs for the stresses.
struct StepLoads {
  std::vector<double> mechanical;
  std::vector<double> thermal;
  std::vector<double> dT;
};

std::vector<double> lerp_or_empty(const std::vector<double>& a, const std::vector<double>& b,
                                  double t) {
  if (a.empty() && b.empty()) return {};
  if (a.empty()) return lerp(std::vector<double>(b.size(), 0.0), b, t);
  if (b.empty()) return lerp(a, std::vector<double>(a.size(), 0.0), t);
  return lerp(a, b, t);
}

std::vector<double> to_global(const ModelConstraints& kinematic, std::vector<double> nodal) {
  kinematic.rotations().to_global(nodal);
  return nodal;
}

// Per frictional pair: whether every closed slave node slips (full slip: the friction capacity
// is reached), and the log line that reports it with the contact forces' resultant, which is then
// the capacity (about the cyclic symmetry axis, per sector and for the whole structure, when the
// model has one).
std::vector<char> full_slip(const Model& model,
                            const std::vector<contact::ContactConstraint>& constraints,
                            const contact::ContactState& state) {
  std::vector<int> closed(model.contact_pairs.size(), 0), stick(model.contact_pairs.size(), 0);
  std::vector<char> frictional(model.contact_pairs.size(), 0);
  for (std::size_t j = 0; j < constraints.size(); ++j) {
    const int p = constraints[j].pair;
    frictional[p] = frictional[p] || constraints[j].law.kind == contact::FrictionLaw::Kind::Coulomb;
    if (state.nodes[j].status == contact::NodeStatus::Open) continue;
    ++closed[p];
    if (state.nodes[j].status == contact::NodeStatus::Stick) ++stick[p];
  }
  std::vector<char> out(model.contact_pairs.size(), 0);
  for (std::size_t p = 0; p < out.size(); ++p)
    out[p] = frictional[p] && closed[p] > 0 && stick[p] == 0;
  return out;
}

std::string full_slip_report(const Model& model, const IncrementResult& increment, int pair) {
  const ContactPair& cp = model.contact_pairs[pair];
  const ContactPairResult& r = increment.contact_pairs[pair];
  int closed = 0;
  for (const ContactNodeResult& c : increment.contact)
    closed += c.pair == pair && c.status != ContactStatus::Open ? 1 : 0;
  std::string text =
      "contact pair " + cp.slave + "/" + cp.master +
      format(": full slip, all %.0f closed slave nodes slip; contact force ", closed) +
      format("(%.6g, %.6g, %.6g), ", r.force[0], r.force[1], r.force[2]) +
      format("moment (%.6g, %.6g, %.6g) about the origin", r.moment[0], r.moment[1], r.moment[2]);
  for (const CyclicSymmetry& c : model.cyclic_symmetries) {
    const Eigen::Vector3d axis = (as_eigen(c.b) - as_eigen(c.a)).normalized();
    // Moment about the axis through a: (M_origin - a x F) . axis.
    const double m = (as_eigen(r.moment) - as_eigen(c.a).cross(as_eigen(r.force))).dot(axis);
    text += format("; about the axis of cyclic symmetry %.6g per sector, %.6g on the whole", m,
                   m * c.sectors) +
            format(" structure (%.0f sectors)", c.sectors);
  }
  return text;
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
  ModelConstraints kinematic;  // *TRANSFORM and *EQUATION
  std::vector<std::vector<double>> temperature_changes;
  {
    const PhaseRecorder::Scope phase(phases, "check");
    if (model.steps.empty())
      throw InputError(whole_model, "the model has no *STEP: there is nothing to analyse");
    if (model.element_count() == 0) throw InputError(whole_model, "the model has no elements");
    prepared = prepare_model(model, registry);
    check_output_requests(model, prepared);
    conditions = accumulate_step_conditions(model, prepared);
    kinematic = ModelConstraints::build(model, prepared, registry);
    temperature_changes = step_temperature_changes(model);
    for (const std::string& warning : model_warnings(model, prepared)) phases.warning(warning);
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
  const StressAveraging averaging(model, prepared.formulation, prepared.rule_kind);
  // K in the nodal systems with the equations eliminated (model_constraints.hpp), as in the
  // linear path; the contact rows stay global and the compliance maps between the two.
  StiffnessMatrix K(model, prepared, threads, kinematic.extra_node_couplings(model, prepared));
  // The elements' material state at the end of step k; K holds the one of `stiffness_states`
  // (a step that changes materials or the temperatures of temperature-dependent elasticity gets
  // a stiffness of its own, evaluated at the end of the step).
  const std::vector<double> initial_temperature = initial_node_temperatures(model);
  std::vector<std::vector<double>> step_temperature(model.steps.size());
  for (std::size_t k = 0; k < model.steps.size(); ++k)
    if (!temperature_changes[k].empty()) {
      step_temperature[k] = initial_temperature;
      for (std::size_t n = 0; n < initial_temperature.size(); ++n)
        step_temperature[k][n] += temperature_changes[k][n];
    }
  auto states_of = [&](std::size_t k) {
    return ElementStates(model, prepared, k,
                         step_temperature[k].empty() ? nullptr : &step_temperature[k]);
  };
  std::optional<ElementStates> stiffness_states;
  stiffness_states.emplace(states_of(0));
  auto assemble = [&] {
    const PhaseRecorder::Scope phase(phases, "assemble");
    assemble_stiffness(model, prepared, *stiffness_states, K, threads);
    kinematic.apply(K);
  };
  assemble();
  const SolverContext context{model, prepared, phases, threads, options.memory_limit_gb};
  const ContactOperator B(prepared, constraints);
  const std::vector<char> touches_contact = contact_nodes(prepared, constraints);

  ContactFactor factor;
  auto set_up = [&](const std::vector<int>& prescribed) {
    factor.solver.reset();
    factor.prescribed = prescribed;
    const std::vector<int> known = kinematic.known_dofs(model, prepared, prescribed);
    factor.floating = find_floating_bodies(
        model, prepared, K.graph(), kinematic.restraints(model, prepared, prescribed), prescribed,
        known, kinematic.rotations(), touches_contact);
    std::vector<int> held = prescribed, pinned = known;
    for (std::vector<int>* dofs : {&held, &pinned}) {
      dofs->insert(dofs->end(), factor.floating.fixing_dofs.begin(),
                   factor.floating.fixing_dofs.end());
      std::sort(dofs->begin(), dofs->end());
      dofs->erase(std::unique(dofs->begin(), dofs->end()), dofs->end());
    }
    {
      const PhaseRecorder::Scope phase(phases, "check");
      check_rigid_body_modes(model, prepared, K.graph(),
                             kinematic.restraints(model, prepared, held));
    }
    if (!K.pristine()) assemble();
    factor.solver = make_cholmod_solver(context);
    factor.solver->prepare(K, partition_dofs(prepared.active_dofs(), pinned));
    {
      const PhaseRecorder::Scope phase(phases, "contact compliance");
      factor.S = B.compliance(*factor.solver, prepared.active_dofs(), kinematic);
      factor.G = B.apply_columns(factor.floating.modes);
    }
    phases.info("contact: " + std::to_string(factor.floating.count()) +
                " rigid motions held only by contact");
    if (report != nullptr && report->linear_solver.empty()) {
      report->linear_solver = factor.solver->description() + " + dense contact active set";
      report->dofs = prepared.active_dofs() - static_cast<long long>(pinned.size());
    }
  };

  // The structure's displacement (global) and the contact-row images d = B u of a step end's
  // loads: mechanical + thermal forces, turned to the nodal systems and reduced by the equations.
  auto solve_global = [&](const std::vector<double>& mechanical, const std::vector<double>& thermal,
                          const std::vector<double>& prescribed_values) {
    std::vector<double> u = factor.solver->solve(
        kinematic.reduced_forces(kinematic.plus_global(mechanical, thermal)), prescribed_values);
    kinematic.to_global_displacements(u);
    return u;
  };
  // The rigid-mode equilibrium right-hand side R^T f (global forces; the thermal load is
  // self-equilibrated, R^T f_th = 0 up to round-off, and kept for consistency with d0).
  auto rigid_load = [&](const StepLoads& loads) {
    std::vector<double> f = to_global(kinematic, loads.mechanical);
    for (std::size_t i = 0; i < loads.thermal.size(); ++i) f[i] += loads.thermal[i];
    const Eigen::Map<const Eigen::VectorXd> map(f.data(), prepared.active_dofs());
    return Eigen::VectorXd(factor.floating.modes.transpose() * map);
  };

  Results results;
  contact::ContactState state;
  const std::vector<StepPenetration> penetration = accumulate_penetrations(model);
  std::vector<std::string> leaked;  // zones ("SLAVE/MASTER") whose leak has been reported
  std::vector<char> slipping(model.contact_pairs.size(), 0);  // full slip at the last increment
  StepLoads previous{std::vector<double>(prepared.active_dofs(), 0.0), {}, {}};
  std::vector<double> u_previous(prepared.active_dofs(), 0.0);  // nodal components
  double total_time = 0.0;
  for (std::size_t k = 0; k < model.steps.size(); ++k) {
    const Step& step = model.steps[k];
    const std::vector<int> prescribed = prescribed_dofs(conditions[k]);
    const ElementStates states = states_of(k);
    const bool new_stiffness = stiffness_states->stiffness_differs(states);
    if (new_stiffness) {
      factor.solver.reset();
      stiffness_states.emplace(states);
      assemble();
    }
    if (!factor.solver || new_stiffness || prescribed != factor.prescribed) set_up(prescribed);
    const Eigen::MatrixXd& R = factor.floating.modes;
    const std::vector<int> reaction_dofs = kinematic.reaction_dofs(prescribed);

    // Loads, prescribed values and temperatures ramp linearly from the end of the previous step
    // (newly prescribed dofs from where they are) to this step's values: Abaqus' default RAMP
    // amplitude of a static step, applied to the temperature field too, so an increment at step
    // fraction tau carries tau of the step's temperature change (docs/contact.md).
    StepLoads end;
    end.mechanical =
        kinematic.plus_global(kinematic.nodal_forces(model, prepared, conditions[k]),
                              assemble_body_loads(model, prepared, states, conditions[k]));
    end.dT = temperature_changes[k];
    if (!end.dT.empty() || !model.initial_stresses.empty()) {
      const PhaseRecorder::Scope phase(phases, "assemble");
      end.thermal = assemble_eigenstrain_load(model, prepared, states, threads);
    }
    std::vector<double> up_end(prepared.active_dofs(), 0.0);
    for (const DofValue& p : conditions[k].prescribed) up_end[p.dof] = p.value;
    for (int dof : conditions[k].fixed) up_end[dof] = u_previous[dof];  // *BOUNDARY, FIXED
    const StepLoads start = previous;
    // Only the prescribed dofs' values matter (dependent and fixing dofs start from zero).
    std::vector<double> up_start(prepared.active_dofs(), 0.0);
    for (const DofValue& p : conditions[k].prescribed) up_start[p.dof] = u_previous[p.dof];
    contact::LinearContactSystem system;
    system.S = factor.S;
    system.G = factor.G;
    const Eigen::VectorXd d0_start =
        B.apply(solve_global(start.mechanical, start.thermal, up_start));
    const Eigen::VectorXd d0_end = B.apply(solve_global(end.mechanical, end.thermal, up_end));
    const Eigen::VectorXd h_start = rigid_load(start), h_end = rigid_load(end);
    const contact::PenetrationLayout fluid_layout =
        contact::layout_penetrations(model, registry, constraints, penetration[k].definitions);
    // Per zone: the fluid pressure of the last converged increment (the step's start value first).
    std::vector<double> fluid_before = penetration[k].start;

    const double period = step.procedure.total_time;
    const bool fixed = step.procedure.fixed_increments;
    const double max_increment = step.procedure.max_increment.value_or(period);
    const double min_increment = step.procedure.min_increment.value_or(1e-5 * period);
    double dt = std::min(step.procedure.initial_increment, max_increment);
    double t = 0.0;
    double last_dt = 0.0;  // the last converged increment of this step (0: none yet)
    std::string sliding;   // the last loss of equilibrium found in this step (a larger trial)
    int increment_number = 0, quick = 0;
    while (t < period * (1.0 - 1e-12)) {
      dt = std::min(dt, period - t);
      const double tau = (t + dt) / period;
      system.d0 = (1.0 - tau) * d0_start + tau * d0_end;
      system.h = (1.0 - tau) * h_start + tau * h_end;
      const std::vector<double> fluid_pressures = penetration[k].at(tau);
      system.fluid = contact::fluid_loads(fluid_layout, constraints, fluid_pressures);
      contact::ContactState trial = state;
      const std::string where = "contact step " + std::to_string(k + 1) + " increment " +
                                std::to_string(increment_number + 1) +
                                format(" (t = %.4g)", t + dt);
      auto log = [&](const contact::IterationRecord& r) {
        phases.info(where + format(": iteration %.0f: %.0f stick, ", r.iteration, r.stick) +
                    format("%.0f slip, %.0f open, ", r.slip, r.open) +
                    format("%.0f changes, residual %.2e", r.changes, r.residual) +
                    (r.anticipated > 0
                         ? format(" (%.0f of them ahead of the slip front)", r.anticipated)
                         : "") +
                    (system.fluid.empty() ? "" : format(", %.0f penetrated", r.penetrated)) +
                    (r.cycle ? format(", cycle detected: step length %.3g", r.damping) : "") +
                    (r.regularised ? ", held by slipping nodes alone: slip springs" : ""));
      };
      contact::ActiveSetOptions iteration_options;
      iteration_options.extrapolation = last_dt > 0.0 ? dt / last_dt : 0.0;
      const contact::IncrementOutcome outcome =
          contact::solve_increment(constraints, system, trial, iteration_options, log);
      if (!outcome.converged) {
        const std::string message =
            where + " did not converge: " +
            (outcome.loss.lost ? sliding_report(model, prepared, factor.floating, outcome.loss)
                               : outcome.reason) +
            (outcome.offending.empty()
                 ? std::string()
                 : "; nodes changing status: " + node_ids(model, constraints, outcome.offending));
        if (outcome.loss.lost)
          sliding = format("at t = %.6g ", t + dt) +
                    sliding_report(model, prepared, factor.floating, outcome.loss);
        if ((fixed || dt * 0.25 < min_increment) && !outcome.loss.lost && !sliding.empty())
          throw NotConvergedError(message + "; the limit load is reached: " + sliding);
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
      last_dt = dt;
      ++increment_number;
      // "Quick": within the iteration budget of docs/contact.md (8 per increment). A tighter
      // limit (5) kept the shrink-fit push at 1/90 of the step for 100 increments of 6
      // iterations each.
      quick = outcome.iterations <= 8 ? quick + 1 : 0;

      // Displacements: the contact forces act on the structure as loads.
      const std::vector<double> f_t = lerp(start.mechanical, end.mechanical, tau);
      const std::vector<double> thermal_t = lerp_or_empty(start.thermal, end.thermal, tau);
      const std::vector<double> dT_t = lerp_or_empty(start.dT, end.dT, tau);
      const std::vector<double> up_t = lerp(up_start, up_end, tau);
      Eigen::VectorXd lambda(3 * constraints.size());
      for (std::size_t j = 0; j < constraints.size(); ++j) {
        lambda.segment<3>(3 * j) = state.nodes[j].lambda;
        lambda[3 * j] += state.nodes[j].fluid;  // pressure penetration: a normal force too
      }
      std::vector<double> contact_forces(prepared.active_dofs(), 0.0);
      B.add_transpose(lambda, -1.0, contact_forces);
      // External forces on the nodal dofs (reactions are measured against them): the mechanical
      // loads and the contact forces; the thermal load joins only the right-hand side.
      const std::vector<double> loads = kinematic.plus_global(f_t, contact_forces);
      std::vector<double> u = solve_global(loads, thermal_t, up_t);
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
        std::vector<double> temperature_t;
        if (!dT_t.empty()) {
          temperature_t = initial_temperature;
          for (std::size_t n = 0; n < temperature_t.size(); ++n) temperature_t[n] += dT_t[n];
        }
        const ElementStates states_t(model, prepared, k,
                                     temperature_t.empty() ? nullptr : &temperature_t);
        const OutputNeeds needs = output_needs(model, k);
        const RecoveryInput input{
            reaction_dofs,        u, loads, &states_t, &kinematic.rotations(), needs.energies,
            needs.thermal_strains};
        recover_increment(model, prepared, input, threads, increment);
        averaging.apply(threads, increment);
        if (needs.error_estimate)
          estimate_stress_errors(model, prepared, states_t, threads, increment);
        compute_section_forces(model, prepared, k, increment);
        contact::fill_contact_results(model, constraints, state, increment);
        increment.penetrations = penetration_results(model, fluid_layout, state, fluid_pressures);
        check_equilibrium(prepared, to_global(kinematic, f_t), increment, constraints, state,
                          increment.contact_equilibrium);
      }
      phases.info(where + format(": converged in %.0f iterations, equilibrium residual %.2e",
                                 outcome.iterations,
                                 increment.contact_equilibrium.relative_residual));
      for (std::size_t z = 0; z < increment.penetrations.size(); ++z) {
        const PenetrationResult& pr = increment.penetrations[z];
        const std::string& label = fluid_layout.zones[z].label;
        if (!pr.leaked) continue;
        if (std::find(leaked.begin(), leaked.end(), label) != leaked.end()) continue;
        leaked.push_back(label);
        phases.info(where + ": pressure penetration " + label +
                    format(": leak at fluid pressure %.6g (the penetrated zone, %.0f of ",
                           pr.pressure, pr.penetrated) +
                    format("%.0f nodes, reaches the LEAK set; the increment before held at %.6g)",
                           pr.nodes, fluid_before[z]));
      }
      fluid_before = fluid_pressures;
      const std::vector<char> slipping_now = full_slip(model, constraints, state);
      for (std::size_t p = 0; p < slipping_now.size(); ++p)
        if (slipping_now[p] && !slipping[p])
          phases.info(where + ": " + full_slip_report(model, increment, static_cast<int>(p)));
      slipping = slipping_now;
      results.increments.push_back(std::move(increment));
      u_previous = u;
      kinematic.rotations().to_local(u_previous);
      // Growth: doubled at once after an easy increment (the predictor was nearly right), by 1.5
      // after two within the budget.
      if (!fixed && outcome.iterations <= 3)
        dt = std::min(dt * 2.0, max_increment);
      else if (!fixed && quick >= 2)
        dt = std::min(dt * 1.5, max_increment);
    }
    total_time += period;
    previous = std::move(end);
  }
  return results;
}

}  // namespace styk::solver_detail
