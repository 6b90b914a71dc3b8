#include "styk/contact/active_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "dense_lu.hpp"

namespace styk::contact {
namespace {

// Proximal weight of the slip rows when a body is held by slipping nodes alone
// (LocalPoint::proximal): springs as stiff as the nodes' own contact stiffness c_t. 0.1 and 1 gave
// the same iteration counts on the SPEC 4.2 models (bench/contact/README.md).
constexpr double kSlipSpring = 1.0;

// Per-constraint constants of one linear system: which components can carry force and the
// complementarity parameters (the inverse self-compliance, so c d has force units and the
// iteration does not depend on the units of the model).
struct Setup {
  std::vector<std::array<bool, 3>> live;
  std::vector<double> c_n, c_t;
  double load_force = 0.0;  // force scale of the loading as the contacts feel it
};

// A component that moves only what the node's earlier components already move is dependent:
// e.g. on a symmetry plane the tangent t2 = (eps, 1, 0) of a node whose y is prescribed acts only
// through eps u_x, a multiple of the normal row (eps is the quadratic face's normal error at the
// node, ~1e-3, so the magnitude test above keeps it). Its multiplier would be undetermined and the
// linearised system singular; the force it stood for is taken by the support. Test: the Schur
// complement of the row in the Gram matrix of the node's rows, S_kk + w^2 G_k G_k^T (the rigid
// motions of bodies held by contact count as movement, weighted to S's scale), at most 1e-8 of
// its diagonal.
void drop_dependent_rows(const LinearContactSystem& system, int k, double max_diag, double g_max,
                         std::array<bool, 3>& live) {
  Eigen::Matrix3d M = system.S.block<3, 3>(3 * k, 3 * k);
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
    if (schur <= 1e-8 * M(c, c))
      live[c] = false;
    else
      accepted.push_back(c);
  }
}

Setup set_up(const std::vector<ContactConstraint>& constraints, const LinearContactSystem& system) {
  const int m = static_cast<int>(constraints.size());
  Setup s;
  s.live.resize(m);
  s.c_n.assign(m, 1.0);
  s.c_t.assign(m, 1.0);
  double max_diag = 0.0;
  for (int i = 0; i < 3 * m; ++i) max_diag = std::max(max_diag, system.S(i, i));
  if (!(max_diag > 0.0)) max_diag = 1.0;
  const double g_max = system.G.size() > 0 ? system.G.cwiseAbs().maxCoeff() : 0.0;
  for (int k = 0; k < m; ++k) {
    for (int c = 0; c < 3; ++c) {
      const int row = 3 * k + c;
      const bool allowed = c == 0 || constraints[k].scale(c) > 0.0;
      // A component whose dofs are all prescribed moves nothing: its force goes to the reactions.
      const bool degenerate =
          system.S(row, row) <= 1e-12 * max_diag &&
          (system.G.cols() == 0 || system.G.row(row).cwiseAbs().maxCoeff() <= 1e-12 * g_max);
      s.live[k][c] = allowed && !degenerate;
    }
    drop_dependent_rows(system, k, max_diag, g_max, s.live[k]);
    const double snn = system.S(3 * k, 3 * k);
    s.c_n[k] = 1.0 / (snn > 1e-12 * max_diag ? snn : max_diag);
    double stt = 0.0;
    int count = 0;
    for (int c = 1; c < 3; ++c)
      if (s.live[k][c]) {
        stt += system.S(3 * k + c, 3 * k + c);
        ++count;
      }
    s.c_t[k] = count > 0 && stt > 1e-12 * max_diag ? count / stt : s.c_n[k];
    s.load_force = std::max(s.load_force, s.c_n[k] * std::abs(system.d0[3 * k]));
  }
  return s;
}

LocalPoint point_of(const ContactConstraint& constraint, const Setup& setup, int k,
                    const Eigen::Vector3d& lambda, const Eigen::Vector3d& d,
                    const Eigen::Vector3d& d_ref, double eps, double proximal = 0.0) {
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
  p.frictional = constraint.law.has_tangential();
  return p;
}

// The iterate: all multipliers, rigid motions and the displacements they give.
struct Iterate {
  Eigen::VectorXd lambda, alpha, d;
};

// What the contacts feel besides their own forces: the structure's loads (d0, h) and the fluid
// forces of the penetrated zone, fluid = the known normal forces p A on its nodes:
// d0 - S fluid and h - G^T fluid.
struct Loads {
  Eigen::VectorXd d0, h;
};

Loads loads_with_fluid(const LinearContactSystem& system, const std::vector<char>& penetrated) {
  Loads out{system.d0, system.h};
  for (std::size_t j = 0; j < penetrated.size(); ++j) {
    if (!penetrated[j]) continue;
    const double f = system.fluid.force[j];
    const auto row = static_cast<Eigen::Index>(3 * j);
    out.d0 -= f * system.S.col(row);
    if (system.G.cols() > 0) out.h -= f * system.G.row(row).transpose();
  }
  return out;
}

Eigen::VectorXd displacements(const LinearContactSystem& system, const Loads& loads,
                              const Iterate& x) {
  Eigen::VectorXd d = loads.d0 - system.S * x.lambda;
  if (system.G.cols() > 0) d += system.G * x.alpha;
  return d;
}

// The fluid's penetrated zone at an iterate: the nodes reachable from an entry node through nodes
// that are open or carry less than the critical normal force (breadth-first over the slave
// faces). Empty without pressure penetration.
std::vector<char> penetrated_zone(const FluidPenetration& fluid,
                                  const std::vector<NodeStatus>& status,
                                  const Eigen::VectorXd& lambda) {
  if (fluid.empty()) return {};
  const std::size_t m = status.size();
  std::vector<char> zone(m, 0);
  const auto wet = [&](std::size_t j) {
    return fluid.force[j] > 0.0 &&
           (status[j] == NodeStatus::Open || lambda[3 * j] < fluid.critical[j]);
  };
  std::vector<std::size_t> front;
  for (std::size_t j = 0; j < m; ++j)
    if (fluid.entry[j] && wet(j)) {
      zone[j] = 1;
      front.push_back(j);
    }
  while (!front.empty()) {
    const std::size_t j = front.back();
    front.pop_back();
    for (int k : fluid.neighbours[j])
      if (!zone[k] && wet(k)) {
        zone[k] = 1;
        front.push_back(k);
      }
  }
  return zone;
}

// Solves the linearised conditions of `status` at `at` (slip rows with the proximal weight, see
// LocalPoint::proximal). Returns false when the system is singular (a body held only by contact is
// not held by the closed constraints).
bool solve_linearised(const std::vector<ContactConstraint>& constraints,
                      const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                      const std::vector<NodeStatus>& status, const Iterate& at,
                      const std::vector<ConstraintState>& previous, double eps, double proximal,
                      Iterate& out) {
  const int m = static_cast<int>(constraints.size());
  const int k = static_cast<int>(system.G.cols());
  std::vector<int> unknowns;  // global rows 3 node + component
  for (int j = 0; j < m; ++j)
    if (status[j] != NodeStatus::Open)
      for (int c = 0; c < 3; ++c)
        if (setup.live[j][c]) unknowns.push_back(3 * j + c);
  const int n = static_cast<int>(unknowns.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + k, n + k);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + k);
  Eigen::MatrixXd S_rows(3, n);
  for (int i = 0; i < n;) {
    const int node = unknowns[i] / 3;
    int end = i;
    while (end < n && unknowns[end] / 3 == node) ++end;
    const LocalPoint p = point_of(constraints[node], setup, node, at.lambda.segment<3>(3 * node),
                                  at.d.segment<3>(3 * node), previous[node].d_ref, eps, proximal);
    const LocalRows rows = linearise(p, status[node]);
    for (int j = 0; j < n; ++j) S_rows.col(j) = system.S.block<3, 1>(3 * node, unknowns[j]);
    const Eigen::MatrixXd QS = rows.Q * S_rows;
    const Eigen::Vector3d Qd0 = rows.Q * loads.d0.segment<3>(3 * node);
    Eigen::MatrixXd QG;
    if (k > 0) QG = rows.Q * system.G.middleRows<3>(3 * node);
    for (int r = i; r < end; ++r) {
      const int c = unknowns[r] % 3;
      A.row(r).head(n) = -QS.row(c);
      for (int q = i; q < end; ++q) A(r, q) += rows.D(c, unknowns[q] % 3);
      if (k > 0) A.row(r).tail(k) = QG.row(c);
      rhs[r] = rows.r[c] - Qd0[c];
    }
    i = end;
  }
  for (int a = 0; a < k; ++a) {
    for (int j = 0; j < n; ++j) A(n + a, j) = system.G(unknowns[j], a);
    rhs[n + a] = loads.h[a];
  }
  out.lambda = Eigen::VectorXd::Zero(3 * m);
  out.alpha = Eigen::VectorXd::Zero(k);
  if (n + k > 0) {
    // Rows mix units (displacement rows of S, force^2 rows of the slip law, force rows of the
    // rigid equilibrium): equilibrate them so the condition estimate means something.
    for (int r = 0; r < n + k; ++r) {
      const double largest = A.row(r).cwiseAbs().maxCoeff();
      if (!(largest > 0.0)) return false;  // e.g. a free rigid motion no closed node touches
      A.row(r) /= largest;
      rhs[r] /= largest;
    }
    for (int c = 0; c < n + k; ++c)
      if (!(A.col(c).cwiseAbs().maxCoeff() > 1e-14)) return false;
    const contact_detail::DenseLu lu(std::move(A));
    if (!lu.factorised() || !(lu.rcond() > 1e-15)) return false;
    const Eigen::VectorXd x = lu.solve(rhs);
    if (!x.allFinite()) return false;
    for (int j = 0; j < n; ++j) out.lambda[unknowns[j]] = x[j];
    out.alpha = x.tail(k);
  }
  out.d = displacements(system, loads, out);
  return true;
}

