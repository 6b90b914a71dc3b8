#include "scalar_field_analysis.hpp"

#include <cmath>
#include <memory>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

#include "analysis_setup.hpp"
#include "assembly.hpp"
#include "extended_refinement.hpp"
#include "parallel.hpp"
#include "phase_recorder.hpp"
#include "scalar_element.hpp"
#include "scalar_field_model.hpp"
#include "scalar_linear_solve.hpp"

namespace styk::solver_detail {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;

// The conductance of the whole mesh (unknowns x unknowns), element matrices computed in parallel.
// The triplets are kept per chunk of elements and joined in element order, so setFromTriplets sums
// each entry's contributions in the same order whatever thread computed them: the matrix, and so
// the answer, is the same bit for bit on any number of threads.
SparseMatrix assemble_conductance(const Model& model, const ScalarFieldModel& prepared,
                                  int threads) {
  constexpr int kChunk = 64;
  std::vector<std::vector<Triplet>> per_chunk((model.element_count() + kChunk - 1) / kChunk);
  parallel_for(model.element_count(), threads, kChunk, [&](int begin, int end, int) {
    ElementGeometry g;
    Eigen::MatrixXd K;
    std::vector<Triplet>& out = per_chunk[begin / kChunk];
    for (int e = begin; e < end; ++e) {
      element_geometry_without_normals(model, e, g);
      scalar_conductance(*prepared.formulation[e], g, prepared.rule(e), prepared.conductivity[e],
                         K);
      const int* nodes = model.element_nodes(e);
      const int n = model.elements[e].node_count;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          out.emplace_back(prepared.unknown_of_node[nodes[i]], prepared.unknown_of_node[nodes[j]],
                           K(i, j));
    }
  });
  std::vector<Triplet> all;
  for (std::vector<Triplet>& part : per_chunk) {
    all.insert(all.end(), part.begin(), part.end());
    part = {};
  }
  SparseMatrix K(prepared.unknowns(), prepared.unknowns());
  K.setFromTriplets(all.begin(), all.end());
  return K;
}

// Nodal flows (per unknown) of one step: *CFLUX / *CECUR plus the consistent *DFLUX flows.
Eigen::VectorXd applied_flows(const Model& model, const ScalarFieldModel& prepared,
                              const ScalarStepConditions& conditions) {
  Eigen::VectorXd f =
      Eigen::Map<const Eigen::VectorXd>(conditions.nodal_flow.data(), prepared.unknowns());
  ElementGeometry g;
  Eigen::VectorXd fe;
  for (const FaceFlux& face : conditions.face_fluxes) {
    element_geometry_without_normals(model, face.element, g);
    scalar_face_flux(*prepared.formulation[face.element], g, face.face, face.flux, fe);
    const int* nodes = model.element_nodes(face.element);
    for (Eigen::Index k = 0; k < fe.size(); ++k) f(prepared.unknown_of_node[nodes[k]]) += fe(k);
  }
  return f;
}

// Solves K phi = f + r with phi prescribed on `conditions.prescribed` (r: reactions there).
class ScalarSolve final : public ScalarLinearSolve {
 public:
  ScalarSolve(const SparseMatrix& K, const std::map<int, double>& prescribed,
              const SourceLoc& where)
      : free_of_unknown_(K.rows(), -1) {
    std::vector<char> fixed(K.rows(), 0);
    for (const auto& entry : prescribed) fixed[entry.first] = 1;
    for (Eigen::Index u = 0; u < K.rows(); ++u)
      if (!fixed[u]) {
        free_of_unknown_[u] = static_cast<int>(free_.size());
        free_.push_back(static_cast<int>(u));
      }
    std::vector<Triplet> ff, fp;
    for (int j = 0; j < K.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
        const int i = free_of_unknown_[it.row()];
        if (i < 0) continue;
        const int fj = free_of_unknown_[j];
        if (fj >= 0)
          ff.emplace_back(i, fj, it.value());
        else
          fp.emplace_back(i, j, it.value());
      }
    const auto n = static_cast<Eigen::Index>(free_.size());
    Kff_.resize(n, n);
    Kff_.setFromTriplets(ff.begin(), ff.end());
    Kfp_.resize(n, K.cols());
    Kfp_.setFromTriplets(fp.begin(), fp.end());
    if (n == 0) return;
    factor_ = std::make_unique<Eigen::CholmodSupernodalLLT<SparseMatrix>>();
    factor_->compute(Kff_);
    if (factor_->info() != Eigen::Success)
      throw InputError(where,
                       "the conductance matrix is not positive definite: an element is "
                       "degenerate or a conductivity is not positive");
  }

