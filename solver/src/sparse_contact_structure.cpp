#include "sparse_contact_structure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "augmented_lu.hpp"

namespace styk::solver_detail {
namespace {

// How many constraints' exact diagonal blocks calibrate the estimate (one blocked solve).
constexpr int kCalibrationSample = 24;

}  // namespace

SparseContactStructure::SparseContactStructure(const StiffnessMatrix& K,
                                               const DofPartition& partition,
                                               ContactOperator::ReducedRows rows, int active_dofs)
    : partition_(partition),
      rows_(std::move(rows)),
      active_dofs_(active_dofs),
      lu_(std::make_unique<AugmentedLu>()) {
  // K_ff over free indices (free_dofs are increasing, so the columns stay sorted).
  k_ptr_.push_back(0);
  for (int f = 0; f < partition_.free_count(); ++f) {
    const int dof = partition_.free_dofs[f];
    for (int p = K.row_ptr()[dof]; p < K.row_ptr()[dof + 1]; ++p) {
      const int c = partition_.free_of_dof[K.col()[p]];
      if (c < 0) continue;
      k_col_.push_back(c);
      k_value_.push_back(K.values()[p]);
    }
    k_ptr_.push_back(static_cast<long>(k_col_.size()));
  }
  free_rows_.resize(rows_.size());
  position_.assign(rows_.size(), -1);
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    for (const auto& [dof, v] : rows_[i])
      if (partition_.free_of_dof[dof] >= 0)
        free_rows_[i].emplace_back(partition_.free_of_dof[dof], v);
    if (!free_rows_[i].empty()) position_[i] = static_cast<int>(carried_++);
  }
  estimate_blocks();
}

void SparseContactStructure::attach(LinearSolver& solver) {
  solver_ = &solver;
  calibrate_blocks();
}

SparseContactStructure::~SparseContactStructure() = default;

// S_jj ~ B_j diag(K_ff)^-1 B_j^T: exact (K^-1)_dd >= 1 / K_dd, and the estimate has S's null
// structure (a row with no free dof is zero; rows dependent over the free dofs stay dependent).
void SparseContactStructure::estimate_blocks() {
  std::vector<double> diagonal(partition_.free_count(), 0.0);
  for (int f = 0; f < partition_.free_count(); ++f)
    for (long p = k_ptr_[f]; p < k_ptr_[f + 1]; ++p)
      if (k_col_[p] == f) diagonal[f] = k_value_[p];
  const std::size_t m = free_rows_.size() / 3;
  blocks_.assign(m, Eigen::Matrix3d::Zero());
  for (std::size_t j = 0; j < m; ++j)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double sum = 0.0;
        for (const auto& [fa, va] : free_rows_[3 * j + a])
          for (const auto& [fb, vb] : free_rows_[3 * j + b])
            if (fa == fb && diagonal[fa] > 0.0) sum += va * vb / diagonal[fa];
        blocks_[j](a, b) = sum;
      }
}

// The estimate is low by the factor that the rest of the structure adds to a node's own
// stiffness; that factor varies little over a contact face, so the median ratio of exact to
// estimated normal self-compliance over an evenly spread sample scales every block.
void SparseContactStructure::calibrate_blocks() {
  const int m = static_cast<int>(blocks_.size());
  std::vector<int> candidates;
  for (int j = 0; j < m; ++j)
    if (blocks_[j](0, 0) > 0.0) candidates.push_back(j);
  if (candidates.empty()) return;
  const int sample = std::min<int>(kCalibrationSample, static_cast<int>(candidates.size()));
  std::vector<LinearSolver::SparseColumn> F;
  std::vector<int> sampled, wanted;
  std::vector<int> local(active_dofs_, -1);
  for (int s = 0; s < sample; ++s) {
    const int j = candidates[static_cast<std::size_t>(s) * candidates.size() / sample];
    sampled.push_back(j);
    F.push_back(ContactOperator::sparse_column(rows_[3 * j], local, wanted));
  }
  std::vector<double> ratio(sample, 0.0);
  solver_->solve_sparse_columns(F, wanted, active_dofs_, sample,
                                [&](const std::vector<int>& solved, const Eigen::MatrixXd& X) {
                                  for (std::size_t c = 0; c < solved.size(); ++c) {
                                    const int j = sampled[solved[c]];
                                    double exact = 0.0;
                                    for (const auto& [dof, v] : rows_[3 * j])
                                      exact += v * X(local[dof], c);
                                    ratio[solved[c]] = exact / blocks_[j](0, 0);
                                  }
                                });
  std::nth_element(ratio.begin(), ratio.begin() + sample / 2, ratio.end());
  if (ratio[sample / 2] > 0.0 && std::isfinite(ratio[sample / 2])) calibration_ = ratio[sample / 2];
  for (Eigen::Matrix3d& block : blocks_) block *= calibration_;
}