// How the bodies held only by contact are held at `at` under `status`. Along a free rigid motion a
// (column of G) the closed constraints can carry, with the normal forces of `at` and tangential
// forces anywhere in their cones, the range sum_j G_nj lambda_nj +- sum_j lambda_nj |G_tj|
// (scaled variables: the cone is the unit disk).
// - slip_only: for some motion every closed constraint that could resist it slips. The exact
//   tangent has no stiffness along the slip there, so the linearised system is singular or
//   nearly so (slip directions a little off the motion) and its step is meaningless.
// - loss: for such a motion the load h_a lies outside that range: no friction force distribution
//   balances it, the body slides (a genuine loss of equilibrium).
struct BodyHold {
  bool slip_only = false;
  EquilibriumLoss loss;
};

// A motion that presses the closed nodes together as the load pushes the body along it (a pin
// in a taper: the contact's normal components along the push, sin(alpha) = 0.05 of the motion for
// a 1:10 taper) is held by normal forces that grow with the motion, however little friction
// there is: no friction capacity to exceed. Measured as the RMS of the closing normal components
// over the RMS of the whole relative motion at the closed nodes (tangential rows unscaled by mu);
// a cylinder's nodes give below 1e-3 (the quadratic faces' normal error at symmetry-plane nodes),
// hence the threshold.
constexpr double kWedgeRatio = 1e-2;

