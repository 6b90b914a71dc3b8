// Direct solver: CHOLMOD supernodal Cholesky of K_ff (upper triangle, free dofs only), ordered by
// METIS nested dissection on the node graph (AMD if METIS fails). The factor is kept, so steps
// that only change loads or prescribed values cost one forward/back substitution.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <Eigen/Core>

#include "blas_kernels.hpp"
#include "cholmod_handles.hpp"
#include "extended_refinement.hpp"
#include "linear_solver.hpp"
#include "node_ordering.hpp"
#include "parallel.hpp"
#include "restricted_substitution.hpp"
#include "styk/core/machine_memory.hpp"

namespace styk::solver_detail {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[320];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

class CholmodSolver final : public LinearSolver {
 public:
  explicit CholmodSolver(const SolverContext& context)
      : context_(context), common_(std::make_unique<CholmodCommon>()) {
    cholmod_common* c = common_->get();
    c->print = 0;  // our messages, not CHOLMOD's
    c->supernodal = CHOLMOD_SUPERNODAL;
    c->quick_return_if_not_posdef = 1;
  }

  std::string description() const override { return description_; }
  double factor_nonzeros() const override { return common_->get()->lnz; }

  void prepare(StiffnessMatrix& K, const DofPartition& partition) override {
    partition_ = partition;
    coupling_ = extract_coupling(K, partition);
    if (partition.free_count() == 0) return;  // everything prescribed: nothing to factorise
    {
      const PhaseRecorder::Scope phase(context_.phases, "order");
      A_ = upper_free_matrix(K, partition);
      // K's values are no longer needed (A_ and coupling_ hold what the solves use): free them
      // before the factor takes its memory.
      K.release_values();
      analyse(K.graph(), partition);
    }
    const PhaseRecorder::Scope phase(context_.phases, "factorise");
    matrix_norm_ = -1.0;
    factorise();
  }

  std::vector<double> solve(const std::vector<double>& f,
                            const std::vector<double>& prescribed_value) override {
    const PhaseRecorder::Scope phase(context_.phases, "solve");
    const DofPartition& partition = partition_;
    std::vector<double> u(f.size(), 0.0);
    for (int dof : partition.prescribed) u[dof] = prescribed_value[dof];
    if (partition.free_count() == 0) return u;
    const std::vector<double> rhs = free_rhs(f, partition, coupling_, prescribed_value);
    cholmod_common* c = common_->get();
    const auto n = static_cast<std::size_t>(partition.free_count());
    CholmodDense b(cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, c), CholmodDenseDeleter{c});
    if (!b) throw std::runtime_error("CHOLMOD: out of memory for the right-hand side");
    std::copy(rhs.begin(), rhs.end(), static_cast<double*>(b->x));
    CholmodDense x(cholmod_l_solve(CHOLMOD_A, L_.get(), b.get(), c), CholmodDenseDeleter{c});
    if (!x) throw std::runtime_error("CHOLMOD: the triangular solves failed");
    check_residual(b.get(), x.get());

    const double* xv = static_cast<const double*>(x->x);
    std::vector<double> free_u(xv, xv + n);
    if (context_.refine_solutions) refine(f, prescribed_value, free_u);
    for (std::size_t i = 0; i < n; ++i) u[partition.free_dofs[i]] = free_u[i];
    return u;
  }

  std::vector<double> solve_homogeneous(const std::vector<double>& F, int columns) override {
    const DofPartition& partition = partition_;
    std::vector<double> X(F.size(), 0.0);
    if (partition.free_count() == 0 || columns == 0) return X;
    const auto n = static_cast<std::size_t>(partition.free_count());
    const std::size_t rows = F.size() / static_cast<std::size_t>(columns);
    cholmod_common* c = common_->get();
    CholmodDense b(cholmod_l_allocate_dense(n, columns, n, CHOLMOD_REAL, c),
                   CholmodDenseDeleter{c});
    if (!b) throw std::runtime_error("CHOLMOD: out of memory for the right-hand sides");
    auto* bx = static_cast<double*>(b->x);
    for (int j = 0; j < columns; ++j)
      for (std::size_t i = 0; i < n; ++i) bx[j * n + i] = F[j * rows + partition.free_dofs[i]];
    CholmodDense x(cholmod_l_solve(CHOLMOD_A, L_.get(), b.get(), c), CholmodDenseDeleter{c});
    if (!x) throw std::runtime_error("CHOLMOD: the triangular solves failed");
    const auto* xv = static_cast<const double*>(x->x);
    for (int j = 0; j < columns; ++j)
      for (std::size_t i = 0; i < n; ++i) X[j * rows + partition.free_dofs[i]] = xv[j * n + i];
    return X;
  }

