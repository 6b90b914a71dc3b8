// The semi-smooth Newton (primal-dual active-set) iteration of one load increment
// (docs/contact.md, "Iteration, diagnostics, failure"): predictor, then per iteration the check of
// bodies held by friction alone, the linearised solve, the classification, the slip-front
// anticipation, the fluid's zone and the convergence / cycle judgement; commit on convergence.
#include "styk/contact/active_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>

#include "active_set_parts.hpp"

namespace styk::contact {
namespace {

using namespace active_set_detail;

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
// the front advances (sticking nodes turned to slip; the only nodes back are the `returned` ones
// at the kink), a sticking node whose ratio |lambda_t| / lambda_n grew from `before` to `now` and
// would pass 1 after `lookahead` more such steps is sent to slip at once. Returns the nodes
// switched.
std::vector<int> anticipate_front(const std::vector<ContactConstraint>& constraints,
                                  const Setup& setup, const std::vector<NodeStatus>& solved,
                                  const Iterate& before, const Iterate& now, double lookahead,
                                  std::size_t returned, std::vector<NodeStatus>& status) {
  std::vector<int> switched;
  if (!(lookahead > 0.0)) return switched;
  std::size_t moved = returned;
  for (std::size_t j = 0; j < status.size(); ++j)
    if (solved[j] == NodeStatus::Stick && status[j] == NodeStatus::Slip) ++moved;
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
  for (std::size_t i = 0; i < candidates.size() && i < moved; ++i) {
    status[candidates[i].second] = NodeStatus::Slip;
    switched.push_back(candidates[i].second);
  }
  return switched;
}

bool any_slipping(const std::vector<NodeStatus>& status) {
  return std::find(status.begin(), status.end(), NodeStatus::Slip) != status.end();
}

// One increment's iteration. The phases are the member functions, in the order run() calls them;
// the members are the iteration's state between phases.
class IncrementIteration {
 public:
  IncrementIteration(const std::vector<ContactConstraint>& constraints,
                     const LinearContactSystem& system, ContactState& state,
                     const ActiveSetOptions& options,
                     const std::function<void(const IterationRecord&)>& log)
      : constraints_(constraints),
        system_(system),
        state_(state),
        options_(options),
        log_(log),
        m_(static_cast<int>(constraints.size())),
        k_(static_cast<int>(system.G.cols())) {
    if (static_cast<int>(state_.nodes.size()) != m_) state_.nodes.assign(m_, ConstraintState{});
    if (state_.alpha.size() != k_) state_.alpha = Eigen::VectorXd::Zero(k_);
    if (state_.dalpha.size() != k_) state_.dalpha = Eigen::VectorXd::Zero(k_);
    setup_ = set_up(constraints_, system_, options_);
    for (const ContactConstraint& c : constraints_)
      nonlinear_springs_ = nonlinear_springs_ || c.exponential_force0 > 0.0;
  }

  IncrementOutcome run() {
    predict();
    for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
      const Step step = iterate(iteration);
      if (step == Step::retry) continue;
      outcome_.iterations = iteration;
      if (step == Step::failed) return outcome_;
      if (step == Step::converged) {
        outcome_.converged = true;
        commit();
        return outcome_;
      }
      if (stagnated()) {
        report_no_convergence();
        return outcome_;
      }
    }
    report_no_convergence();
    return outcome_;
  }

 private:
  // What an iteration ended with; `retry`: no solve, the statuses were changed instead.
  enum class Step { next, retry, converged, failed };

  // A status set with the fluid's zone: what cycle detection compares.
  using Seen = std::pair<std::vector<NodeStatus>, std::vector<char>>;

  double force_scale(const Iterate& x) const {
    return std::max(
        {x.lambda.size() > 0 ? x.lambda.cwiseAbs().maxCoeff() : 0.0, setup_.load_force, 1e-300});
  }