// The exact slip tangent lacks stiffness only along each node's slip direction e. A motion that
// crosses the slip directions (a sleeve turned past its friction capacity by a prescribed rotation
// is free to slide axially, while its nodes slip around the axis) is held by the tangent's
// P = I - e e^T part, so the exact Newton step is regular there; slip springs would only slow it
// down to a linear rate (measured on model B's sector at full slip: no convergence in 50
// iterations with them, 2-6 per increment without). Threshold on the RMS of the motion's components
// across the slip directions over the RMS of its tangential part at the slipping nodes.
constexpr double kCrossingRatio = 1e-2;

// Checks one motion v (k, unit): the range of G_v^T lambda the closed constraints can carry.
void check_motion(const std::vector<ContactConstraint>& constraints,
                  const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                  const std::vector<NodeStatus>& status, const Iterate& at,
                  const std::vector<ConstraintState>& previous, const Eigen::VectorXd& v,
                  BodyHold& out) {
  const Eigen::VectorXd gv = system.G * v;
  const double g_max = gv.cwiseAbs().maxCoeff();
  double carried = 0.0, capacity = 0.0, across = 0.0, along_total = 0.0;
  int slipping = 0;
  for (std::size_t j = 0; j < status.size(); ++j) {
    if (status[j] == NodeStatus::Open) continue;
    const double ln = std::max(at.lambda[3 * j], 0.0);
    carried += gv[3 * j] * ln;
    Eigen::Vector2d gt = Eigen::Vector2d::Zero();
    for (int c = 1; c < 3; ++c)
      if (setup.live[j][c]) gt[c - 1] = gv[3 * j + c];
    if (!(gt.norm() > 1e-12 * g_max)) continue;
    if (status[j] == NodeStatus::Stick) return;  // a sticking node holds the motion
    ++slipping;
    capacity += ln * gt.norm();
    // The slip direction e = xi / |xi|, xi = lambda_t + c_t (d_t - d_t_ref) (friction_law.hpp).
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();
    for (int c = 1; c < 3; ++c)
      if (setup.live[j][c])
        xi[c - 1] = at.lambda[3 * j + c] + setup.c_t[j] * (at.d[3 * j + c] - previous[j].d_ref[c]);
    const Eigen::Vector2d e =
        xi.norm() > 0.0 ? Eigen::Vector2d(xi.normalized()) : Eigen::Vector2d::Zero();
    across += (gt - gt.dot(e) * e).squaredNorm();
    along_total += gt.squaredNorm();
  }
  if (slipping == 0) return;
  if (across > kCrossingRatio * kCrossingRatio * along_total) return;  // held by P (above)
  const double push = loads.h.dot(v) - carried;  // the load not carried by the normal forces
  const double applied = std::abs(push);
  // The push moves the body along sign(push) v, which changes the closed nodes' normal
  // displacements by sign(push) (G v)_n: positive closes them.
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
  // A wedge: no friction limit, and the normal rows see the motion, so the exact Newton step is
  // regular (slip springs would only slow it down: they hold the body back against the small
  // stiffness sin^2(alpha) k_n of the wedge).
  if (closing > kWedgeRatio * kWedgeRatio * motion) return;
  out.slip_only = true;
  const double excess = applied - capacity;
  EquilibriumLoss& worst = out.loss;
  if (!(excess > 1e-9 * std::max(applied, 1e-300))) return;
  if (!worst.lost || excess > worst.applied - worst.capacity) {
    worst.lost = true;
    worst.motion = v;
    worst.slipping = slipping;
    worst.applied = applied;
    worst.capacity = capacity;
  }
}

