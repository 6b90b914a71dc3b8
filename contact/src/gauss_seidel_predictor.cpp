// The status predictor of increments that start from the elastic trial: nonsmooth block
// Gauss-Seidel sweeps (Jean and Moreau's NSGS) on the condensed contact problem d = d0 - S lambda.
// Each sweep solves every constraint's own conditions with the others' multipliers held, by the
// projection lambda <- lambda - complementarity_residual (friction_law.hpp) at c = the inverse
// self-compliances, so a node's own normal row is solved exactly in one projection. A sweep costs
// one product with S and no factorisation; the slip front, which the Newton steps move a few node
// rows per linearised solve, moves along the sweeps instead.
#include <algorithm>
#include <cmath>

#include "active_set_parts.hpp"

namespace styk::contact::active_set_detail {
namespace {

// One constraint's conditions with the rest of the multipliers held: w = d + S_jj lambda_j is
// what the others give it. A few projections (exact for the normal row; the tangential rows
// settle geometrically with the block's off-diagonal coupling).
Eigen::Vector3d local_solution(const ContactConstraint& constraint, const Setup& setup, int j,
                               const Eigen::Matrix3d& Sjj, const Eigen::Vector3d& w,
                               const Eigen::Vector3d& d_ref, Eigen::Vector3d lambda, double eps) {
  for (int inner = 0; inner < 8; ++inner) {
    const LocalPoint p = point_of(constraint, setup, j, lambda, w - Sjj * lambda, d_ref, eps);
    const Eigen::Vector3d residual = complementarity_residual(p);
    lambda -= residual;
    for (int c = 0; c < 3; ++c)
      if (!setup.live[j][c]) lambda[c] = 0.0;
    if (residual.cwiseAbs().maxCoeff() <= 1e-12 * std::max(lambda.cwiseAbs().maxCoeff(), eps))
      break;
  }
  return lambda;
}

}  // namespace

int gauss_seidel_sweeps(const std::vector<ContactConstraint>& constraints,
                        const LinearContactSystem& system, const Setup& setup,
                        const std::vector<ConstraintState>& previous, double eps, int max_sweeps,
                        int settled_sweeps, Iterate& x) {
  const int m = static_cast<int>(constraints.size());
  std::vector<NodeStatus> last(m, NodeStatus::Open);
  int unchanged = 0;
  int sweep = 0;
  for (; sweep < max_sweeps && unchanged < settled_sweeps; ++sweep) {
    int changes = 0;
    for (int j = 0; j < m; ++j) {
      if (!setup.live[j][0]) continue;
      const Eigen::Matrix3d Sjj = system.S.block<3, 3>(3 * j, 3 * j);
      const Eigen::Vector3d old = x.lambda.segment<3>(3 * j);
      const Eigen::Vector3d w = x.d.segment<3>(3 * j) + Sjj * old;
      const Eigen::Vector3d now =
          local_solution(constraints[j], setup, j, Sjj, w, previous[j].d_ref, old, eps);
      const Eigen::Vector3d change = now - old;
      if (change.cwiseAbs().maxCoeff() > 0.0) {
        x.lambda.segment<3>(3 * j) = now;
        x.d.noalias() -= system.S.middleCols<3>(3 * j) * change;
      }
      const NodeStatus status = classify(
          point_of(constraints[j], setup, j, now, x.d.segment<3>(3 * j), previous[j].d_ref, eps));
      changes += status != last[j] ? 1 : 0;
      last[j] = status;
    }
    unchanged = changes == 0 ? unchanged + 1 : 0;
  }
  return sweep;
}

}  // namespace styk::contact::active_set_detail