namespace {

// Rows of the augmented system, unknowns (w, mu, alpha) with mu the multipliers of every carried
// row (a row with free dofs) and w = K_ff^-1 B^T mu, so S lambda = B w:
//   K_ff w - B^T mu = 0
//   -(q_r B_node) w + coupling_r mu + qg_r alpha = rhs_r      (carried rows among the unknowns)
//   mu_i = 0                                                   (the other carried rows)
//   g^T mu = h
// The entries of the other rows and of the unknowns' whole nodes are stored even when zero, so
// the pattern does not depend on the statuses.
AugmentedMatrix augment(const std::vector<long>& k_ptr, const std::vector<long>& k_col,
                        const std::vector<double>& k_value,
                        const std::vector<std::vector<std::pair<int, double>>>& free_rows,
                        const std::vector<int>& position, long carried,
                        const contact::NewtonRows& rows) {
  const long nf = static_cast<long>(k_ptr.size()) - 1;
  const long k = rows.qg.cols();
  const long m = static_cast<long>(free_rows.size()) / 3;
  std::vector<int> unknown_of_row(free_rows.size(), -1);
  for (std::size_t r = 0; r < rows.unknowns.size(); ++r)
    unknown_of_row[rows.unknowns[r]] = static_cast<int>(r);
  AugmentedMatrix A;
  std::vector<std::vector<std::pair<long, double>>> multiplier_columns(nf);  // per free dof
  for (std::size_t i = 0; i < free_rows.size(); ++i)
    for (const auto& [f, v] : free_rows[i])
      multiplier_columns[f].emplace_back(nf + position[i], -v);
  for (long f = 0; f < nf; ++f) {
    for (long p = k_ptr[f]; p < k_ptr[f + 1]; ++p) A.add(k_col[p], k_value[p]);
    for (const auto& [c, v] : multiplier_columns[f]) A.add(c, v);
    A.end_row();
  }
  std::vector<std::pair<long, double>> w;
  for (long j = 0; j < m; ++j)
    for (int c = 0; c < 3; ++c) {
      const long i = 3 * j + c;
      if (position[i] < 0) continue;
      const int r = unknown_of_row[i];
      w.clear();
      for (int q = 0; q < 3; ++q)
        for (const auto& [f, v] : free_rows[3 * j + q])
          w.emplace_back(f, r >= 0 ? -rows.q[r][q] * v : 0.0);
      std::sort(w.begin(), w.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t e = 0; e < w.size();) {
        double sum = 0.0;
        const long f = w[e].first;
        for (; e < w.size() && w[e].first == f; ++e) sum += w[e].second;
        A.add(f, sum);
      }
      for (int q = 0; q < 3; ++q) {
        if (position[3 * j + q] < 0) continue;
        double v = r < 0 && q == c ? 1.0 : 0.0;
        if (r >= 0)
          for (const auto& [s, d] : rows.coupling[r])
            if (rows.unknowns[s] == 3 * j + q) v += d;
        A.add(nf + position[3 * j + q], v);
      }
      for (long a = 0; a < k; ++a) A.add(nf + carried + a, r >= 0 ? rows.qg(r, a) : 0.0);
      A.end_row();
    }
  for (long a = 0; a < k; ++a) {
    for (std::size_t i = 0; i < free_rows.size(); ++i)
      if (position[i] >= 0) {
        const int r = unknown_of_row[i];
        A.add(nf + position[i], r >= 0 ? rows.g(r, a) : 0.0);
      }
    A.end_row();
  }
  return A;
}

}  // namespace

bool SparseContactStructure::solve(const contact::NewtonRows& rows, Eigen::VectorXd& x,
                                   Eigen::VectorXd& s_lambda) {
  for (int row : rows.unknowns)
    if (position_[row] < 0)
      throw std::logic_error("sparse contact solve: an unknown row without free dofs");
  const AugmentedMatrix A =
      augment(k_ptr_, k_col_, k_value_, free_rows_, position_, carried_, rows);
  const long nf = static_cast<long>(k_ptr_.size()) - 1;
  const long n = static_cast<long>(rows.unknowns.size());
  const long k = rows.qg.cols();
  std::vector<double> b(A.size(), 0.0), solution(A.size(), 0.0);
  for (long r = 0; r < n; ++r) b[nf + position_[rows.unknowns[r]]] = rows.rhs[r];
  for (long a = 0; a < k; ++a) b[nf + carried_ + a] = rows.h[a];
  if (!lu_->solve(A, b, solution)) return false;
  x.resize(n + k);
  for (long r = 0; r < n; ++r) x[r] = solution[nf + position_[rows.unknowns[r]]];
  for (long a = 0; a < k; ++a) x[n + a] = solution[nf + carried_ + a];
  s_lambda = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free_rows_.size()));
  for (std::size_t i = 0; i < free_rows_.size(); ++i) {
    double sum = 0.0;
    for (const auto& [f, v] : free_rows_[i]) sum += v * solution[f];
    s_lambda[static_cast<Eigen::Index>(i)] = sum;
  }
  return true;
}

int SparseContactStructure::factorisations() const { return lu_->factorisations(); }

Eigen::VectorXd SparseContactStructure::times(const Eigen::VectorXd& lambda) const {
  std::vector<double> F(active_dofs_, 0.0);
  bool any = false;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (lambda[static_cast<Eigen::Index>(i)] == 0.0) continue;
    any = true;
    for (const auto& [dof, v] : rows_[i]) F[dof] += v * lambda[static_cast<Eigen::Index>(i)];
  }
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows_.size()));
  if (!any) return out;
  const std::vector<double> X = solver_->solve_homogeneous(F, 1);
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    double sum = 0.0;
    for (const auto& [dof, v] : rows_[i]) sum += v * X[dof];
    out[static_cast<Eigen::Index>(i)] = sum;
  }
  return out;
}

}  // namespace styk::solver_detail
