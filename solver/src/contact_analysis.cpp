// The contact step driver (contact_analysis.hpp) as one type whose member functions are its
// phases: check -> per step: stiffness and factorisation (with the contact compliance) -> the
// step's load ramp -> per increment: the active-set iteration, then on convergence the
// displacements, recovery and the increment's reports; on failure a cut-back or the error.
#include "contact_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "analysis_setup.hpp"
#include "assembly.hpp"
#include "augmented_lu.hpp"
#include "body_loads.hpp"
#include "contact_increment_report.hpp"
#include "contact_operator.hpp"
#include "contact_solve_choice.hpp"
#include "distributed_solver.hpp"
#include "element_states.hpp"
#include "floating_bodies.hpp"
#include "increment_control.hpp"
#include "linear_solver.hpp"
#include "mechanism_check.hpp"
#include "model_constraints.hpp"
#include "output_quantities.hpp"
#include "penetration_steps.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "recovery.hpp"
#include "sparse_contact_structure.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"
#include "stress_averaging.hpp"
#include "styk/contact/active_set.hpp"
#include "styk/contact/contact_results.hpp"
#include "styk/contact/penalty_law.hpp"
#include "styk/contact/penetration.hpp"
#include "styk/core/machine_memory.hpp"
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

// K factorised with the prescribed dofs plus the dofs pinning the bodies held only by contact,
// and the structure-side pieces of the contact system that depend on it.
struct ContactFactor {
  std::vector<int> prescribed;  // the model's (nodal dofs, without the fixing dofs)
  FloatingBodies floating;
  std::unique_ptr<LinearSolver> solver;
  Eigen::MatrixXd S, G;
  // Instead of S when the contact layer is too large for it (SolveOptions::contact_solve).
  std::shared_ptr<SparseContactStructure> structure;
};

// The loads of one step end (or start): mechanical forces on the nodal dofs (what reactions are
// measured against), the thermal load of the step's temperature change (global components;
// empty without one) and the temperature change itself, which recovery needs for the stresses.
struct StepLoads {
  std::vector<double> mechanical;
  std::vector<double> thermal;
  std::vector<double> dT;
};

// One step's linear ramp from its start to its end (docs/contact.md, "Increments and steps"), as
// the structure and as the contacts see it.
struct StepRamp {
  StepLoads start, end;
  std::vector<double> up_start, up_end;  // prescribed values (nodal dofs)
  Eigen::VectorXd d0_start, d0_end;      // B u of the loads alone
  Eigen::VectorXd h_start, h_end;        // R^T f: the rigid-mode equilibrium right-hand side
  contact::PenetrationLayout fluid_layout;
  std::vector<int> reaction_dofs;
};

// What the check phase finds.
struct ContactModel {
  MechanicalModel mechanical;
  std::vector<contact::ContactConstraint> constraints;
  std::vector<std::vector<double>> temperature_changes;
};

const char* const kDirectOnly =
    "contact analysis needs the direct solver (CHOLMOD): the iterative solver cannot supply the "
    "contact compliance";

ContactModel check_contact_model(const Model& model, const ElementRegistry& registry,
                                 const SolveOptions& options, const PhaseRecorder& phases) {
  if (options.force == LinearSolverKind::Iterative)
    throw InputError(SourceLoc{model.source, 0}, kDirectOnly);
  for (const Step& step : model.steps)
    if (step.procedure.solver == LinearSolverKind::Iterative)
      throw InputError(step.procedure.where, kDirectOnly);
  const PhaseRecorder::Scope phase(phases, "check");
  ContactModel out;
  out.mechanical = prepare_mechanical_model(model, registry, phases);
  out.temperature_changes = step_temperature_changes(model);
  std::vector<std::string> notes;
  out.constraints = contact::build_contact_constraints(model, registry, &notes);
  for (const std::string& note : notes) phases.info(note);
  if (out.constraints.empty())
    throw InputError(model.contact_pairs.front().where,
                     "no slave node of any contact pair reaches its master surface");
  const PreparedModel& prepared = out.mechanical.prepared;
  for (const contact::ContactConstraint& c : out.constraints)
    if (prepared.active_of_node[c.slave] < 0)
      throw InputError(
          model.contact_pairs[c.pair].where,
          "slave node " + std::to_string(model.node_ids[c.slave]) + " belongs to no element");
  phases.info("contact: " + std::to_string(out.constraints.size()) + " constraints in " +
              std::to_string(model.contact_pairs.size()) + " pairs");
  for (const ContactPair& pair : model.contact_pairs)
    phases.info(
        "contact pair " + pair.slave + "/" + pair.master + ": normal law " +
        contact::normal_law_label(model.surface_interactions.at(pair.interaction).behavior));
  return out;
}