  void solve_sparse_columns(const std::vector<SparseColumn>& F, const std::vector<int>& rows,
                            int active_dofs, int block, const ColumnBlockSink& sink) override {
    if (partition_.free_count() == 0 || !L_ || !L_->is_super || F.empty()) {
      LinearSolver::solve_sparse_columns(F, rows, active_dofs, block, sink);
      return;
    }
    const RestrictedSubstitution substitution(*L_, partition_);
    const std::size_t nsuper = substitution.supernodes();
    // Back substitution: the paths from the wanted rows to the root.
    std::vector<char> back(nsuper, 0);
    std::vector<SuiteSparse_long> wanted(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) {
      wanted[r] = substitution.position(rows[r]);
      if (wanted[r] >= 0) substitution.mark_path(substitution.supernode(wanted[r]), back);
    }
    // Columns whose entries sit in the same subtree share most of their forward paths: order
    // them by their first permuted position (the supernodes are in postorder), then block.
    std::vector<SuiteSparse_long> first(F.size(), std::numeric_limits<SuiteSparse_long>::max());
    for (std::size_t j = 0; j < F.size(); ++j)
      for (int dof : F[j].dof) {
        const SuiteSparse_long p = substitution.position(dof);
        if (p >= 0) first[j] = std::min(first[j], p);
      }
    std::vector<int> order(F.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return first[a] < first[b]; });
    block = std::max(block, 1);
    const int blocks = (static_cast<int>(F.size()) + block - 1) / block;
    const auto n = static_cast<Eigen::Index>(partition_.free_count());
    const int threads = resolve_threads(context_.threads);
    struct Scratch {
      Eigen::MatrixXd X, E;
      std::vector<char> forward;
    };
    std::vector<Scratch> scratch(threads);
    // The workers call the BLAS on independent blocks: one BLAS thread each.
    const SingleThreadedBlas single_threaded_blas;
    parallel_for(blocks, threads, 1, [&](int begin, int end, int worker) {
      Scratch& w = scratch[worker];
      for (int b = begin; b < end; ++b) {
        const int from = b * block;
        const int count = std::min(block, static_cast<int>(F.size()) - from);
        std::vector<int> columns(order.begin() + from, order.begin() + from + count);
        w.X.setZero(n, count);
        w.forward.assign(nsuper, 0);
        for (int j = 0; j < count; ++j) {
          const SparseColumn& f = F[columns[j]];
          for (std::size_t p = 0; p < f.dof.size(); ++p) {
            const SuiteSparse_long at = substitution.position(f.dof[p]);
            if (at < 0) continue;
            w.X(at, j) += f.value[p];
            substitution.mark_path(substitution.supernode(at), w.forward);
          }
        }
        substitution.solve(w.X, w.forward, back, w.E);
        Eigen::MatrixXd values(rows.size(), count);
        for (std::size_t r = 0; r < rows.size(); ++r)
          if (wanted[r] >= 0)
            values.row(r) = w.X.row(wanted[r]);
          else
            values.row(r).setZero();
        sink(columns, values);
      }
    });
  }

 private:
  // Upper triangle of K_ff in CSC. For symmetric K, column j of the upper triangle is row j of K
  // restricted to columns <= j, so it comes straight out of K's CSR rows (already sorted).
  CholmodSparse upper_free_matrix(const StiffnessMatrix& K, const DofPartition& partition) {
    cholmod_common* c = common_->get();
    const int n = partition.free_count();
    std::vector<SuiteSparse_long> count(n + 1, 0);
    const int threads = context_.threads;
    parallel_for(n, threads, 4096, [&](int begin, int end, int) {
      for (int j = begin; j < end; ++j) {
        const int row = partition.free_dofs[j];
        SuiteSparse_long m = 0;
        for (int p = K.row_ptr()[row]; p < K.row_ptr()[row + 1]; ++p) {
          const int i = partition.free_of_dof[K.col()[p]];
          m += (i >= 0 && i <= j);
        }
        count[j + 1] = m;
      }
    });
    for (int j = 0; j < n; ++j) count[j + 1] += count[j];
    CholmodSparse A(cholmod_l_allocate_sparse(n, n, count[n], /*sorted=*/1, /*packed=*/1,
                                              /*stype=*/1, CHOLMOD_REAL, c),
                    CholmodSparseDeleter{c});
    if (!A) throw std::runtime_error("CHOLMOD: out of memory for the stiffness matrix");
    auto* Ap = static_cast<SuiteSparse_long*>(A->p);
    auto* Ai = static_cast<SuiteSparse_long*>(A->i);
    auto* Ax = static_cast<double*>(A->x);
    std::copy(count.begin(), count.end(), Ap);
    parallel_for(n, threads, 4096, [&](int begin, int end, int) {
      for (int j = begin; j < end; ++j) {
        const int row = partition.free_dofs[j];
        SuiteSparse_long at = Ap[j];
        for (int p = K.row_ptr()[row]; p < K.row_ptr()[row + 1]; ++p) {
          const int i = partition.free_of_dof[K.col()[p]];
          if (i >= 0 && i <= j) {
            Ai[at] = i;
            Ax[at++] = K.values()[p];
          }
        }
      }
    });
    return A;
  }

  void analyse(const NodeGraph& graph, const DofPartition& partition) {
    cholmod_common* c = common_->get();
    std::vector<std::int64_t> perm =
        metis_free_dof_ordering(graph, context_.prepared.dof_offset, partition);
    c->nmethods = 1;
    c->postorder = 1;
    cholmod_factor* L = nullptr;
    if (static_cast<int>(perm.size()) == partition.free_count()) {
      c->method[0].ordering = CHOLMOD_GIVEN;
      std::vector<SuiteSparse_long> given(perm.begin(), perm.end());
      L = cholmod_l_analyze_p(A_.get(), given.data(), nullptr, 0, c);
      description_ = "CHOLMOD supernodal Cholesky (METIS node-graph ordering)";
    } else {
      context_.phases.info("METIS ordering failed; CHOLMOD uses AMD instead");
      c->method[0].ordering = CHOLMOD_AMD;
      L = cholmod_l_analyze(A_.get(), c);
      description_ = "CHOLMOD supernodal Cholesky (AMD ordering)";
    }
    if (L == nullptr) throw std::runtime_error("CHOLMOD: the symbolic analysis ran out of memory");
    L_ = CholmodFactor(L, CholmodFactorDeleter{c});
    // Refuse a factor that cannot fit before trying (the supernodal factor is ~8 bytes/entry).
    const double factor_bytes = 8.0 * c->lnz;
    const bool given = context_.memory_limit_gb > 0.0;
    const double limit = given ? context_.memory_limit_gb * 1e9 : 0.8 * physical_memory_bytes();
    if (limit > 0.0 && factor_bytes > limit)
      throw FactorTooLarge(format(given ? "the Cholesky factor of this model needs %.3g GB, more "
                                          "than the memory limit of %.3g GB (--memory-limit); use "
                                          "the iterative solver (*STATIC, SOLVER=ITERATIVE)"
                                        : "the Cholesky factor of this model needs %.3g GB, more "
                                          "than the %.3g GB (80 %% of the memory) here; use the "
                                          "iterative solver (*STATIC, SOLVER=ITERATIVE)",
                                  factor_bytes / 1e9, limit / 1e9));
  }

  void factorise() {
    cholmod_common* c = common_->get();
    const auto start = std::chrono::steady_clock::now();
    cholmod_l_factorize(A_.get(), L_.get(), c);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (c->status == CHOLMOD_NOT_POSDEF) throw singular_at(static_cast<long>(L_->minor));
    if (c->status == CHOLMOD_OUT_OF_MEMORY)
      throw ResourceLimitError(
          "CHOLMOD ran out of memory in the factorisation; use the iterative solver (*STATIC, "
          "SOLVER=ITERATIVE)");
    if (c->status < CHOLMOD_OK)
      throw std::runtime_error("CHOLMOD factorisation failed with status " +
                               std::to_string(c->status));
    const long tiny_pivot = first_tiny_pivot();
    if (tiny_pivot >= 0) throw singular_at(tiny_pivot);
    context_.phases.info(format("CHOLMOD: %.0f dofs, nnz(L) = %.1f M, %.1f GFLOP/s",
                                static_cast<double>(partition_.free_count()), c->lnz / 1e6,
                                seconds > 0.0 ? c->fl / seconds / 1e9 : 0.0));
  }

  // The message for a zero or negative pivot in column `column` of the permuted matrix.
  InputError singular_at(long column) const {
    const auto* perm = static_cast<const SuiteSparse_long*>(L_->Perm);
    const long free = perm != nullptr ? static_cast<long>(perm[column]) : column;
    const int dof = partition_.free_dofs[free];
    return InputError(SourceLoc{context_.model.source, 0},
                      "the stiffness matrix is singular at " +
                          describe_dof(context_.model, context_.prepared, dof) +
                          ": the model is a mechanism there or an element is degenerate");
  }

  // A mechanism rarely gives an exactly negative pivot: round-off leaves a tiny positive one,
  // and the solve would return huge, meaningless displacements along the mechanism. A pivot
  // L_kk^2 below kPivotRatio times the diagonal entry it started from means the column is
  // (numerically) a linear combination of the earlier ones. Returns the first such permuted
  // column, -1 if none.
  long first_tiny_pivot() const {
    constexpr double kPivotRatio = 1e-11;
    const cholmod_factor* L = L_.get();
    if (!L->is_super) return -1;
    const auto* perm = static_cast<const SuiteSparse_long*>(L->Perm);
    const auto* Ap = static_cast<const SuiteSparse_long*>(A_->p);
    const auto* Ai = static_cast<const SuiteSparse_long*>(A_->i);
    const auto* Ax = static_cast<const double*>(A_->x);
    const auto* super = static_cast<const SuiteSparse_long*>(L->super);
    const auto* pi = static_cast<const SuiteSparse_long*>(L->pi);
    const auto* px = static_cast<const SuiteSparse_long*>(L->px);
    const auto* Lx = static_cast<const double*>(L->x);
    for (std::size_t s = 0; s < L->nsuper; ++s) {
      const SuiteSparse_long first = super[s];
      const SuiteSparse_long columns = super[s + 1] - first;
      const SuiteSparse_long rows = pi[s + 1] - pi[s];
      for (SuiteSparse_long j = 0; j < columns; ++j) {
        const double pivot = Lx[px[s] + j * rows + j];
        // Diagonal of A in the original column: the last entry of the sorted upper column.
        const SuiteSparse_long column = perm[first + j];
        const SuiteSparse_long last = Ap[column + 1] - 1;
        const double diagonal = last >= Ap[column] && Ai[last] == column ? Ax[last] : 0.0;
        if (!(pivot * pivot > kPivotRatio * std::abs(diagonal))) return first + j;
      }
    }
    return -1;
  }

  // Refinement in extended precision (extended_refinement.hpp): the answer of the assembled
  // system, whichever factorisation (and, distributed, whichever number of ranks) found it.
  void refine(const std::vector<double>& f, const std::vector<double>& prescribed_value,
              std::vector<double>& x) {
    cholmod_common* c = common_->get();
    const auto n = static_cast<std::size_t>(partition_.free_count());
    const std::vector<long double> load = extended_free_load(f, prescribed_value);
    const ExtendedResidual residual = [&](const std::vector<double>& y, std::vector<double>& r) {
      r = extended_free_residual(load, y);
    };
    const Correction correct = [&](const std::vector<double>& r) {
      CholmodDense b(cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, c), CholmodDenseDeleter{c});
      if (!b) throw std::runtime_error("CHOLMOD: out of memory for the right-hand side");
      std::copy(r.begin(), r.end(), static_cast<double*>(b->x));
      CholmodDense d(cholmod_l_solve(CHOLMOD_A, L_.get(), b.get(), c), CholmodDenseDeleter{c});
      if (!d) throw std::runtime_error("CHOLMOD: the triangular solves failed");
      const double* dv = static_cast<const double*>(d->x);
      return std::vector<double>(dv, dv + n);
    };
    const RefinementOutcome outcome = refine_in_extended_precision(x, residual, correct);
    context_.phases.info("CHOLMOD: " + describe(outcome));
  }

  // f_f - K_fp u_p over the free dofs, in extended precision (the same for every correction).
  std::vector<long double> extended_free_load(const std::vector<double>& f,
                                              const std::vector<double>& prescribed_value) const {
    const DofPartition& partition = partition_;
    std::vector<long double> load(partition.free_count());
    for (int i = 0; i < partition.free_count(); ++i) load[i] = f[partition.free_dofs[i]];
    for (const CouplingEntry& entry : coupling_)
      load[entry.free_row] -= static_cast<long double>(entry.value) * prescribed_value[entry.dof];
    return load;
  }

  // load - K_ff x over the free dofs, in extended precision, rounded once. K_ff is the upper
  // triangle A_ (column j holds rows i <= j): entry (i, j) acts on both rows.
  std::vector<double> extended_free_residual(const std::vector<long double>& load,
                                             const std::vector<double>& x) const {
    const std::size_t n = x.size();
    std::vector<long double> r = load;
    const auto* Ap = static_cast<const SuiteSparse_long*>(A_->p);
    const auto* Ai = static_cast<const SuiteSparse_long*>(A_->i);
    const auto* Ax = static_cast<const double*>(A_->x);
    for (std::size_t j = 0; j < n; ++j)
      for (SuiteSparse_long p = Ap[j]; p < Ap[j + 1]; ++p) {
        const auto i = static_cast<std::size_t>(Ai[p]);
        const long double a = Ax[p];
        r[i] -= a * x[j];
        if (i != j) r[j] -= a * x[i];
      }
    return std::vector<double>(r.begin(), r.end());
  }

  // The solve is accepted when its normwise backward error
  //   eta = ||b - K_ff x||_inf / (||K_ff||_inf ||x||_inf + ||b||_inf)
  // is round-off small: x is then the exact solution of a system perturbed by eta relative to
  // K_ff and b, which is all a backward-stable Cholesky promises. The relative residual
  // ||r|| / ||b|| is not a fit test: it grows with the condition number, which thin shells
  // (membrane E t against bending E t^3) raise as (size / t)^2 without being singular.
  // Mechanisms are caught before, by the factor's pivots (first_tiny_pivot); a backward error
  // above kBackwardErrorLimit means the factor itself is garbage.
  void check_residual(cholmod_dense* b, cholmod_dense* x) {
    constexpr double kBackwardErrorLimit = 1e-10;
    cholmod_common* c = common_->get();
    CholmodDense r(cholmod_l_copy_dense(b, c), CholmodDenseDeleter{c});
    if (!r) throw std::runtime_error("CHOLMOD: out of memory for the residual");
    double one[2] = {1.0, 0.0};
    double minus_one[2] = {-1.0, 0.0};
    cholmod_l_sdmult(A_.get(), 0, one, minus_one, x, r.get(), c);
    const double residual = cholmod_l_norm_dense(r.get(), 0, c);
    if (!(matrix_norm_ >= 0.0)) matrix_norm_ = cholmod_l_norm_sparse(A_.get(), 0, c);
    const double scale =
        matrix_norm_ * cholmod_l_norm_dense(x, 0, c) + cholmod_l_norm_dense(b, 0, c);
    const double backward_error = scale > 0.0 ? residual / scale : 0.0;
    if (scale > 0.0 && !(residual <= kBackwardErrorLimit * scale))
      throw InputError(SourceLoc{context_.model.source, 0},
                       format("the stiffness matrix is nearly singular: the solution's backward "
                              "error ||K u - f|| / (||K|| ||u|| + ||f||) is %.2g (limit %.0g); "
                              "the model is close to a mechanism or has badly distorted elements",
                              backward_error, kBackwardErrorLimit));
  }

  SolverContext context_;
  std::unique_ptr<CholmodCommon> common_;  // declared first: destroyed after the objects below
  CholmodSparse A_{nullptr, CholmodSparseDeleter{nullptr}};
  CholmodFactor L_{nullptr, CholmodFactorDeleter{nullptr}};
  DofPartition partition_;
  std::vector<CouplingEntry> coupling_;
  std::string description_ = "CHOLMOD supernodal Cholesky";
  double matrix_norm_ = -1.0;  // ||K_ff||_inf, computed at the first solve after factorising
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver(const SolverContext& context) {
  return std::make_unique<CholmodSolver>(context);
}

}  // namespace styk::solver_detail