// Every free motion on its own, and with several the direction of the unbalanced load
// h - (what the normal forces carry), which separates h from the reachable set when no single
// motion does (e.g. a sleeve free to turn and slide, pushed and twisted at once).
BodyHold body_hold(const std::vector<ContactConstraint>& constraints,
                   const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                   const std::vector<NodeStatus>& status, const Iterate& at,
                   const std::vector<ConstraintState>& previous) {
  BodyHold out;
  const int k = static_cast<int>(system.G.cols());
  for (int a = 0; a < k; ++a)
    check_motion(constraints, system, loads, setup, status, at, previous,
                 Eigen::VectorXd::Unit(k, a), out);
  if (k > 1) {
    Eigen::VectorXd unbalanced = loads.h;
    for (std::size_t j = 0; j < status.size(); ++j)
      if (status[j] != NodeStatus::Open)
        unbalanced -= std::max(at.lambda[3 * j], 0.0) * system.G.row(3 * j).transpose();
    if (unbalanced.norm() > 0.0)
      check_motion(constraints, system, loads, setup, status, at, previous, unbalanced.normalized(),
                   out);
  }
  return out;
}

// |lambda_t| / lambda_n of constraint j at x (scaled variables: 1 on the cone); -1 when open.
double friction_ratio(const Setup& setup, const Eigen::VectorXd& lambda, int j) {
  const double ln = lambda[3 * j];
  if (!(ln > 0.0)) return -1.0;
  double lt2 = 0.0;
  for (int c = 1; c < 3; ++c)
    if (setup.live[j][c]) lt2 += lambda[3 * j + c] * lambda[3 * j + c];
  return std::sqrt(lt2) / ln;
}