  int free_count() const override { return static_cast<int>(free_.size()); }
  bool same_partition(const std::map<int, double>& prescribed) const override {
    if (prescribed.size() + free_.size() != free_of_unknown_.size()) return false;
    for (const auto& entry : prescribed)
      if (free_of_unknown_[entry.first] >= 0) return false;
    return true;
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& f, const std::map<int, double>& prescribed,
                        const SourceLoc& where) override {
    Eigen::VectorXd phi = Eigen::VectorXd::Zero(f.size());
    for (const auto& [u, value] : prescribed) phi(u) = value;
    if (free_.empty()) return phi;
    Eigen::VectorXd rhs(free_.size());
    for (std::size_t i = 0; i < free_.size(); ++i) rhs(i) = f(free_[i]);
    rhs -= Kfp_ * phi;
    const Eigen::VectorXd first = factor_->solve(rhs);
    const double scale = rhs.norm();
    if (factor_->info() != Eigen::Success || !first.allFinite() ||
        (scale > 0.0 && !((Kff_ * first - rhs).norm() <= 1e-8 * scale)))
      throw InputError(where,
                       "the conductance matrix is nearly singular: badly distorted "
                       "elements or conductivities of very different magnitudes");
    std::vector<double> x(first.data(), first.data() + first.size());
    refine(f, phi, x);
    for (std::size_t i = 0; i < free_.size(); ++i) phi(free_[i]) = x[i];
    return phi;
  }

  std::string description() const override {
    return "CHOLMOD supernodal Cholesky (Eigen, AMD/METIS ordering)";
  }

 private:
  // Refinement in extended precision (extended_refinement.hpp), as the mechanical solves: the
  // answer of the assembled system, serial or distributed. `phi` holds the prescribed values.
  void refine(const Eigen::VectorXd& f, const Eigen::VectorXd& phi, std::vector<double>& x) const {
    // f_f - K_fp phi_p, the same for every correction.
    std::vector<long double> load(free_.size());
    for (std::size_t i = 0; i < free_.size(); ++i) load[i] = f(free_[i]);
    for (int j = 0; j < Kfp_.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(Kfp_, j); it; ++it)
        load[it.row()] -= static_cast<long double>(it.value()) * phi(j);
    const ExtendedResidual residual = [&](const std::vector<double>& y, std::vector<double>& r) {
      std::vector<long double> sum = load;
      for (int j = 0; j < Kff_.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(Kff_, j); it; ++it)
          sum[it.row()] -= static_cast<long double>(it.value()) * y[j];
      r.assign(sum.begin(), sum.end());
    };
    const Correction correct = [&](const std::vector<double>& r) {
      const Eigen::VectorXd d =
          factor_->solve(Eigen::Map<const Eigen::VectorXd>(r.data(), r.size()));
      return std::vector<double>(d.data(), d.data() + d.size());
    };
    refine_in_extended_precision(x, residual, correct);
  }

  std::vector<int> free_of_unknown_;
  std::vector<int> free_;
  SparseMatrix Kff_, Kfp_;
  std::unique_ptr<Eigen::CholmodSupernodalLLT<SparseMatrix>> factor_;
};

// Gradients and fluxes at the integration points, fluxes extrapolated to the element nodes and
// averaged over the elements at each node (method I of SPEC §5).
void recover_fluxes(const Model& model, const ScalarFieldModel& prepared,
                    const Eigen::VectorXd& phi, int threads, ScalarFieldResult& out) {
  const std::size_t points = static_cast<std::size_t>(prepared.ip_offset.back());
  out.gradient.assign(points, Vec3{});
  out.flux.assign(points, Vec3{});
  std::vector<Vec3> element_node_flux(model.connectivity.size(), Vec3{});
  parallel_for(model.element_count(), threads, 64, [&](int begin, int end, int) {
    ElementGeometry g;
    Eigen::MatrixXd gradients;
    for (int e = begin; e < end; ++e) {
      element_geometry_without_normals(model, e, g);
      const int* nodes = model.element_nodes(e);
      const int n = model.elements[e].node_count;
      Eigen::VectorXd phi_e(n);
      for (int k = 0; k < n; ++k) phi_e(k) = phi(prepared.unknown_of_node[nodes[k]]);
      scalar_gradients(*prepared.formulation[e], g, prepared.rule(e), phi_e, gradients);
      const Eigen::MatrixXd flux = -(gradients * prepared.conductivity[e].asDiagonal());
      for (Eigen::Index p = 0; p < gradients.rows(); ++p)
        for (int d = 0; d < 3; ++d) {
          out.gradient[prepared.ip_offset[e] + p][d] = gradients(p, d);
          out.flux[prepared.ip_offset[e] + p][d] = flux(p, d);
        }
      const Eigen::MatrixXd at_nodes =
          prepared.extrapolations[prepared.rule_of_element[e]].to_nodes * flux;
      for (int k = 0; k < n; ++k)
        for (int d = 0; d < 3; ++d)
          element_node_flux[model.elements[e].first_node + k][d] = at_nodes(k, d);
    }
  });
  out.flux_nodal.assign(model.node_count(), Vec3{});
  std::vector<int> count(model.node_count(), 0);
  for (std::size_t c = 0; c < model.connectivity.size(); ++c) {
    const int node = model.connectivity[c];
    ++count[node];
    for (int d = 0; d < 3; ++d) out.flux_nodal[node][d] += element_node_flux[c][d];
  }
  for (int n = 0; n < model.node_count(); ++n)
    if (count[n] > 0)
      for (int d = 0; d < 3; ++d) out.flux_nodal[n][d] /= count[n];
}

}  // namespace

