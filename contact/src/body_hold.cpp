// Bodies held by friction alone (docs/contact.md, "Bodies held by friction alone"): per free rigid
// motion of a body held only by contact, whether every closed node resisting it slips, and whether
// the load along it exceeds what the friction cones can carry.
#include <algorithm>
#include <cmath>

#include "active_set_parts.hpp"

namespace styk::contact::active_set_detail {
namespace {

// What the closed constraints offer against one motion (G v at the contact rows).
struct Resistance {
  bool held_by_sticking = false;  // a sticking node resists the motion
  int slipping = 0;               // closed nodes that resist it, all slipping
  double carried = 0.0;           // G_v^T lambda_n: what the normal forces carry along it
  double capacity = 0.0;          // sum lambda_n |G_t v|: the most friction carries along it
  double across = 0.0;            // squared components across the slip directions
  double along = 0.0;             // squared tangential components
};

Resistance resistance_along(const Setup& setup, const std::vector<NodeStatus>& status,
                            const Iterate& at, const std::vector<ConstraintState>& previous,
                            const Eigen::VectorXd& gv) {
  const double g_max = gv.cwiseAbs().maxCoeff();
  Resistance r;
  for (std::size_t j = 0; j < status.size(); ++j) {
    if (status[j] == NodeStatus::Open) continue;
    const double ln = std::max(at.lambda[3 * j], 0.0);
    r.carried += gv[3 * j] * ln;
    Eigen::Vector2d gt = Eigen::Vector2d::Zero();
    for (int c = 1; c < 3; ++c)
      if (setup.live[j][c]) gt[c - 1] = gv[3 * j + c];
    if (!(gt.norm() > 1e-12 * g_max)) continue;
    if (status[j] == NodeStatus::Stick) {
      r.held_by_sticking = true;
      return r;
    }
    ++r.slipping;
    r.capacity += ln * gt.norm();
    // The slip direction e = xi / |xi|, xi = lambda_t + c_t (d_t - d_t_ref) (friction_law.hpp).
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();
    for (int c = 1; c < 3; ++c)
      if (setup.live[j][c])
        xi[c - 1] = at.lambda[3 * j + c] + setup.c_t[j] * (at.d[3 * j + c] - previous[j].d_ref[c]);
    const Eigen::Vector2d e =
        xi.norm() > 0.0 ? Eigen::Vector2d(xi.normalized()) : Eigen::Vector2d::Zero();
    r.across += (gt - gt.dot(e) * e).squaredNorm();
    r.along += gt.squaredNorm();
  }
  return r;
}

// A motion that presses the closed nodes together as the load pushes the body along it (a pin
// in a taper: the contact's normal components along the push, sin(alpha) = 0.05 of the motion for
// a 1:10 taper) is held by normal forces that grow with the motion, however little friction
// there is: no friction capacity to exceed. Measured as the RMS of the closing normal components
// over the RMS of the whole relative motion at the closed nodes (tangential rows unscaled by mu),
// against ActiveSetOptions::wedge_ratio. The push moves the body along sign(push) v, which
// changes the closed nodes' normal displacements by sign(push) (G v)_n: positive closes them.
bool is_wedge(const std::vector<ContactConstraint>& constraints,
              const std::vector<NodeStatus>& status, const Eigen::VectorXd& gv, double push,
              double wedge_ratio) {
  double closing = 0.0, motion = 0.0;
  for (std::size_t j = 0; j < status.size(); ++j) {
    if (status[j] == NodeStatus::Open) continue;
    const double normal = (push >= 0.0 ? 1.0 : -1.0) * gv[3 * j];
    closing += normal > 0.0 ? normal * normal : 0.0;
    motion += normal * normal;
    for (int c = 1; c < 3; ++c) {
      const double scale = constraints[j].scale(c);
      if (scale > 0.0) motion += (gv[3 * j + c] / scale) * (gv[3 * j + c] / scale);
    }
  }
  return closing > wedge_ratio * wedge_ratio * motion;
}

// Checks one motion v (k, unit): the range of G_v^T lambda the closed constraints can carry.
void check_motion(const std::vector<ContactConstraint>& constraints,
                  const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                  const std::vector<NodeStatus>& status, const Iterate& at,
                  const std::vector<ConstraintState>& previous, const ActiveSetOptions& options,
                  const Eigen::VectorXd& v, BodyHold& out) {
  const Eigen::VectorXd gv = system.G * v;
  const Resistance r = resistance_along(setup, status, at, previous, gv);
  if (r.held_by_sticking || r.slipping == 0) return;
  // The exact slip tangent lacks stiffness only along each node's slip direction e; a motion
  // crossing the slip directions is held by its P = I - e e^T part (ActiveSetOptions::
  // crossing_ratio), so the exact Newton step is regular there.
  const double crossing = options.crossing_ratio;
  if (r.across > crossing * crossing * r.along) return;
  const double push = loads.h.dot(v) - r.carried;  // the load not carried by the normal forces
  const double applied = std::abs(push);
  // A wedge: no friction limit, and the normal rows see the motion, so the exact Newton step is
  // regular (slip springs would only slow it down: they hold the body back against the small
  // stiffness sin^2(alpha) k_n of the wedge).
  if (is_wedge(constraints, status, gv, push, options.wedge_ratio)) return;
  out.slip_only = true;
  const double excess = applied - r.capacity;
  EquilibriumLoss& worst = out.loss;
  if (!(excess > 1e-9 * std::max(applied, 1e-300))) return;
  if (!worst.lost || excess > worst.applied - worst.capacity) {
    worst.lost = true;
    worst.motion = v;
    worst.slipping = r.slipping;
    worst.applied = applied;
    worst.capacity = r.capacity;
  }
}

}  // namespace

// Every free motion on its own, and with several the direction of the unbalanced load
// h - (what the normal forces carry), which separates h from the reachable set when no single
// motion does (e.g. a sleeve free to turn and slide, pushed and twisted at once).
BodyHold body_hold(const std::vector<ContactConstraint>& constraints,
                   const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                   const std::vector<NodeStatus>& status, const Iterate& at,
                   const std::vector<ConstraintState>& previous, const ActiveSetOptions& options) {
  BodyHold out;
  const int k = static_cast<int>(system.G.cols());
  for (int a = 0; a < k; ++a)
    check_motion(constraints, system, loads, setup, status, at, previous, options,
                 Eigen::VectorXd::Unit(k, a), out);
  if (k > 1) {
    Eigen::VectorXd unbalanced = loads.h;
    for (std::size_t j = 0; j < status.size(); ++j)
      if (status[j] != NodeStatus::Open)
        unbalanced -= std::max(at.lambda[3 * j], 0.0) * system.G.row(3 * j).transpose();
    if (unbalanced.norm() > 0.0)
      check_motion(constraints, system, loads, setup, status, at, previous, options,
                   unbalanced.normalized(), out);
  }
  return out;
}

}  // namespace styk::contact::active_set_detail