  // Phase 1, the predictor: the last converged multipliers (plus the extrapolated change of the
  // last increment) against the new loads, classified.
  void predict() {
    const double extrapolation = state_.started ? options_.extrapolation : 0.0;
    at_.lambda.resize(3 * m_);
    for (int j = 0; j < m_; ++j)
      at_.lambda.segment<3>(3 * j) =
          state_.nodes[j].lambda + extrapolation * state_.nodes[j].dlambda;
    at_.alpha = state_.alpha + extrapolation * state_.dalpha;
    // The fluid's zone starts where the last increment left it.
    if (!system_.fluid.empty())
      for (int j = 0; j < m_; ++j) zone_.push_back(state_.nodes[j].penetrated ? 1 : 0);
    loads_ = loads_with_fluid(system_, zone_);
    at_.d = displacements(system_, loads_, at_);
    const bool trust_predictor = state_.started || k_ == 0;
    status_ = predicted_statuses(trust_predictor, extrapolation);
    bool elastic_trial = extrapolation == 0.0;
    if (trust_predictor && extrapolation > 0.0 && predictor_overshoots()) {
      elastic_trial = true;
      stick_slipping_frictional_nodes();
    }
    // From the elastic trial (everything closed sticks) the slip front can only advance; from an
    // extrapolated predictor it may have to move either way.
    from_elastic_trial_ = elastic_trial;
    closed_touching_ = !trust_predictor;
    seen_.emplace_back(status_, zone_);
    seen_residuals_.push_back(std::numeric_limits<double>::infinity());
  }

  std::vector<NodeStatus> predicted_statuses(bool trust_predictor, double extrapolation) const {
    std::vector<NodeStatus> status(m_);
    const double eps = 1e-12 * force_scale(at_);
    for (int j = 0; j < m_; ++j) {
      if (!trust_predictor) {
        // A body held only by contact has no meaningful displacement before some contact
        // closes: start from every touching node closed and sticking.
        status[j] = constraints_[j].gap0 <= 0.0 ? NodeStatus::Stick : NodeStatus::Open;
        continue;
      }
      status[j] = classify(point_of(constraints_[j], setup_, j, at_.lambda.segment<3>(3 * j),
                                    at_.d.segment<3>(3 * j), state_.nodes[j].d_ref, eps));
      // Without an extrapolated change (a step's start, or the first increment) the first solve
      // is the elastic trial: every closed frictional node sticks, which fixes the bodies held
      // by contact and gives each node the tangential force a stuck state would need; the
      // classification then returns the nodes beyond the cone to slip, with that force's
      // direction (return mapping). Trial slip directions from frozen multipliers instead are
      // arbitrary where a body held by friction moves under a new load.
      if (extrapolation == 0.0 && status[j] == NodeStatus::Slip &&
          constraints_[j].law.has_tangential())
        status[j] = NodeStatus::Stick;
    }
    return status;
  }

  // An extrapolated predictor that sends every closed frictional node to slip while the last
  // increment had sticking nodes overshoots the front (the change of the last increment
  // continued). Measured on model B's sector turned by a prescribed angle: from such a predictor
  // the iteration stalled (3 x 50 iterations and three cut-backs in the second increment); from
  // the elastic trial it converges in 5.
  bool predictor_overshoots() const {
    int closed_frictional = 0, sticking = 0, stuck_before = 0;
    for (int j = 0; j < m_; ++j) {
      if (!constraints_[j].law.has_tangential()) continue;
      stuck_before += state_.nodes[j].status == NodeStatus::Stick ? 1 : 0;
      if (status_[j] == NodeStatus::Open) continue;
      ++closed_frictional;
      sticking += status_[j] == NodeStatus::Stick ? 1 : 0;
    }
    return closed_frictional > 0 && sticking == 0 && stuck_before > 0;
  }

  void stick_slipping_frictional_nodes() {
    for (int j = 0; j < m_; ++j)
      if (status_[j] == NodeStatus::Slip && constraints_[j].law.has_tangential())
        status_[j] = NodeStatus::Stick;
  }

