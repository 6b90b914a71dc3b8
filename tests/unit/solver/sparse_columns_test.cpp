// LinearSolver::solve_sparse_columns: CHOLMOD's override restricts the forward substitution to the
// elimination-tree paths of each block's right-hand sides and the back substitution to the paths of
// the wanted rows (docs/contact.md, "The linear algebra"). It must give the wanted rows of the full
// solve K_ff^-1 F (solve_homogeneous) to round-off, whatever the blocking and the thread count,
// with prescribed rows of F ignored and prescribed wanted rows zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "assembly.hpp"
#include "cantilever_model.hpp"
#include "linear_solver.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"
#include "styk/elements/builtin.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

using solver_detail::LinearSolver;

TEST(CholmodSparseColumns, RestrictedSubstitutionsMatchTheFullSolve) {
  // C3D20 cantilever 12 x 3 x 3 (clamped at x = 0): 2044 nodes, a few hundred supernodes, so the
  // elimination-tree paths of a few dofs cover only part of the factor.
  ElementRegistry registry = test::builtin_registry();
  testkit::CantileverSpec spec;
  spec.nx = 12;
  spec.ny = 3;
  spec.nz = 3;
  const Model model = testkit::make_cantilever(spec, registry).model;
  const solver_detail::PreparedModel prepared = solver_detail::prepare_model(model, registry);
  std::vector<int> clamped;
  for (int n = 0; n < model.node_count(); ++n)
    if (std::abs(model.coords[n][0]) < 1e-12 && prepared.active_of_node[n] >= 0)
      for (int d = 0; d < 3; ++d) clamped.push_back(3 * prepared.active_of_node[n] + d);
  std::sort(clamped.begin(), clamped.end());
  const int dofs = prepared.active_dofs();

  // Right-hand sides shaped like contact rows: a few dofs of neighbouring nodes each, spread over
  // the model (one touches a clamped dof, which must be ignored); wanted: the dofs they touch
  // plus one clamped dof (must come back zero).
  std::vector<LinearSolver::SparseColumn> F;
  std::vector<int> wanted{clamped.front()};
  for (int c = 0; c < 40; ++c) {
    LinearSolver::SparseColumn column;
    const int node = (c * 997) % (dofs / 3 - 1);
    for (int k = 0; k < 4; ++k) {
      const int dof = 3 * (node + k / 3) + (c + k) % 3;
      if (dof >= dofs) continue;
      column.dof.push_back(dof);
      column.value.push_back(1.0 + 0.25 * k - 0.1 * c);
      wanted.push_back(dof);
    }
    F.push_back(column);
  }
  F[0].dof.push_back(clamped.back());
  F[0].value.push_back(5.0);
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());

  for (int threads : {1, 2}) {
    const solver_detail::PhaseRecorder phases(nullptr, nullptr);
    const solver_detail::SolverContext context{model, prepared, phases, threads};
    // prepare() releases K's values: one matrix per solver.
    solver_detail::StiffnessMatrix K(model, prepared, 1);
    const solver_detail::ElementStates states(model, prepared, 0, nullptr);  // step 1's materials
    solver_detail::assemble_stiffness(model, prepared, states, K, 1);
    const std::unique_ptr<LinearSolver> solver = solver_detail::make_cholmod_solver(context);
    solver->prepare(K, solver_detail::partition_dofs(dofs, clamped));

    // Reference: the full dense-block solve.
    std::vector<double> dense(static_cast<std::size_t>(dofs) * F.size(), 0.0);
    for (std::size_t j = 0; j < F.size(); ++j)
      for (std::size_t p = 0; p < F[j].dof.size(); ++p)
        if (!std::binary_search(clamped.begin(), clamped.end(), F[j].dof[p]))
          dense[j * dofs + F[j].dof[p]] += F[j].value[p];
    const std::vector<double> X = solver->solve_homogeneous(dense, static_cast<int>(F.size()));
    double scale = 0.0;
    for (double x : X) scale = std::max(scale, std::abs(x));
    ASSERT_GT(scale, 0.0);

    for (int block : {1, 7, 64}) {
      std::vector<int> seen(F.size(), 0);
      double worst = 0.0;
      solver->solve_sparse_columns(
          F, wanted, dofs, block,
          [&](const std::vector<int>& columns, const Eigen::MatrixXd& values) {
            EXPECT_LE(static_cast<int>(columns.size()), block);
            for (std::size_t j = 0; j < columns.size(); ++j) {
              ++seen[columns[j]];
              for (std::size_t r = 0; r < wanted.size(); ++r)
                worst = std::max(worst, std::abs(values(r, j) - X[columns[j] * dofs + wanted[r]]));
            }
          });
      for (int count : seen) EXPECT_EQ(count, 1) << "block " << block;
      // Same arithmetic minus exact zeros: round-off of the substitutions, 1e-12 relative.
      EXPECT_LE(worst, 1e-12 * scale) << "threads " << threads << ", block " << block;
    }
  }
}

}  // namespace
}  // namespace styk
