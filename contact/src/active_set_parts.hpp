// The pieces the active-set iteration (active_set.cpp) is made of: the per-constraint constants of
// one linear contact system, the iterate, the loads the contacts feel, the linearised solve
// (linearised_step.cpp) and the check of bodies held by friction alone (body_hold.cpp).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "dense_lu.hpp"
#include "styk/contact/active_set.hpp"

namespace styk::contact::active_set_detail {

// Per-constraint constants of one linear system: which components can carry force and the
// complementarity parameters (the inverse self-compliance, so c d has force units and the
// iteration does not depend on the units of the model).
struct Setup {
  std::vector<std::array<bool, 3>> live;
  std::vector<double> c_n, c_t;
  double load_force = 0.0;  // force scale of the loading as the contacts feel it
};

Setup set_up(const std::vector<ContactConstraint>& constraints, const LinearContactSystem& system,
             const ActiveSetOptions& options);

LocalPoint point_of(const ContactConstraint& constraint, const Setup& setup, int k,
                    const Eigen::Vector3d& lambda, const Eigen::Vector3d& d,
                    const Eigen::Vector3d& d_ref, double eps, double proximal = 0.0);

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

Loads loads_with_fluid(const LinearContactSystem& system, const std::vector<char>& penetrated);

Eigen::VectorXd displacements(const LinearContactSystem& system, const Loads& loads,
                              const Iterate& x);

// S's diagonal block of constraint j and S v, from S or from the structure operator.
Eigen::Matrix3d compliance_block(const LinearContactSystem& system, int j);
Eigen::VectorXd compliance_times(const LinearContactSystem& system, const Eigen::VectorXd& v);

// The factor of the last linearised system an increment solved, which later iterations try
// first (ActiveSetOptions::reuse_factor_size): while the closed set keeps its unknowns and few
// statuses change, the system changes little, and GMRES preconditioned with the old factor
// replaces a new factorisation (DenseLu::solve_by_krylov).
struct LinearisedFactor {
  std::vector<int> unknowns;         // of the factorised system
  std::vector<NodeStatus> statuses;  // under which it was linearised
  std::unique_ptr<contact_detail::DenseLu> lu;
  // Off after an iteration solved with the old factor failed to lower the contact residual
  // tenfold: near the tolerance that solve's backward error (within sqrt(n) eps of a direct
  // one's, not equal to it) can be what stalls the iteration, so the next solve factorises.
  bool refine_next = true;
  int reused = 0;  // solves served by an older factor
};

// Solves the linearised conditions of `status` at `at` (slip rows with the proximal weight, see
// LocalPoint::proximal). Returns false when the system is singular (a body held only by contact is
// not held by the closed constraints). `factor` (may be null) is the increment's reusable factor.
bool solve_linearised(const std::vector<ContactConstraint>& constraints,
                      const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                      const std::vector<NodeStatus>& status, const Iterate& at,
                      const std::vector<ConstraintState>& previous, double eps, double proximal,
                      const ActiveSetOptions& options, LinearisedFactor* factor, Iterate& out);

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

BodyHold body_hold(const std::vector<ContactConstraint>& constraints,
                   const LinearContactSystem& system, const Loads& loads, const Setup& setup,
                   const std::vector<NodeStatus>& status, const Iterate& at,
                   const std::vector<ConstraintState>& previous, const ActiveSetOptions& options);

// Nonsmooth block Gauss-Seidel sweeps on d = d0 - S lambda from `x` (S held densely, no bodies
// held by contact alone), until the statuses are unchanged over `settled_sweeps` sweeps or
// `max_sweeps` have run. Returns the sweeps run; `x` holds their multipliers and displacements.
int gauss_seidel_sweeps(const std::vector<ContactConstraint>& constraints,
                        const LinearContactSystem& system, const Setup& setup,
                        const std::vector<ConstraintState>& previous, double eps, int max_sweeps,
                        int settled_sweeps, Iterate& x);

}  // namespace styk::contact::active_set_detail