  // Phase 2, one iteration: solve, classify, anticipate, follow the fluid, judge.
  Step iterate(int iteration) {
    Iterate next;
    bool regularised = false;
    const int reused_before = factor_.reused;
    const Step solved = solve_step(next, regularised);
    if (solved != Step::next) return solved;
    if (damping_ < 1.0) {
      next.lambda = at_.lambda + damping_ * (next.lambda - at_.lambda);
      next.alpha = at_.alpha + damping_ * (next.alpha - at_.alpha);
      next.d = displacements(system_, loads_, next);
    }
    const int sweeps = front_predicted_ ? 0 : predict_front(next);
    IterationRecord record;
    record.iteration = iteration;
    record.damping = damping_;
    record.regularised = regularised;
    record.reused_factor = factor_.reused > reused_before;
    record.sweeps = sweeps;
    const double scale = force_scale(next);
    std::vector<NodeStatus> new_status;
    std::vector<int> changed = classify_iterate(next, scale, new_status, record.residual);
    record.residual /= scale;
    // A Newton step solved by refinement should cut the residual by far more than 10x near the
    // solution; when it does not, the refined solve's accuracy may be what limits it.
    factor_.refine_next = !(record.reused_factor && !outcome_.history.empty() &&
                            record.residual > 0.1 * outcome_.history.back().residual);
    const std::vector<int> anticipated = anticipate(iteration, next, changed, new_status);
    changed.insert(changed.end(), anticipated.begin(), anticipated.end());
    record.anticipated = static_cast<int>(anticipated.size());
    count_statuses(new_status, record);
    // The fluid's zone follows the contact state: a moved front is a change like a status's.
    std::vector<char> new_zone = penetrated_zone(system_.fluid, new_status, next.lambda);
    int zone_changes = 0;
    for (std::size_t j = 0; j < new_zone.size(); ++j) {
      zone_changes += new_zone[j] != zone_[j] ? 1 : 0;
      record.penetrated += new_zone[j];
    }
    record.changes = static_cast<int>(changed.size()) + zone_changes;
    const bool converged =
        judge(record, changed.empty() && zone_changes == 0, new_status, new_zone);
    outcome_.history.push_back(record);
    if (log_) log_(record);
    if (!converged && no_exponential_equilibrium(record, next, new_status)) return Step::failed;
    changed_history_.push_back(changed);
    seen_.emplace_back(new_status, new_zone);
    seen_residuals_.push_back(record.residual);
    advance(std::move(next), std::move(new_status), std::move(new_zone), zone_changes > 0);
    if (options_.anticipate_on_cone) linearise_on_cone(anticipated);
    return converged ? Step::converged : Step::next;
  }

  // The front predictor (ActiveSetOptions::predictor_sweeps) on the elastic trial's solution:
  // Gauss-Seidel sweeps on d = d0 - S lambda move the stick/slip front and the multipliers
  // towards the solution, and the classification then starts the Newton steps from there. Only
  // where S is held, no body is held by contact alone (the sweeps do not move the rigid motions)
  // and every law is linear (the sweeps' projections solve a node's normal row exactly only
  // there); no fluid (its zone follows the Newton iterate). Returns the sweeps run.
  int predict_front(Iterate& next) {
    front_predicted_ = true;
    if (options_.predictor_sweeps <= 0 || !from_elastic_trial_ || k_ != 0 ||
        system_.S.size() == 0 || !system_.fluid.empty() || nonlinear_springs_ || damping_ < 1.0)
      return 0;
    for (const ContactConstraint& c : constraints_)
      if (c.bonded) return 0;
    Iterate swept = next;
    const int sweeps =
        gauss_seidel_sweeps(constraints_, system_, setup_, state_.nodes, 1e-12 * force_scale(next),
                            options_.predictor_sweeps, options_.predictor_settled_sweeps, swept);
    if (!swept.lambda.allFinite() || !swept.d.allFinite()) return 0;
    next = std::move(swept);
    return sweeps;
  }

  // The EXPONENTIAL law carries at least A p0 / 100 on a closed node (its force at the clearance
  // c0) and nothing beyond c0. A node the structure presses towards the master with less than
  // that has no equilibrium: the spring pushes it beyond c0, where nothing holds it off. Such a
  // node stays below the least force under the law's tangent there (spring_tangent), the iterate
  // standing still with a residual; twice in a row with no status change is the signature (a node
  // on its way to a root above the least force leaves the band in one step). CalculiX diverges on
  // such a deck ("too many cutbacks"); the increment fails here naming the nodes.
  bool no_exponential_equilibrium(const IterationRecord& record, const Iterate& next,
                                  const std::vector<NodeStatus>& new_status) {
    std::vector<int> below;
    if (record.changes == 0 && damping_ == 1.0)
      for (int j = 0; j < m_; ++j) {
        const double least = constraints_[j].exponential_force0 / 100.0;
        if (least > 0.0 && status_[j] != NodeStatus::Open && new_status[j] != NodeStatus::Open &&
            at_.lambda[3 * j] <= least && next.lambda[3 * j] < least * (1.0 - 1e-9))
          below.push_back(j);
      }
    exponential_stalls_ = below.empty() ? 0 : exponential_stalls_ + 1;
    if (exponential_stalls_ < 2) return false;
    outcome_.reason =
        "the EXPONENTIAL pressure-overclosure law has no equilibrium: " +
        std::to_string(below.size()) +
        " slave node(s) are pressed towards the master with less than the law's least force "
        "A p0 / 100 (its force at the clearance c0, beyond which it carries nothing); raise the "
        "load or lower p0, or use LINEAR or HARD";
    outcome_.offending = below;
    outcome_.offending_role = "nodes below the least force";
    outcome_.no_equilibrium = true;
    return true;
  }