Results run_scalar_field_analysis(const Model& model, const ElementRegistry& registry,
                                  const SolveOptions& options, ProgressSink* progress,
                                  AnalysisReport* report) {
  const AnalysisStart start(options, progress, report);
  const PhaseRecorder& phases = start.phases();
  const int threads = start.threads();
  if (options.force == LinearSolverKind::Iterative)
    throw InputError(SourceLoc{model.source, 0},
                     "the iterative solver serves mechanical steps; steady heat and electric "
                     "potential are solved with CHOLMOD (drop --solver iterative)");

  ScalarFieldModel prepared;
  std::vector<ScalarStepConditions> conditions;
  {
    const PhaseRecorder::Scope phase(phases, "check");
    prepared = prepare_scalar_field_model(model, registry);
    conditions = accumulate_scalar_conditions(model, prepared);
  }
  SparseMatrix K;
  {
    const PhaseRecorder::Scope phase(phases, "assemble");
    K = assemble_conductance(model, prepared, threads);
    phases.info("conductance: " + std::to_string(prepared.unknowns()) + " unknowns, " +
                std::to_string(K.nonZeros()) + " nonzeros");
  }

  Results results;
  std::unique_ptr<ScalarLinearSolve> solver;
  double total_time = 0.0;
  for (std::size_t s = 0; s < model.steps.size(); ++s) {
    const Step& step = model.steps[s];
    const ScalarStepConditions& c = conditions[s];
    if (!solver || !solver->same_partition(c.prescribed)) {
      const PhaseRecorder::Scope phase(phases, "factorise");
      check_every_part_prescribed(model, prepared, c, step);
      solver.reset();
      if (options.distributed)
        solver = make_distributed_scalar_solve(K, c.prescribed, step.procedure.where,
                                               join_mpi_world(), phases);
      else
        solver = std::make_unique<ScalarSolve>(K, c.prescribed, step.procedure.where);
      if (report != nullptr && report->linear_solver.empty()) {
        report->linear_solver = solver->description();
        report->dofs = solver->free_count();
      }
    }
    Eigen::VectorXd f, phi;
    {
      const PhaseRecorder::Scope phase(phases, "solve");
      f = applied_flows(model, prepared, c);
      phi = solver->solve(f, c.prescribed, step.procedure.where);
    }

    IncrementResult increment;
    increment.step = static_cast<int>(s) + 1;
    increment.increment = 1;
    increment.step_time = step.procedure.total_time;
    total_time += step.procedure.total_time;
    increment.total_time = total_time;
    increment.ip_offset = prepared.ip_offset;
    {
      const PhaseRecorder::Scope phase(phases, "recover");
      ScalarFieldResult& out = increment.scalar;
      out.kind = prepared.field;
      out.value.assign(model.node_count(), 0.0);
      out.reaction.assign(model.node_count(), 0.0);
      for (int u = 0; u < prepared.unknowns(); ++u) out.value[prepared.node_of_unknown[u]] = phi(u);
      // Reaction flow: what the prescribed value draws, K phi - f, at the prescribed nodes.
      const Eigen::VectorXd r = K * phi - f;
      for (const auto& entry : c.prescribed)
        out.reaction[prepared.node_of_unknown[entry.first]] = r(entry.first);
      recover_fluxes(model, prepared, phi, threads, out);
    }
    results.increments.push_back(std::move(increment));
  }
  return results;
}

}  // namespace styk::solver_detail
