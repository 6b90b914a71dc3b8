// Per-system constants of the iteration (which components carry force, the complementarity
// parameters), the loads the contacts feel and the displacements of an iterate.
#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "active_set_parts.hpp"

namespace styk::contact::active_set_detail {
namespace {

// A component that moves only what the node's earlier components already move is dependent:
// e.g. on a symmetry plane the tangent t2 = (eps, 1, 0) of a node whose y is prescribed acts only
// through eps u_x, a multiple of the normal row (eps is the quadratic face's normal error at the
// node, ~1e-3, so the degeneracy test of set_up keeps it). Its multiplier would be undetermined and
// the linearised system singular; the force it stood for is taken by the support. Test: the Schur
// complement of the row in the Gram matrix of the node's rows, S_kk + w^2 G_k G_k^T (the rigid
// motions of bodies held by contact count as movement, weighted to S's scale), at most
// `ratio` (ActiveSetOptions::dependent_row_ratio) of its diagonal.
void drop_dependent_rows(const LinearContactSystem& system, const Eigen::Matrix3d& block, int k,
                         double max_diag, double g_max, double ratio, std::array<bool, 3>& live) {
  Eigen::Matrix3d M = block;
  if (system.G.cols() > 0 && g_max > 0.0) {
    const Eigen::MatrixXd Gk = system.G.middleRows<3>(3 * k);
    M += (max_diag / (g_max * g_max)) * Gk * Gk.transpose();
  }
  std::vector<int> accepted;
  for (int c = 0; c < 3; ++c) {
    if (!live[c]) continue;
    double schur = M(c, c);
    if (!accepted.empty()) {
      const int a = static_cast<int>(accepted.size());
      Eigen::MatrixXd Maa(a, a);
      Eigen::VectorXd mac(a);
      for (int i = 0; i < a; ++i) {
        mac[i] = M(accepted[i], c);
        for (int j = 0; j < a; ++j) Maa(i, j) = M(accepted[i], accepted[j]);
      }
      schur -= mac.dot(Maa.ldlt().solve(mac));
    }
    if (schur <= ratio * M(c, c))
      live[c] = false;
    else
      accepted.push_back(c);
  }
}

}  // namespace

Setup set_up(const std::vector<ContactConstraint>& constraints, const LinearContactSystem& system,
             const ActiveSetOptions& options) {
  const int m = static_cast<int>(constraints.size());
  Setup s;
  s.live.resize(m);
  s.c_n.assign(m, 1.0);
  s.c_t.assign(m, 1.0);
  std::vector<Eigen::Matrix3d> blocks(m);
  double max_diag = 0.0;
  for (int k = 0; k < m; ++k) {
    blocks[k] = compliance_block(system, k);
    max_diag = std::max(max_diag, blocks[k].diagonal().maxCoeff());
  }
  if (!(max_diag > 0.0)) max_diag = 1.0;
  const double g_max = system.G.size() > 0 ? system.G.cwiseAbs().maxCoeff() : 0.0;
  for (int k = 0; k < m; ++k) {
    for (int c = 0; c < 3; ++c) {
      const int row = 3 * k + c;
      const bool held = c > 0 && constraints[k].mortar && !system.held.empty() && system.held[k][c];
      const bool allowed = (c == 0 || constraints[k].scale(c) > 0.0) && !held;
      // A component whose dofs are all prescribed moves nothing: its force goes to the reactions.
      const bool degenerate =
          blocks[k](c, c) <= 1e-12 * max_diag &&
          (system.G.cols() == 0 || system.G.row(row).cwiseAbs().maxCoeff() <= 1e-12 * g_max);
      s.live[k][c] = allowed && !degenerate;
    }
    drop_dependent_rows(system, blocks[k], k, max_diag, g_max, options.dependent_row_ratio,
                        s.live[k]);
    // A penalty spring is in series with the structure: c_n is the inverse of both compliances
    // (the spring's largest, so c_n e < 1 at every force, and b keeps the sign of lambda_n on a
    // closed node).
    const double snn = blocks[k](0, 0);
    s.c_n[k] = 1.0 / ((snn > 1e-12 * max_diag ? snn : max_diag) +
                      constraints[k].largest_spring_compliance());
    double stt = 0.0;
    int count = 0;
    for (int c = 1; c < 3; ++c)
      if (s.live[k][c]) {
        stt += blocks[k](c, c);
        ++count;
      }
    s.c_t[k] = count > 0 && stt > 1e-12 * max_diag ? count / stt : s.c_n[k];
    s.load_force = std::max(s.load_force, s.c_n[k] * std::abs(system.d0[3 * k]));
  }
  return s;
}

LocalPoint point_of(const ContactConstraint& constraint, const Setup& setup, int k,
                    const Eigen::Vector3d& lambda, const Eigen::Vector3d& d,
                    const Eigen::Vector3d& d_ref, double eps, double proximal) {
  LocalPoint p;
  p.proximal = proximal;
  p.lambda = lambda;
  p.d = d;
  p.d_ref = d_ref;
  p.gap0 = constraint.gap0;
  p.c_n = setup.c_n[k];
  p.c_t = setup.c_t[k];
  p.eps = eps;
  p.live = setup.live[k];
  p.tied = constraint.law.kind == FrictionLaw::Kind::Tied;
  p.compliance = constraint.penalty_compliance();
  p.exponential_force0 = constraint.exponential_force0;
  p.exponential_beta = constraint.exponential_beta;
  p.bonded = constraint.bonded;
  p.frictional = constraint.law.has_tangential();
  return p;
}

Loads loads_with_fluid(const LinearContactSystem& system, const std::vector<char>& penetrated) {
  Loads out{system.d0, system.h};
  Eigen::VectorXd fluid = Eigen::VectorXd::Zero(system.d0.size());
  bool any = false;
  for (std::size_t j = 0; j < penetrated.size(); ++j) {
    if (!penetrated[j]) continue;
    const double f = system.fluid.force[j];
    const auto row = static_cast<Eigen::Index>(3 * j);
    fluid[row] = f;
    any = true;
    if (system.G.cols() > 0) out.h -= f * system.G.row(row).transpose();
  }
  if (any) out.d0 -= compliance_times(system, fluid);
  return out;
}

Eigen::VectorXd displacements(const LinearContactSystem& system, const Loads& loads,
                              const Iterate& x) {
  Eigen::VectorXd d = loads.d0 - compliance_times(system, x.lambda);
  if (system.G.cols() > 0) d += system.G * x.alpha;
  return d;
}

Eigen::Matrix3d compliance_block(const LinearContactSystem& system, int j) {
  if (system.structure) return system.structure->block(j);
  return system.S.block<3, 3>(3 * j, 3 * j);
}

Eigen::VectorXd compliance_times(const LinearContactSystem& system, const Eigen::VectorXd& v) {
  if (system.structure) return system.structure->times(v);
  return system.S * v;
}

}  // namespace styk::contact::active_set_detail