  // The linearised solve of the current statuses. A body held by slipping nodes alone: either
  // the load exceeds what friction can carry (a genuine loss of equilibrium: stop here, the
  // driver reports it) or the iterate is merely far from the stick zone the solution has: take
  // the step with the slip springs (LocalPoint::proximal), which give the body a stiffness along
  // the slip.
  Step solve_step(Iterate& next, bool& regularised) {
    const double eps = 1e-12 * force_scale(at_);
    const BodyHold hold =
        body_hold(constraints_, system_, loads_, setup_, status_, at_, state_.nodes, options_);
    if (hold.loss.lost) {
      outcome_.loss = hold.loss;
      outcome_.reason = "friction capacity exceeded";
      return Step::failed;
    }
    regularised = hold.slip_only;
    bool solved =
        solve_linearised(constraints_, system_, loads_, setup_, status_, at_, state_.nodes, eps,
                         regularised ? options_.slip_spring : 0.0, options_, &factor_, next);
    if (!solved && !regularised && any_slipping(status_)) {
      // Singular for another reason (e.g. slip directions that leave a rotation free).
      regularised = true;
      solved = solve_linearised(constraints_, system_, loads_, setup_, status_, at_, state_.nodes,
                                eps, options_.slip_spring, options_, &factor_, next);
    }
    if (solved) return Step::next;
    if (!closed_touching_) {
      // Close every touching node once and try again before giving up.
      closed_touching_ = true;
      for (int j = 0; j < m_; ++j)
        if (status_[j] == NodeStatus::Open && constraints_[j].gap0 <= 0.0)
          status_[j] = NodeStatus::Stick;
      return Step::retry;
    }
    outcome_.reason =
        "the closed contact constraints do not hold the bodies supported only by "
        "contact (singular contact system)";
    return Step::failed;
  }

  // The exact classification of `next`: its statuses, the nodes whose status changed and the
  // largest complementarity residual (force units).
  std::vector<int> classify_iterate(const Iterate& next, double scale,
                                    std::vector<NodeStatus>& new_status, double& residual) const {
    new_status.assign(m_, NodeStatus::Open);
    std::vector<int> changed;
    residual = 0.0;
    for (int j = 0; j < m_; ++j) {
      const LocalPoint p = point_of(constraints_[j], setup_, j, next.lambda.segment<3>(3 * j),
                                    next.d.segment<3>(3 * j), state_.nodes[j].d_ref, 1e-12 * scale);
      new_status[j] = classify(p);
      residual = std::max(residual, complementarity_residual(p).cwiseAbs().maxCoeff());
      if (new_status[j] != status_[j]) changed.push_back(j);
    }
    return changed;
  }

  // Slip-front anticipation (ActiveSetOptions::front_lookahead). Once a node has come back from
  // slip to stick well inside the cone the front has found its place: anticipating further would
  // only make the nodes at the front flip. A node back at the kink does not end it
  // (ActiveSetOptions::front_kink_band). Not in the first iteration either (the growth from the
  // predictor, the last step's solution, to the trial is the load step's, not the front's), nor
  // after a damped step or from an extrapolated predictor: both cost the builder's shrink-fit
  // model A iterations.
  std::vector<int> anticipate(int iteration, const Iterate& next, const std::vector<int>& changed,
                              std::vector<NodeStatus>& new_status) {
    std::size_t at_kink = 0;
    for (int j : changed) {
      if (status_[j] != NodeStatus::Slip || new_status[j] != NodeStatus::Stick) continue;
      const LocalPoint p = point_of(constraints_[j], setup_, j, next.lambda.segment<3>(3 * j),
                                    next.d.segment<3>(3 * j), state_.nodes[j].d_ref, 0.0);
      if (cone_ratio(p) > 1.0 - options_.front_kink_band)
        ++at_kink;
      else
        front_receded_ = true;
    }
    if (damping_ < 1.0 || front_receded_ || !from_elastic_trial_ || iteration == 1) return {};
    return anticipate_front(constraints_, setup_, status_, at_, next, options_.front_lookahead,
                            at_kink, new_status);
  }