class ContactAnalysis {
 public:
  ContactAnalysis(const Model& model, const ElementRegistry& registry, const SolveOptions& options,
                  const AnalysisStart& start, AnalysisReport* report, ContactModel checked)
      : model_(model),
        registry_(registry),
        phases_(start.phases()),
        report_(report),
        threads_(start.threads()),
        checked_(std::move(checked)),
        prepared_(checked_.mechanical.prepared),
        kinematic_(checked_.mechanical.kinematic),
        constraints_(checked_.constraints),
        averaging_(model, prepared_.formulation, prepared_.rule_kind),
        // K in the nodal systems with the equations eliminated (model_constraints.hpp), as in
        // the linear path; the contact rows stay global and the compliance maps between the two.
        K_(model, prepared_, threads_, kinematic_.extra_node_couplings(model, prepared_)),
        initial_temperature_(initial_node_temperatures(model)),
        // No refinement of the structure's solves: the contact answer is settled to the active
        // set's tolerance (1e-9), and each refinement would cost a substitution (~0.3 s with
        // model B's factor, two dozen times a run) for digits the contact iteration does not keep.
        context_{model, prepared_, phases_, threads_, options.memory_limit_gb, false},
        share_(rank_share(options)),
        contact_solve_(options.contact_solve),
        B_(prepared_, constraints_),
        touches_contact_(contact_nodes(prepared_, constraints_)),
        penetration_(accumulate_penetrations(model)),
        slipping_(model.contact_pairs.size(), 0),
        previous_{std::vector<double>(prepared_.active_dofs(), 0.0), {}, {}},
        u_previous_(prepared_.active_dofs(), 0.0) {
    step_temperature_.resize(model.steps.size());
    for (std::size_t k = 0; k < model.steps.size(); ++k)
      if (!checked_.temperature_changes[k].empty()) {
        step_temperature_[k] = initial_temperature_;
        for (std::size_t n = 0; n < initial_temperature_.size(); ++n)
          step_temperature_[k][n] += checked_.temperature_changes[k][n];
      }
    stiffness_states_.emplace(states_of(0));
    assemble();
  }

  Results run() {
    for (std::size_t k = 0; k < model_.steps.size(); ++k) run_step(k);
    return std::move(results_);
  }

 private:
  // A distributed run's share of rows and elements (the graph partition of the static path).
  std::optional<RankShare> rank_share(const SolveOptions& options) const {
    if (!options.distributed) return std::nullopt;
    const PhaseRecorder::Scope phase(phases_, "partition");
    RankShare share = share_of_rank(model_, prepared_, K_.graph(), join_mpi_world(),
                                    kinematic_.equations().dependent_dofs());
    phases_.info("partition: " + std::to_string(share.rows.size) + " ranks, " +
                 std::to_string(share.cut_node_pairs) + " node pairs couple two ranks");
    return share;
  }

  // The elements' material state at the end of step k; K holds the one of `stiffness_states_`
  // (a step that changes materials or the temperatures of temperature-dependent elasticity gets
  // a stiffness of its own, evaluated at the end of the step).
  ElementStates states_of(std::size_t k) const {
    return ElementStates(model_, prepared_, k,
                         step_temperature_[k].empty() ? nullptr : &step_temperature_[k]);
  }

  void assemble() {
    const PhaseRecorder::Scope phase(phases_, "assemble");
    assemble_stiffness(model_, prepared_, *stiffness_states_, K_, threads_,
                       share_ ? &share_->assembles_element : nullptr);
    kinematic_.apply(K_);
  }

