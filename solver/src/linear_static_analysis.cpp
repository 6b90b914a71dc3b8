// The linear static step driver (linear_static_analysis.hpp): check -> pattern -> assemble (with
// *TRANSFORM rotations and *EQUATION elimination applied to K) -> (per step) rigid-body check,
// order/factorise when the set of prescribed dofs changes, solve (mechanical and thermal loads),
// recover.
#include "linear_static_analysis.hpp"

#include <memory>
#include <optional>

#include "analysis_setup.hpp"
#include "assembly.hpp"
#include "body_loads.hpp"
#include "distributed_solver.hpp"
#include "element_states.hpp"
#include "linear_solver.hpp"
#include "mechanism_check.hpp"
#include "model_constraints.hpp"
#include "model_warnings.hpp"
#include "output_quantities.hpp"
#include "parallel.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "recovery.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"
#include "stress_averaging.hpp"
#include "thermal_load.hpp"

namespace styk::solver_detail {
namespace {

#ifdef STYK_HAVE_PETSC
constexpr bool kHaveIterativeSolver = true;
#else
constexpr bool kHaveIterativeSolver = false;
#endif

// Automatic choice: CHOLMOD below this many free dofs, CG + GAMG (tolerance 1e-7) from it on.
// Measured on the C3D20 cantilever of PERFORMANCE.md, 2 cores, one batch (wall / peak RSS):
//   51 408 dofs:  CHOLMOD  2.0 s / 0.55 GB   GAMG  5.3 s / 0.19 GB (59 its)
//   195 000 dofs: CHOLMOD 19.0 s / 2.79 GB   GAMG 20.7 s / 0.61 GB (55 its)
// CHOLMOD time grows ~ n^1.8 (factorisation flops), GAMG ~ n^1.0; the times cross at ~170k dofs
// and GAMG needs 3-5x less memory, so the switch sits a little below the crossing.
constexpr long long kIterativeFromDofs = 150000;

// *TRANSFORM and *EQUATION make the system the direct solver's: GAMG's rigid-body near-null
// space is built for global dofs without eliminated ones.
std::string constraint_keyword(const Model& model) {
  if (!model.cyclic_symmetries.empty()) return "*TIE, CYCLIC SYMMETRY";
  return model.equations.empty() ? "*TRANSFORM" : "*EQUATION";
}

LinearSolverKind choose_solver(const SolveOptions& options, const Step& step, long long free_dofs,
                               const Model& model, bool constrained, bool rotations) {
  const bool forced = options.force != LinearSolverKind::Automatic;
  const LinearSolverKind requested = forced ? options.force : step.procedure.solver;
  if (requested == LinearSolverKind::Iterative && constrained)
    throw InputError(forced ? SourceLoc{model.source, 0} : step.procedure.where,
                     "the iterative solver does not support " + constraint_keyword(model) +
                         " (local systems and equations are eliminated for the direct solver "
                         "only); use --solver cholmod or *STATIC, SOLVER=CHOLMOD");
  // GAMG's near-null space (PETSc's rigid-body modes) and its node blocks assume 3 displacement
  // dofs per node.
  if (requested == LinearSolverKind::Iterative && rotations)
    throw InputError(forced ? SourceLoc{model.source, 0} : step.procedure.where,
                     "the iterative solver does not support rotational dofs (beam elements: its "
                     "multigrid assumes 3 displacements per node); use --solver cholmod or "
                     "*STATIC, SOLVER=CHOLMOD");
  if (requested == LinearSolverKind::Iterative && !kHaveIterativeSolver)
    throw InputError(forced ? SourceLoc{} : step.procedure.where,
                     "the iterative solver is not available: this build has no PETSc "
                     "(configure with STYK_PETSC=ON)");
  if (requested != LinearSolverKind::Automatic) return requested;
  return kHaveIterativeSolver && !constrained && !rotations && free_dofs >= kIterativeFromDofs
             ? LinearSolverKind::Iterative
             : LinearSolverKind::Cholmod;
}

std::unique_ptr<LinearSolver> make_solver(LinearSolverKind kind, const SolverContext& context,
                                          const SolveOptions& options, const RankShare* share) {
  if (share != nullptr)
    return make_distributed_solver(context, share->rows, kind != LinearSolverKind::Iterative,
                                   options.iterative_tolerance);
  if (kind == LinearSolverKind::Iterative)
    return make_gamg_solver(context, options.iterative_tolerance);
  return make_cholmod_solver(context);
}

}  // namespace

Results run_linear_static_analysis(const Model& model, const ElementRegistry& registry,
                                   const SolveOptions& options, ProgressSink* progress,
                                   AnalysisReport* report) {
  const AnalysisStart start(options, progress, report);
  const PhaseRecorder& phases = start.phases();
  const int threads = start.threads();

  MechanicalModel mechanical;
  std::vector<std::vector<double>> temperatures;
  {
    const PhaseRecorder::Scope phase(phases, "check");
    mechanical = prepare_mechanical_model(model, registry, phases);
    temperatures = step_temperatures(model);
  }
  const PreparedModel& prepared = mechanical.prepared;
  const std::vector<StepConditions>& conditions = mechanical.conditions;
  const ModelConstraints& constraints = mechanical.kinematic;

  // Extrapolation operators per element type, built once for every step (SPEC §5 averaging).
  const StressAveraging averaging(model, prepared.formulation, prepared.rule_kind);

  std::unique_ptr<StiffnessMatrix> K;
  {
    const PhaseRecorder::Scope phase(phases, "pattern");
    K = std::make_unique<StiffnessMatrix>(model, prepared, threads,
                                          constraints.extra_node_couplings(model, prepared));
    phases.info("pattern: " + std::to_string(prepared.active_dofs()) + " dofs, " +
                std::to_string(K->nonzeros()) + " nonzeros, " +
                std::to_string(K->colouring().colours()) + " element colours");
  }
  // A distributed run: this rank's rows and elements (every rank holds the whole model).
  std::optional<RankShare> share;
  if (options.distributed) {
    const PhaseRecorder::Scope phase(phases, "partition");
    share = share_of_rank(model, prepared, K->graph(), join_mpi_world(),
                          constraints.equations().dependent_dofs());
    phases.info("partition: " + std::to_string(share->rows.size) + " ranks, " +
                std::to_string(share->cut_node_pairs) + " node pairs couple two ranks");
  }
  const std::vector<char>* owned_elements = share ? &share->assembles_element : nullptr;
  // The elements' material state of step k (materials, temperatures, initial stresses).
  auto states_of = [&](std::size_t k) {
    return ElementStates(model, prepared, k, temperatures[k].empty() ? nullptr : &temperatures[k]);
  };
  // "Pristine" K is the assembled stiffness in the nodal systems, equations eliminated, of the
  // material state `stiffness_states`.
  std::optional<ElementStates> stiffness_states;
  stiffness_states.emplace(states_of(0));
  auto assemble = [&] {
    const PhaseRecorder::Scope phase(phases, "assemble");
    assemble_stiffness(model, prepared, *stiffness_states, *K, threads, owned_elements);
    constraints.apply(*K);
  };
  assemble();

  const SolverContext context{model, prepared, phases, threads, options.memory_limit_gb};
  std::unique_ptr<LinearSolver> solver;
  LinearSolverKind solver_kind = LinearSolverKind::Automatic;
  std::vector<int> solver_prescribed;
  auto set_up_solver = [&](LinearSolverKind kind, const std::vector<int>& prescribed) {
    solver.reset();  // drops any view of K's arrays before K is reassembled
    if (!K->pristine()) assemble();
    solver = make_solver(kind, context, options, share ? &*share : nullptr);
    solver->prepare(*K, partition_dofs(prepared.active_dofs(), prescribed));
    solver_kind = kind;
    solver_prescribed = prescribed;
  };

  Results results;
  double total_time = 0.0;
  std::vector<double> w_previous(prepared.active_dofs(), 0.0);  // nodal, for *BOUNDARY, FIXED
  for (std::size_t k = 0; k < model.steps.size(); ++k) {
    const Step& step = model.steps[k];
    // Prescribed dofs are nodal (local where a *TRANSFORM applies); `known` adds the dofs that
    // *EQUATIONs eliminate, which the linear solver treats like prescribed ones.
    const std::vector<int> prescribed = prescribed_dofs(conditions[k]);
    const std::vector<int> known = constraints.known_dofs(model, prepared, prescribed);
    const long long free_dofs = prepared.active_dofs() - static_cast<long long>(known.size());
    const LinearSolverKind kind = choose_solver(options, step, free_dofs, model,
                                                !constraints.empty(), prepared.has_rotations());

    // A stiffness of its own when the step changes materials (*CHANGE SOLID SECTION) or the
    // temperatures of temperature-dependent elasticity.
    const ElementStates states = states_of(k);
    const bool new_stiffness = stiffness_states->stiffness_differs(states);
    if (new_stiffness) {
      solver.reset();  // drops any view of K's arrays before K is reassembled
      stiffness_states.emplace(states);
      assemble();
    }
    // A new factorisation only when the stiffness, the prescribed set (or the solver) changes;
    // otherwise the step costs a right-hand side and a solve.
    if (!solver || new_stiffness || kind != solver_kind || known != solver_prescribed) {
      {
        const PhaseRecorder::Scope phase(phases, "check");
        check_rigid_body_modes(model, prepared, K->graph(),
                               constraints.restraints(model, prepared, prescribed));
      }
      try {
        set_up_solver(kind, known);
      } catch (const FactorTooLarge& too_large) {
        const bool automatic = options.force == LinearSolverKind::Automatic &&
                               step.procedure.solver == LinearSolverKind::Automatic;
        if (!automatic || share || !kHaveIterativeSolver || !constraints.empty() ||
            prepared.has_rotations())
          throw;
        phases.info(std::string(too_large.what()) + "; switching to the iterative solver");
        set_up_solver(LinearSolverKind::Iterative, known);
      }
      if (report != nullptr && report->linear_solver.empty()) {
        report->linear_solver = solver->description();
        report->dofs = free_dofs;
      }
    }

    std::vector<double> thermal;
    if (!temperatures[k].empty() || !model.initial_stresses.empty()) {
      const PhaseRecorder::Scope phase(phases, "assemble");
      thermal = assemble_eigenstrain_load(model, prepared, states, threads);
    }
    // f: the external (mechanical) forces, which reactions are measured against, body forces
    // included; the eigenstrain load (thermal strain, initial stress) joins only the right-hand
    // side (internal forces include it).
    const std::vector<double> f =
        constraints.plus_global(constraints.nodal_forces(model, prepared, conditions[k]),
                                assemble_body_loads(model, prepared, states, conditions[k]));
    std::vector<double> prescribed_value(prepared.active_dofs(), 0.0);
    for (const DofValue& p : conditions[k].prescribed) prescribed_value[p.dof] = p.value;
    for (int dof : conditions[k].fixed) prescribed_value[dof] = w_previous[dof];
    std::vector<double> u =
        solver->solve(constraints.reduced_forces(constraints.plus_global(f, std::move(thermal))),
                      prescribed_value);
    w_previous = u;  // nodal: the values *BOUNDARY, FIXED holds in a later step
    constraints.to_global_displacements(u);
    if (report != nullptr) report->iterations += solver->iterations();

    IncrementResult increment;
    increment.step = static_cast<int>(k) + 1;
    increment.increment = 1;
    increment.step_time = step.procedure.total_time;
    total_time += step.procedure.total_time;
    increment.total_time = total_time;
    {
      const PhaseRecorder::Scope phase(phases, "recover");
      const std::vector<int> reaction_dofs = constraints.reaction_dofs(prescribed);
      const OutputNeeds needs = output_needs(model, k);
      const RecoveryInput input{
          reaction_dofs,        u, f, &states, &constraints.rotations(), needs.energies,
          needs.thermal_strains};
      recover_increment(model, prepared, input, threads, increment);
      averaging.apply(threads, increment);
      if (needs.error_estimate) estimate_stress_errors(model, prepared, states, threads, increment);
      compute_section_forces(model, prepared, k, increment);
    }
    results.increments.push_back(std::move(increment));
  }
  return results;
}

}  // namespace styk::solver_detail