  // The nodes just sent ahead of the front are linearised for slip with their tangential
  // multipliers on the cone (ActiveSetOptions::anticipate_on_cone). Only the linearisation point
  // moves: at_.d stays (every other node's rows see the same displacements), and the trial
  // traction keeps its direction, so the check of bodies held by friction (body_hold.cpp) sees
  // the same slip directions.
  void linearise_on_cone(const std::vector<int>& nodes) {
    for (int j : nodes) {
      const LocalPoint p = point_of(constraints_[j], setup_, j, at_.lambda.segment<3>(3 * j),
                                    at_.d.segment<3>(3 * j), state_.nodes[j].d_ref, 0.0);
      const Eigen::Vector2d on_cone = traction_on_cone(p);
      for (int c = 1; c < 3; ++c)
        if (p.live[c]) at_.lambda[3 * j + c] = on_cone[c - 1] - p.c_t * (p.d[c] - p.d_ref[c]);
    }
  }

  static void count_statuses(const std::vector<NodeStatus>& status, IterationRecord& record) {
    for (NodeStatus s : status) {
      switch (s) {
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
  }

  // Converged when nothing changed and the residual is within the tolerance, after a full step.
  // A status set seen before means the iteration cycles: shorter steps break the cycle.
  bool judge(IterationRecord& record, bool unchanged, const std::vector<NodeStatus>& new_status,
             const std::vector<char>& new_zone) {
    const bool settled = unchanged && record.residual <= options_.tolerance;
    if (settled && damping_ < 1.0) {
      // A damped step is only near the solution of its status set: one full step more makes it
      // exact.
      damping_ = 1.0;
      return false;
    }
    if (!settled && unchanged && damping_ < 1.0 && full_step_allowed_ &&
        options_.full_step_on_steady_statuses) {
      // The damped step changed no status: Newton on that set, near its solution, converges
      // quadratically with full steps; damped ones only cut the residual by 1 - damping each.
      damped_level_ = damping_;
      damping_ = 1.0;
      return false;
    }
    if (!settled && record.changes > 0 && revisits_without_progress(record, new_status, new_zone)) {
      record.cycle = true;
      // A full step taken early that led back into a cycle: damped steps to the end, halved from
      // the level they had.
      if (damped_level_ < 1.0) full_step_allowed_ = false;
      damping_ = std::max(std::min(damping_, damped_level_) * options_.cycle_damping,
                          options_.min_damping);
    }
    return settled;
  }

  // A status set seen before in the increment: with linear laws the same set gives the same
  // iterate, so the iteration cycles. An EXPONENTIAL law's rows depend on the iterate as well: a
  // node sent open by a Newton step from above its root (the tangent there is stiff) closes again
  // at a new linearisation point, progress rather than a cycle; it counts as one only when the
  // residual has not fallen since the set's last visit (the two-step deck of
  // tests/unit/contact/exponential_cli_test.cpp: 29 iterations with damping, 8 without).
  bool revisits_without_progress(const IterationRecord& record,
                                 const std::vector<NodeStatus>& new_status,
                                 const std::vector<char>& new_zone) const {
    const auto seen = std::find(seen_.rbegin(), seen_.rend(), Seen{new_status, new_zone});
    if (seen == seen_.rend()) return false;
    if (!nonlinear_springs_) return true;
    const std::size_t visit = seen_.size() - 1 - static_cast<std::size_t>(seen - seen_.rbegin());
    return record.residual >= seen_residuals_[visit];
  }

  void advance(Iterate next, std::vector<NodeStatus> new_status, std::vector<char> new_zone,
               bool zone_moved) {
    at_ = std::move(next);
    status_ = std::move(new_status);
    if (zone_moved) {
      zone_ = std::move(new_zone);
      loads_ = loads_with_fluid(system_, zone_);
      at_.d = displacements(system_, loads_, at_);
    }
  }

  // Phase 3 on convergence: the state advances (reference displacements of the friction law,
  // accumulated slip, the predictor's changes).
  void commit() {
    for (int j = 0; j < m_; ++j) {
      ConstraintState& s = state_.nodes[j];
      s.status = status_[j];
      s.dlambda = at_.lambda.segment<3>(3 * j) - s.lambda;
      s.lambda = at_.lambda.segment<3>(3 * j);
      s.d = at_.d.segment<3>(3 * j);
      if (s.status != NodeStatus::Open)
        for (int c = 1; c < 3; ++c)
          if (setup_.live[j][c]) s.slip[c - 1] += (s.d[c] - s.d_ref[c]) / constraints_[j].scale(c);
      s.d_ref = s.d;
      s.penetrated = !zone_.empty() && zone_[j] != 0;
      s.fluid = s.penetrated ? system_.fluid.force[j] : 0.0;
    }
    state_.dalpha = at_.alpha - state_.alpha;
    state_.alpha = at_.alpha;
    state_.started = true;
  }

  // Phase 3 at the cap: the reason and the nodes whose status changed in the last four
  // iterations.
  // Neither the residual nor the fluid's penetrated zone has reached a new extreme for
  // ActiveSetOptions::stagnation_iterations iterations: a new low of the residual, or a zone larger
  // than ever in the increment, is progress. The zone grows by the nodes it reaches and is bounded
  // by the closed nodes, so its growth is finite progress even while the residual wavers (SPEC 4.6
  // flange with the ring 30 thick, default mesh, at 6.5 MPa: the zone grows by one node per
  // iteration from 226 to 238 in iterations 1-13, the residual 3.3e-3 ... 1.1e-2, then 1.2e-15).
  bool stagnated() const {
    const std::vector<IterationRecord>& history = outcome_.history;
    const auto window = static_cast<std::size_t>(std::max(options_.stagnation_iterations, 1));
    if (options_.stagnation_iterations <= 0 || history.size() <= window) return false;
    double before = std::numeric_limits<double>::infinity();
    int zone_before = 0;
    for (std::size_t i = 0; i + window < history.size(); ++i) {
      before = std::min(before, history[i].residual);
      zone_before = std::max(zone_before, history[i].penetrated);
    }
    for (std::size_t i = history.size() - window; i < history.size(); ++i)
      if (history[i].residual < before || history[i].penetrated > zone_before) return false;
    return true;
  }

  void report_no_convergence() {
    char residual[32];
    std::snprintf(residual, sizeof residual, "%.2e",
                  outcome_.history.empty() ? 0.0 : outcome_.history.back().residual);
    outcome_.reason = outcome_.iterations < options_.max_iterations
                          ? "no progress in the last " +
                                std::to_string(options_.stagnation_iterations) +
                                " iterations (last residual " + residual + ")"
                          : "no convergence in " + std::to_string(options_.max_iterations) +
                                " iterations (last residual " + residual + ")";
    std::set<int> offending;
    const std::size_t last = changed_history_.size();
    for (std::size_t i = last > 4 ? last - 4 : 0; i < last; ++i)
      offending.insert(changed_history_[i].begin(), changed_history_[i].end());
    outcome_.offending.assign(offending.begin(), offending.end());
  }

  const std::vector<ContactConstraint>& constraints_;
  const LinearContactSystem& system_;
  ContactState& state_;  // the last converged increment; advanced only by commit()
  const ActiveSetOptions& options_;
  const std::function<void(const IterationRecord&)>& log_;
  const int m_, k_;
  Setup setup_;
  Loads loads_;                         // with the fluid forces of zone_
  Iterate at_;                          // the current iterate
  std::vector<NodeStatus> status_;      // the statuses the next solve uses
  std::vector<char> zone_;              // the fluid's penetrated zone (empty without fluid)
  std::vector<Seen> seen_;              // status sets of this increment, for cycle detection
  std::vector<double> seen_residuals_;  // the residual each of them ended with (predictor: inf)
  bool nonlinear_springs_ = false;      // some constraint has the EXPONENTIAL law
  std::vector<std::vector<int>> changed_history_;
  IncrementOutcome outcome_;
  double damping_ = 1.0;             // step length (< 1 after a cycle)
  double damped_level_ = 1.0;        // the step length before an early full step (judge)
  bool full_step_allowed_ = true;    // no early full step has led back into a cycle
  bool from_elastic_trial_ = false;  // the increment started from the elastic trial
  bool front_receded_ = false;       // some node went from slip back to stick
  bool front_predicted_ = false;     // the front predictor has had its turn (the first solve)
  bool closed_touching_ = false;     // the touching nodes have been closed after a singular solve
  int exponential_stalls_ = 0;       // iterations in a row with nodes below the least force
  LinearisedFactor factor_;          // the last large linearised system's factor, for reuse
};

}  // namespace

IncrementOutcome solve_increment(const std::vector<ContactConstraint>& constraints,
                                 const LinearContactSystem& system, ContactState& state,
                                 const ActiveSetOptions& options,
                                 const std::function<void(const IterationRecord&)>& log) {
  return IncrementIteration(constraints, system, state, options, log).run();
}

}  // namespace styk::contact