  // Phase: the step's stiffness (re-assembled when the step changes it) and factorisation (redone
  // when the stiffness or the prescribed set changes).
  void update_factor(const ElementStates& states, const std::vector<int>& prescribed) {
    const bool new_stiffness = stiffness_states_->stiffness_differs(states);
    if (new_stiffness) {
      factor_.solver.reset();  // drops any view of K's arrays before K is reassembled
      stiffness_states_.emplace(states);
      assemble();
    }
    if (!factor_.solver || new_stiffness || prescribed != factor_.prescribed) factorise(prescribed);
  }

  // K factorised with the prescribed dofs and the dofs pinning the bodies held only by contact;
  // then the contact compliance S and G = B R.
  void factorise(const std::vector<int>& prescribed) {
    factor_.solver.reset();
    factor_.prescribed = prescribed;
    const std::vector<int> known = kinematic_.known_dofs(model_, prepared_, prescribed);
    factor_.floating = find_floating_bodies(
        model_, prepared_, K_.graph(), kinematic_.restraints(model_, prepared_, prescribed),
        prescribed, known, kinematic_.rotations(), touches_contact_);
    std::vector<int> held = prescribed, pinned = known;
    for (std::vector<int>* dofs : {&held, &pinned}) {
      dofs->insert(dofs->end(), factor_.floating.fixing_dofs.begin(),
                   factor_.floating.fixing_dofs.end());
      std::sort(dofs->begin(), dofs->end());
      dofs->erase(std::unique(dofs->begin(), dofs->end()), dofs->end());
    }
    {
      const PhaseRecorder::Scope phase(phases_, "check");
      check_rigid_body_modes(model_, prepared_, K_.graph(),
                             kinematic_.restraints(model_, prepared_, held));
    }
    if (!K_.pristine()) assemble();
    // Distributed: MUMPS across the ranks; every rank then holds the same compliance and runs the
    // same active-set iteration (the dense contact system is small beside K).
    factor_.solver = share_ ? make_distributed_solver(context_, share_->rows, true, 0.0)
                            : make_cholmod_solver(context_);
    const DofPartition partition = partition_dofs(prepared_.active_dofs(), pinned);
    factor_.structure.reset();
    factor_.S.resize(0, 0);
    factor_.solver->prepare(K_, partition);
    if (sparse_contact_solve(factor_.solver->factor_nonzeros())) {
      // CHOLMOD keeps its own copy of K_ff and released K's values: assembled again for the
      // structure's copy, then released (the next step's factorisation reassembles as before).
      if (!K_.pristine()) assemble();
      factor_.structure = std::make_shared<SparseContactStructure>(
          K_, partition, B_.reduced_rows(prepared_.active_dofs(), kinematic_),
          prepared_.active_dofs());
      K_.release_values();
    }
    {
      const PhaseRecorder::Scope phase(phases_, "contact compliance");
      if (factor_.structure)
        factor_.structure->attach(*factor_.solver);
      else
        factor_.S = B_.compliance(*factor_.solver, prepared_.active_dofs(), kinematic_);
      factor_.G = B_.apply_columns(factor_.floating.modes);
    }
    phases_.info("contact: " + std::to_string(factor_.floating.count()) +
                 " rigid motions held only by contact");
    if (report_ != nullptr && report_->linear_solver.empty()) {
      report_->linear_solver =
          factor_.solver->description() +
          (factor_.structure ? " + sparse contact solve (MUMPS LU of K with the contact rows)"
                             : " + dense contact active set");
      report_->dofs = prepared_.active_dofs() - static_cast<long long>(pinned.size());
    }
  }

  // Whether the contact iteration sees the structure through the sparse solve: when asked to,
  // or by the automatic rule (contact_solve_choice.hpp) from the size of the contact layer and of
  // K's factor. Distributed runs hold S.
  bool sparse_contact_solve(double factor_nonzeros) const {
    if (share_ || contact_solve_ == ContactSolveKind::Dense) return false;
    if (!augmented_lu_available()) {
      if (contact_solve_ == ContactSolveKind::Sparse)
        throw InputError(SourceLoc{model_.source, 0},
                         "the sparse contact solve needs a build with PETSc (MUMPS)");
      return false;
    }
    if (contact_solve_ == ContactSolveKind::Sparse) return true;
    ContactSolveSize size;
    size.constraints = static_cast<double>(constraints_.size());
    for (int i = 0; i < B_.rows(); ++i) size.used_rows += B_.row_used(i) ? 1.0 : 0.0;
    size.factor_nonzeros = factor_nonzeros;
    size.memory_limit_bytes = context_.memory_limit_gb > 0.0 ? context_.memory_limit_gb * 1e9
                                                             : 0.8 * physical_memory_bytes();
    return sparse_contact_pays(size);
  }

