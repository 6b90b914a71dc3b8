// Same-process comparison of the two ways to compute the contact compliance S = B K^-1 B^T
// (docs/contact.md, "The linear algebra"): full dense-block substitutions (cholmod_solve with 64
// right-hand sides, the path kept for *TRANSFORM / *EQUATION) against the restricted sparse
// substitutions (LinearSolver::solve_sparse_columns) with 1 and 2 threads. The runs alternate,
// so a machine shared with other work loads them alike; prints the times and max |S_a - S_b|.
#include "compliance_ab.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "assembly.hpp"
#include "contact_operator.hpp"
#include "linear_solver.hpp"
#include "model_constraints.hpp"
#include "phase_recorder.hpp"
#include "prepared_model.hpp"
#include "stiffness_matrix.hpp"
#include "styk/contact/constraints.hpp"

namespace styk::bench {
namespace {

using namespace solver_detail;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The old path: every force-carrying column of B^T as a dense right-hand side.
Eigen::MatrixXd dense_block_compliance(const ContactOperator& B, LinearSolver& solver, int dofs) {
  std::vector<int> columns;
  for (int i = 0; i < B.rows(); ++i)
    if (B.row_used(i)) columns.push_back(i);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(B.rows(), B.rows());
  const auto n = static_cast<std::size_t>(dofs);
  constexpr int kBlock = 64;
  for (std::size_t first = 0; first < columns.size(); first += kBlock) {
    const int count = static_cast<int>(std::min<std::size_t>(kBlock, columns.size() - first));
    std::vector<double> F(n * count, 0.0);
    for (int j = 0; j < count; ++j) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(B.rows());
      e[columns[first + j]] = 1.0;
      std::vector<double> f(n, 0.0);
      B.add_transpose(e, 1.0, f);
      std::copy(f.begin(), f.end(), F.begin() + j * n);
    }
    const std::vector<double> X = solver.solve_homogeneous(F, count);
    for (int j = 0; j < count; ++j) {
      const Eigen::Map<const Eigen::VectorXd> x(X.data() + j * n, dofs);
      const Eigen::VectorXd Bx = B.apply(Eigen::Ref<const Eigen::VectorXd>(x));
      for (int i : columns) S(i, columns[first + j]) = Bx[i];
    }
  }
  return 0.5 * (S + S.transpose());
}

}  // namespace

void compliance_ab(const char* name, const Model& model, const ElementRegistry& registry) {
  const PreparedModel prepared = prepare_model(model, registry);
  const std::vector<contact::ContactConstraint> constraints =
      contact::build_contact_constraints(model, registry, nullptr);
  const ContactOperator B(prepared, constraints);
  const int dofs = prepared.active_dofs();
  // The supports of every step, plus the slave and master nodes of the first constraint held,
  // which fixes the translations of a body held only by contact (enough to factorise; the
  // timing does not depend on which dofs are held).
  std::vector<int> held;
  auto hold = [&](int node, int dof) {
    if (prepared.active_of_node[node] >= 0) held.push_back(3 * prepared.active_of_node[node] + dof);
  };
  for (const Boundary& b : model.boundaries) hold(b.node, b.dof - 1);
  for (const Step& step : model.steps)
    for (const Boundary& b : step.boundaries) hold(b.node, b.dof - 1);
  for (int d = 0; d < 3; ++d) {
    hold(constraints.front().slave, d);
    for (const contact::MasterTerm& t : constraints.front().master) hold(t.node, d);
  }
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  int used = 0;
  for (int i = 0; i < B.rows(); ++i) used += B.row_used(i);

  const PhaseRecorder phases(nullptr, nullptr);
  const ModelConstraints none;
  double dense_s = 0.0, sparse1_s = 0.0, sparse2_s = 0.0, worst = 0.0, largest = 0.0;
  constexpr int kRounds = 2;
  for (int round = 0; round < kRounds; ++round) {
    for (int threads : {1, 2}) {
      const SolverContext context{model, prepared, phases, threads};
      StiffnessMatrix K(model, prepared, threads);
      const ElementStates states(model, prepared, 0, nullptr);  // step 1's materials
      assemble_stiffness(model, prepared, states, K, threads);
      const std::unique_ptr<LinearSolver> solver = make_cholmod_solver(context);
      solver->prepare(K, partition_dofs(dofs, held));
      Eigen::MatrixXd reference;
      if (threads == 1) {
        const auto start = std::chrono::steady_clock::now();
        reference = dense_block_compliance(B, *solver, dofs);
        dense_s += seconds_since(start);
      }
      const auto start = std::chrono::steady_clock::now();
      const Eigen::MatrixXd S = B.compliance(*solver, dofs, none);
      (threads == 1 ? sparse1_s : sparse2_s) += seconds_since(start);
      if (threads == 1) {
        worst = std::max(worst, (S - reference).cwiseAbs().maxCoeff());
        largest = std::max(largest, reference.cwiseAbs().maxCoeff());
      }
    }
  }
  std::printf("%s,%d,%d,%.3f,%.3f,%.3f,%.2f,%.2f,%.1e\n", name, dofs, used, dense_s / kRounds,
              sparse1_s / kRounds, sparse2_s / kRounds, dense_s / sparse1_s, dense_s / sparse2_s,
              worst / largest);
  std::fflush(stdout);
}

}  // namespace styk::bench