// The stick/slip front moves a few nodes per iteration: a node that starts to slip sheds its
// tangential force on its sticking neighbours, which leave the cone in the next iteration. While
// the front only advances (sticking nodes turned to slip, none back), a sticking node whose ratio
// |lambda_t| / lambda_n grew from `before` to `now` and would pass 1 after `lookahead` more such
// steps is sent to slip at once. Returns the nodes switched.
std::vector<int> anticipate_front(const std::vector<ContactConstraint>& constraints,
                                  const Setup& setup, const std::vector<NodeStatus>& solved,
                                  const Iterate& before, const Iterate& now, double lookahead,
                                  std::vector<NodeStatus>& status) {
  std::vector<int> switched;
  if (!(lookahead > 0.0)) return switched;
  std::size_t advanced = 0;
  for (std::size_t j = 0; j < status.size(); ++j) {
    if (solved[j] == NodeStatus::Slip && status[j] == NodeStatus::Stick) return switched;
    if (solved[j] == NodeStatus::Stick && status[j] == NodeStatus::Slip) ++advanced;
  }
  std::vector<std::pair<double, int>> candidates;  // (predicted ratio, node)
  for (std::size_t j = 0; j < status.size(); ++j) {
    if (solved[j] != NodeStatus::Stick || status[j] != NodeStatus::Stick) continue;
    if (constraints[j].law.kind == FrictionLaw::Kind::Tied ||
        !(setup.live[j][1] || setup.live[j][2]))
      continue;
    const int k = static_cast<int>(j);
    const double ratio_before = friction_ratio(setup, before.lambda, k);
    const double ratio_now = friction_ratio(setup, now.lambda, k);
    if (ratio_before < 0.0 || ratio_now < 0.0 || !(ratio_now > ratio_before)) continue;
    const double predicted = ratio_now + lookahead * (ratio_now - ratio_before);
    if (predicted > 1.0) candidates.emplace_back(predicted, k);
  }
  // The front moves about as many nodes per iteration as it just did: no more than that many
  // ahead, the likeliest first (a global redistribution, as in a shrink fit's push, raises many
  // ratios at once and would otherwise send far too many).
  std::sort(candidates.begin(), candidates.end(), std::greater<>());
  for (std::size_t i = 0; i < candidates.size() && i < advanced; ++i) {
    status[candidates[i].second] = NodeStatus::Slip;
    switched.push_back(candidates[i].second);
  }
  return switched;
}

bool any_slipping(const std::vector<NodeStatus>& status) {
  return std::find(status.begin(), status.end(), NodeStatus::Slip) != status.end();
}

}  // namespace