  // Per constraint: the tangential directions of mortar rows that the slave node's prescribed
  // dofs fix (contact::LinearContactSystem::held), in the node's own system (*TRANSFORM).
  std::vector<std::array<bool, 3>> held_directions(const std::vector<int>& prescribed) const {
    std::vector<char> is_prescribed(prepared_.active_dofs(), 0);
    for (int dof : prescribed) is_prescribed[dof] = 1;
    std::vector<std::array<bool, 3>> held(constraints_.size(), {false, false, false});
    for (std::size_t j = 0; j < constraints_.size(); ++j) {
      const contact::ContactConstraint& c = constraints_[j];
      if (!c.mortar) continue;
      const int a = prepared_.active_of_node[c.slave];
      const Eigen::Matrix3d* R = kinematic_.rotations().of(a);
      for (int k = 0; k < 3; ++k) {
        const int dof = prepared_.dof(a, k);
        if (dof < 0 || !is_prescribed[dof]) continue;
        const Eigen::Vector3d axis =
            R != nullptr ? Eigen::Vector3d(R->col(k)) : Eigen::Vector3d::Unit(k);
        held[j][1] = held[j][1] || std::abs(c.t1.dot(axis)) > 1.0 - 1e-9;
        held[j][2] = held[j][2] || std::abs(c.t2.dot(axis)) > 1.0 - 1e-9;
      }
    }
    return held;
  }

  // The structure's displacement (global) and the contact-row images d = B u of a step end's
  // loads: mechanical + thermal forces, turned to the nodal systems and reduced by the equations.
  std::vector<double> solve_global(const std::vector<double>& mechanical,
                                   const std::vector<double>& thermal,
                                   const std::vector<double>& prescribed_values) const {
    std::vector<double> u = factor_.solver->solve(
        kinematic_.reduced_forces(kinematic_.plus_global(mechanical, thermal)), prescribed_values);
    kinematic_.to_global_displacements(u);
    return u;
  }

  // The rigid-mode equilibrium right-hand side R^T f (global forces; the thermal load is
  // self-equilibrated, R^T f_th = 0 up to round-off, and kept for consistency with d0).
  Eigen::VectorXd rigid_load(const StepLoads& loads) const {
    std::vector<double> f = to_global(kinematic_, loads.mechanical);
    for (std::size_t i = 0; i < loads.thermal.size(); ++i) f[i] += loads.thermal[i];
    const Eigen::Map<const Eigen::VectorXd> map(f.data(), prepared_.active_dofs());
    return Eigen::VectorXd(factor_.floating.modes.transpose() * map);
  }

  // Phase: the step's ramp. Loads, prescribed values and temperatures ramp linearly from the end
  // of the previous step (newly prescribed dofs from where they are) to this step's values:
  // Abaqus' default RAMP amplitude of a static step, applied to the temperature field too, so an
  // increment at step fraction tau carries tau of the step's temperature change
  // (docs/contact.md).
  StepRamp step_ramp(std::size_t k, const ElementStates& states,
                     const std::vector<int>& prescribed) const {
    const StepConditions& conditions = checked_.mechanical.conditions[k];
    StepRamp ramp;
    ramp.start = previous_;
    ramp.end.mechanical =
        kinematic_.plus_global(kinematic_.nodal_forces(model_, prepared_, conditions),
                               assemble_body_loads(model_, prepared_, states, conditions));
    ramp.end.dT = checked_.temperature_changes[k];
    if (!ramp.end.dT.empty() || !model_.initial_stresses.empty()) {
      const PhaseRecorder::Scope phase(phases_, "assemble");
      ramp.end.thermal = assemble_eigenstrain_load(model_, prepared_, states, threads_);
    }
    ramp.up_end.assign(prepared_.active_dofs(), 0.0);
    for (const DofValue& p : conditions.prescribed) ramp.up_end[p.dof] = p.value;
    for (int dof : conditions.fixed) ramp.up_end[dof] = u_previous_[dof];  // *BOUNDARY, FIXED
    // Only the prescribed dofs' values matter (dependent and fixing dofs start from zero).
    ramp.up_start.assign(prepared_.active_dofs(), 0.0);
    for (const DofValue& p : conditions.prescribed) ramp.up_start[p.dof] = u_previous_[p.dof];
    ramp.d0_start =
        B_.apply(solve_global(ramp.start.mechanical, ramp.start.thermal, ramp.up_start));
    ramp.d0_end = B_.apply(solve_global(ramp.end.mechanical, ramp.end.thermal, ramp.up_end));
    ramp.h_start = rigid_load(ramp.start);
    ramp.h_end = rigid_load(ramp.end);
    ramp.fluid_layout =
        contact::layout_penetrations(model_, registry_, constraints_, penetration_[k].definitions);
    ramp.reaction_dofs = kinematic_.reaction_dofs(prescribed);
    return ramp;
  }

  void run_step(std::size_t k) {
    const std::vector<int> prescribed = prescribed_dofs(checked_.mechanical.conditions[k]);
    const ElementStates states = states_of(k);
    update_factor(states, prescribed);
    const StepRamp ramp = step_ramp(k, states, prescribed);
    contact::LinearContactSystem system;
    system.S = factor_.S;
    system.structure = factor_.structure;
    system.G = factor_.G;
    system.held = held_directions(prescribed);
    // Per zone: the fluid pressure of the last converged increment (the step's start value first).
    fluid_before_ = penetration_[k].start;
    sliding_.clear();
    IncrementControl control(model_.steps[k].procedure);
    while (!control.finished()) {
      const double tau = control.tau();
      system.d0 = (1.0 - tau) * ramp.d0_start + tau * ramp.d0_end;
      system.h = (1.0 - tau) * ramp.h_start + tau * ramp.h_end;
      const std::vector<double> fluid_pressures = penetration_[k].at(tau);
      system.fluid = contact::fluid_loads(ramp.fluid_layout, constraints_, fluid_pressures);
      const std::string where = "contact step " + std::to_string(k + 1) + " increment " +
                                std::to_string(control.converged_count() + 1) +
                                format(" (t = %.4g)", control.end());
      contact::ContactState trial = state_;
      contact::ActiveSetOptions iteration_options;
      iteration_options.extrapolation = control.extrapolation();
      const contact::IncrementOutcome outcome = iterate(where, system, trial, iteration_options);
      if (!outcome.converged) {
        cut_back(where, outcome, control);  // throws at the limits
        continue;
      }
      state_ = std::move(trial);
      control.accept(outcome.iterations);
      IncrementResult increment = recover(k, ramp, control, tau, fluid_pressures);
      report_increment(where, outcome, ramp, fluid_pressures, increment);
      results_.increments.push_back(std::move(increment));
    }
    if (factor_.structure)
      phases_.info("contact step " + std::to_string(k + 1) + ": sparse contact solve, " +
                   std::to_string(factor_.structure->factorisations()) +
                   " LU factorisations so far");
    total_time_ += model_.steps[k].procedure.total_time;
    previous_ = ramp.end;
  }

  // Phase: the active-set iteration of one increment from `trial` (timed as "contact iteration":
  // the dense assembly and LU of the closed rows, per iteration).
  contact::IncrementOutcome iterate(const std::string& where,
                                    const contact::LinearContactSystem& system,
                                    contact::ContactState& trial,
                                    const contact::ActiveSetOptions& iteration_options) const {
    const PhaseRecorder::Scope phase(phases_, "contact iteration");
    const bool fluid = !system.fluid.empty();
    return contact::solve_increment(
        constraints_, system, trial, iteration_options,
        [&](const contact::IterationRecord& r) { phases_.info(where + iteration_line(r, fluid)); });
  }