IncrementOutcome solve_increment(const std::vector<ContactConstraint>& constraints,
                                 const LinearContactSystem& system, ContactState& state,
                                 const ActiveSetOptions& options,
                                 const std::function<void(const IterationRecord&)>& log) {
  const int m = static_cast<int>(constraints.size());
  const int k = static_cast<int>(system.G.cols());
  IncrementOutcome outcome;
  if (static_cast<int>(state.nodes.size()) != m) state.nodes.assign(m, ConstraintState{});
  if (state.alpha.size() != k) state.alpha = Eigen::VectorXd::Zero(k);
  if (state.dalpha.size() != k) state.dalpha = Eigen::VectorXd::Zero(k);
  const Setup setup = set_up(constraints, system);

  // The predictor: last converged multipliers (plus the extrapolated change of the last
  // increment) against the new loads.
  const double extrapolation = state.started ? options.extrapolation : 0.0;
  Iterate at;
  at.lambda.resize(3 * m);
  for (int j = 0; j < m; ++j)
    at.lambda.segment<3>(3 * j) = state.nodes[j].lambda + extrapolation * state.nodes[j].dlambda;
  at.alpha = state.alpha + extrapolation * state.dalpha;
  // The fluid's zone starts where the last increment left it.
  std::vector<char> zone;
  if (!system.fluid.empty())
    for (int j = 0; j < m; ++j) zone.push_back(state.nodes[j].penetrated ? 1 : 0);
  Loads loads = loads_with_fluid(system, zone);
  at.d = displacements(system, loads, at);
  auto force_scale = [&](const Iterate& x) {
    return std::max(
        {x.lambda.size() > 0 ? x.lambda.cwiseAbs().maxCoeff() : 0.0, setup.load_force, 1e-300});
  };
  std::vector<NodeStatus> status(m);
  const bool trust_predictor = state.started || k == 0;
  for (int j = 0; j < m; ++j) {
    if (trust_predictor) {
      status[j] =
          classify(point_of(constraints[j], setup, j, at.lambda.segment<3>(3 * j),
                            at.d.segment<3>(3 * j), state.nodes[j].d_ref, 1e-12 * force_scale(at)));
      // Without an extrapolated change (a step's start, or the first increment) the first solve
      // is the elastic trial: every closed frictional node sticks, which fixes the bodies held
      // by contact and gives each node the tangential force a stuck state would need; the
      // classification then returns the nodes beyond the cone to slip, with that force's
      // direction (return mapping). Trial slip directions from frozen multipliers instead are
      // arbitrary where a body held by friction moves under a new load.
      if (extrapolation == 0.0 && status[j] == NodeStatus::Slip &&
          constraints[j].law.has_tangential())
        status[j] = NodeStatus::Stick;
    } else {
      // A body held only by contact has no meaningful displacement before some contact closes:
      // start from every touching node closed and sticking.
      status[j] = constraints[j].gap0 <= 0.0 ? NodeStatus::Stick : NodeStatus::Open;
    }
  }
  // An extrapolated predictor that sends every closed frictional node to slip while the last
  // increment had sticking nodes overshoots the front (the change of the last increment
  // continued): start from the elastic trial instead. Measured on model B's sector turned by a
  // prescribed angle: from such a predictor the iteration stalled (3 x 50 iterations and three
  // cut-backs in the second increment); from the trial it converges in 5.
  bool elastic_trial = extrapolation == 0.0;
  if (trust_predictor && extrapolation > 0.0) {
    int closed_frictional = 0, sticking = 0, stuck_before = 0;
    for (int j = 0; j < m; ++j) {
      if (!constraints[j].law.has_tangential()) continue;
      stuck_before += state.nodes[j].status == NodeStatus::Stick ? 1 : 0;
      if (status[j] == NodeStatus::Open) continue;
      ++closed_frictional;
      sticking += status[j] == NodeStatus::Stick ? 1 : 0;
    }
    if (closed_frictional > 0 && sticking == 0 && stuck_before > 0) {
      elastic_trial = true;
      for (int j = 0; j < m; ++j)
        if (status[j] == NodeStatus::Slip && constraints[j].law.has_tangential())
          status[j] = NodeStatus::Stick;
    }
  }

  using Seen = std::pair<std::vector<NodeStatus>, std::vector<char>>;
  std::vector<Seen> seen{{status, zone}};
  std::vector<std::vector<int>> changed_history;
  double damping = 1.0;
  bool closed_touching = !trust_predictor;
  bool front_receded = false;  // some node went from slip back to stick in this increment
  // From the elastic trial (everything closed sticks) the slip front can only advance; from an
  // extrapolated predictor it may have to move either way. Not in the first iteration either:
  // the growth from the predictor (the last step's solution) to the trial is the load step's,
  // not the front's. Both cost the builder's shrink-fit model A iterations (bench README).
  const bool from_elastic_trial = elastic_trial;
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    const double eps = 1e-12 * force_scale(at);
    Iterate next;
    // A body held by slipping nodes alone: either the load exceeds what friction can carry (a
    // genuine loss of equilibrium: stop here, the driver reports it) or the iterate is merely far
    // from the stick zone the solution has: take the step with the slip springs
    // (LocalPoint::proximal), which give the body a stiffness along the slip.
    const BodyHold hold = body_hold(constraints, system, loads, setup, status, at, state.nodes);
    if (hold.loss.lost) {
      outcome.loss = hold.loss;
      outcome.reason = "friction capacity exceeded";
      outcome.iterations = iteration;
      return outcome;
    }
    bool regularised = hold.slip_only;
    bool solved = solve_linearised(constraints, system, loads, setup, status, at, state.nodes, eps,
                                   regularised ? kSlipSpring : 0.0, next);
    if (!solved && !regularised && any_slipping(status)) {
      // Singular for another reason (e.g. slip directions that leave a rotation free).
      regularised = true;
      solved = solve_linearised(constraints, system, loads, setup, status, at, state.nodes, eps,
                                kSlipSpring, next);
    }
    if (!solved) {
      if (!closed_touching) {
        // Close every touching node once and try again before giving up.
        closed_touching = true;
        for (int j = 0; j < m; ++j)
          if (status[j] == NodeStatus::Open && constraints[j].gap0 <= 0.0)
            status[j] = NodeStatus::Stick;
        continue;
      }
      outcome.reason =
          "the closed contact constraints do not hold the bodies supported only by "
          "contact (singular contact system)";
      outcome.iterations = iteration;
      return outcome;
    }
    if (damping < 1.0) {
      next.lambda = at.lambda + damping * (next.lambda - at.lambda);
      next.alpha = at.alpha + damping * (next.alpha - at.alpha);
      next.d = displacements(system, loads, next);
    }
    const double scale = force_scale(next);
    std::vector<NodeStatus> new_status(m);
    std::vector<int> changed;
    double residual = 0.0;
    IterationRecord record;
    record.iteration = iteration;
    record.damping = damping;
    record.regularised = regularised;
    for (int j = 0; j < m; ++j) {
      const LocalPoint p = point_of(constraints[j], setup, j, next.lambda.segment<3>(3 * j),
                                    next.d.segment<3>(3 * j), state.nodes[j].d_ref, 1e-12 * scale);
      new_status[j] = classify(p);
      residual = std::max(residual, complementarity_residual(p).cwiseAbs().maxCoeff());
      if (new_status[j] != status[j]) changed.push_back(j);
    }
    // Once a node has come back from slip to stick the front has found its place: anticipating
    // further would only make the nodes at the front flip.
    for (int j = 0; j < m; ++j)
      if (status[j] == NodeStatus::Slip && new_status[j] == NodeStatus::Stick) front_receded = true;
    const std::vector<int> anticipated =
        damping < 1.0 || front_receded || !from_elastic_trial || iteration == 1
            ? std::vector<int>{}
            : anticipate_front(constraints, setup, status, at, next, options.front_lookahead,
                               new_status);
    changed.insert(changed.end(), anticipated.begin(), anticipated.end());
    record.anticipated = static_cast<int>(anticipated.size());
    for (int j = 0; j < m; ++j) {
      switch (new_status[j]) {
        case NodeStatus::Open:
          ++record.open;
          break;
        case NodeStatus::Stick:
          ++record.stick;
          break;
        case NodeStatus::Slip:
          ++record.slip;
          break;
      }
    }
    // The fluid's zone follows the contact state: a moved front is a change like a status's.
    std::vector<char> new_zone = penetrated_zone(system.fluid, new_status, next.lambda);
    int zone_changes = 0;
    for (std::size_t j = 0; j < new_zone.size(); ++j) {
      zone_changes += new_zone[j] != zone[j] ? 1 : 0;
      record.penetrated += new_zone[j];
    }
    record.changes = static_cast<int>(changed.size()) + zone_changes;
    record.residual = residual / scale;
    bool converged = changed.empty() && zone_changes == 0 && record.residual <= options.tolerance;
    if (converged && damping < 1.0) {
      // A damped step is only near the solution of its status set: one full step more makes it
      // exact.
      converged = false;
      damping = 1.0;
    } else if (!converged && record.changes > 0 &&
               std::find(seen.begin(), seen.end(), Seen{new_status, new_zone}) != seen.end()) {
      // A status set seen before: the iteration cycles. Shorter steps break the cycle.
      record.cycle = true;
      damping = std::max(damping * 0.5, 1.0 / 64.0);
    }
    outcome.history.push_back(record);
    if (log) log(record);
    changed_history.push_back(changed);
    seen.emplace_back(new_status, new_zone);
    at = std::move(next);
    status = std::move(new_status);
    if (zone_changes > 0) {
      zone = std::move(new_zone);
      loads = loads_with_fluid(system, zone);
      at.d = displacements(system, loads, at);
    }
    outcome.iterations = iteration;
    if (converged) {
      outcome.converged = true;
      for (int j = 0; j < m; ++j) {
        ConstraintState& s = state.nodes[j];
        s.status = status[j];
        s.dlambda = at.lambda.segment<3>(3 * j) - s.lambda;
        s.lambda = at.lambda.segment<3>(3 * j);
        s.d = at.d.segment<3>(3 * j);
        if (s.status != NodeStatus::Open)
          for (int c = 1; c < 3; ++c)
            if (setup.live[j][c]) s.slip[c - 1] += (s.d[c] - s.d_ref[c]) / constraints[j].scale(c);
        s.d_ref = s.d;
        s.penetrated = !zone.empty() && zone[j] != 0;
        s.fluid = s.penetrated ? system.fluid.force[j] : 0.0;
      }
      state.dalpha = at.alpha - state.alpha;
      state.alpha = at.alpha;
      state.started = true;
      return outcome;
    }
  }
  char residual[32];
  std::snprintf(residual, sizeof residual, "%.2e",
                outcome.history.empty() ? 0.0 : outcome.history.back().residual);
  outcome.reason = "no convergence in " + std::to_string(options.max_iterations) +
                   " iterations (last residual " + residual + ")";
  std::set<int> offending;
  const std::size_t last = changed_history.size();
  for (std::size_t i = last > 4 ? last - 4 : 0; i < last; ++i)
    offending.insert(changed_history[i].begin(), changed_history[i].end());
  outcome.offending.assign(offending.begin(), offending.end());
  return outcome;
}

}  // namespace styk::contact