  // Phase on failure: a smaller increment, or NotConvergedError at the limits naming the step,
  // the time, the reason and the nodes whose status kept changing (the last loss of equilibrium
  // found in the step, at a larger trial increment, names the limit load). A contact law without
  // equilibrium at the increment's load stops the step at once: a smaller increment cannot help.
  void cut_back(const std::string& where, const contact::IncrementOutcome& outcome,
                IncrementControl& control) {
    const std::string message =
        where + " did not converge: " +
        (outcome.loss.lost ? sliding_report(model_, prepared_, factor_.floating, outcome.loss)
                           : outcome.reason) +
        (outcome.offending.empty() ? std::string()
                                   : "; " + outcome.offending_role + ": " +
                                         node_ids(model_, constraints_, outcome.offending));
    if (outcome.loss.lost)
      sliding_ = format("at t = %.6g ", control.end()) +
                 sliding_report(model_, prepared_, factor_.floating, outcome.loss);
    if (outcome.no_equilibrium) throw NotConvergedError(message);
    if (!control.can_cut() && !outcome.loss.lost && !sliding_.empty())
      throw NotConvergedError(message + "; the limit load is reached: " + sliding_);
    if (!control.can_cut())
      throw NotConvergedError(
          message + (control.fixed()
                         ? " (fixed increments: *STATIC, DIRECT)"
                         : format("; the increment %.3g reached the minimum", control.size())));
    phases_.info(message + format("; cutting the increment to %.4g", control.cut_size()));
    control.cut();
  }

  // Phase on convergence: the displacements (the contact forces act on the structure as loads)
  // and the recovery of the increment's results.
  IncrementResult recover(std::size_t k, const StepRamp& ramp, const IncrementControl& control,
                          double tau, const std::vector<double>& fluid_pressures) {
    const std::vector<double> f_t = lerp(ramp.start.mechanical, ramp.end.mechanical, tau);
    const std::vector<double> thermal_t = lerp_or_empty(ramp.start.thermal, ramp.end.thermal, tau);
    const std::vector<double> dT_t = lerp_or_empty(ramp.start.dT, ramp.end.dT, tau);
    const std::vector<double> up_t = lerp(ramp.up_start, ramp.up_end, tau);
    Eigen::VectorXd lambda(3 * constraints_.size());
    for (std::size_t j = 0; j < constraints_.size(); ++j) {
      lambda.segment<3>(3 * j) = state_.nodes[j].lambda;
      lambda[3 * j] += state_.nodes[j].fluid;  // pressure penetration: a normal force too
    }
    std::vector<double> contact_forces(prepared_.active_dofs(), 0.0);
    B_.add_transpose(lambda, -1.0, contact_forces);
    // External forces on the nodal dofs (reactions are measured against them): the mechanical
    // loads and the contact forces; the thermal load joins only the right-hand side.
    const std::vector<double> loads = kinematic_.plus_global(f_t, contact_forces);
    std::vector<double> u = solve_global(loads, thermal_t, up_t);
    const Eigen::MatrixXd& R = factor_.floating.modes;
    if (R.cols() > 0) {
      const Eigen::VectorXd rigid = R * state_.alpha;
      for (std::size_t i = 0; i < u.size(); ++i) u[i] += rigid[i];
    }
    IncrementResult increment;
    increment.step = static_cast<int>(k) + 1;
    increment.increment = control.converged_count();
    increment.step_time = control.start();
    increment.total_time = total_time_ + control.start();
    {
      const PhaseRecorder::Scope phase(phases_, "recover");
      std::vector<double> temperature_t;
      if (!dT_t.empty()) {
        temperature_t = initial_temperature_;
        for (std::size_t n = 0; n < temperature_t.size(); ++n) temperature_t[n] += dT_t[n];
      }
      const ElementStates states_t(model_, prepared_, k,
                                   temperature_t.empty() ? nullptr : &temperature_t);
      const OutputNeeds needs = output_needs(model_, k);
      const RecoveryInput input{
          ramp.reaction_dofs,   u, loads, &states_t, &kinematic_.rotations(), needs.energies,
          needs.thermal_strains};
      recover_increment(model_, prepared_, input, threads_, increment);
      averaging_.apply(threads_, increment);
      if (needs.error_estimate)
        estimate_stress_errors(model_, prepared_, states_t, threads_, increment);
      compute_section_forces(model_, prepared_, k, increment);
      contact::fill_contact_results(model_, constraints_, state_, increment);
      increment.penetrations =
          penetration_results(model_, ramp.fluid_layout, state_, fluid_pressures);
      check_equilibrium(prepared_, to_global(kinematic_, f_t), increment, constraints_, state_,
                        increment.contact_equilibrium);
    }
    u_previous_ = u;
    kinematic_.rotations().to_local(u_previous_);
    return increment;
  }

  // Phase: what a converged increment reports once (a leak of the fluid, a pair reaching full
  // slip).
  void report_increment(const std::string& where, const contact::IncrementOutcome& outcome,
                        const StepRamp& ramp, const std::vector<double>& fluid_pressures,
                        const IncrementResult& increment) {
    phases_.info(where + format(": converged in %.0f iterations, equilibrium residual %.2e",
                                outcome.iterations,
                                increment.contact_equilibrium.relative_residual));
    for (std::size_t z = 0; z < increment.penetrations.size(); ++z) {
      const PenetrationResult& pr = increment.penetrations[z];
      const std::string& label = ramp.fluid_layout.zones[z].label;
      if (!pr.leaked) continue;
      if (std::find(leaked_.begin(), leaked_.end(), label) != leaked_.end()) continue;
      leaked_.push_back(label);
      phases_.info(where + ": pressure penetration " + label +
                   format(": leak at fluid pressure %.6g (the penetrated zone, %.0f of ",
                          pr.pressure, pr.penetrated) +
                   format("%.0f nodes, reaches the LEAK set; the increment before held at %.6g)",
                          pr.nodes, fluid_before_[z]));
    }
    fluid_before_ = fluid_pressures;
    const std::vector<char> slipping_now = full_slip(model_, constraints_, state_);
    for (std::size_t p = 0; p < slipping_now.size(); ++p)
      if (slipping_now[p] && !slipping_[p])
        phases_.info(where + ": " + full_slip_report(model_, increment, static_cast<int>(p)));
    slipping_ = slipping_now;
  }

  const Model& model_;
  const ElementRegistry& registry_;
  const PhaseRecorder& phases_;
  AnalysisReport* report_;
  const int threads_;
  ContactModel checked_;
  const PreparedModel& prepared_;
  const ModelConstraints& kinematic_;  // *TRANSFORM and *EQUATION
  const std::vector<contact::ContactConstraint>& constraints_;
  const StressAveraging averaging_;
  StiffnessMatrix K_;
  const std::vector<double> initial_temperature_;
  std::vector<std::vector<double>> step_temperature_;  // per step: absolute, empty if unchanged
  std::optional<ElementStates> stiffness_states_;      // the material state K holds
  const SolverContext context_;
  const std::optional<RankShare> share_;  // a distributed run: this rank's rows and elements
  const ContactSolveKind contact_solve_;
  const ContactOperator B_;
  const std::vector<char> touches_contact_;
  const std::vector<StepPenetration> penetration_;
  ContactFactor factor_;
  // Carried from increment to increment and step to step.
  Results results_;
  contact::ContactState state_;
  std::vector<std::string> leaked_;  // zones ("SLAVE/MASTER") whose leak has been reported
  std::vector<char> slipping_;       // per pair: full slip at the last increment
  StepLoads previous_;               // the loads at the end of the last step
  std::vector<double> u_previous_;   // nodal components
  double total_time_ = 0.0;
  // Within a step.
  std::vector<double> fluid_before_;  // per zone: the fluid pressure of the last increment
  std::string sliding_;  // the last loss of equilibrium found in the step (a larger trial)
};

}  // namespace

Results run_contact_analysis(const Model& model, const ElementRegistry& registry,
                             const SolveOptions& options, ProgressSink* progress,
                             AnalysisReport* report) {
  const AnalysisStart start(options, progress, report);
  ContactModel checked = check_contact_model(model, registry, options, start.phases());
  return ContactAnalysis(model, registry, options, start, report, std::move(checked)).run();
}

}  // namespace styk::solver_detail
