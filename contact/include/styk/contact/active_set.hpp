// The semi-smooth Newton (primal-dual active-set) iteration of one load increment.
//
// The structure is seen through a linear operator built by the solver: with lambda the
// generalised multipliers of all constraints (3 per constraint, see ContactConstraint::row) and
// alpha the rigid motions of bodies held only by contact,
//   d = d0 - S lambda + G alpha        (generalised contact displacements, 3 per constraint)
//   G^T lambda = h                     (those bodies' equilibrium)
// S = B K^-1 B^T is the contact compliance (K with the free rigid motions fixed), G = B R.
// Each iteration solves the linearised complementarity conditions (friction_law.hpp) of the
// current status set for (lambda, alpha) exactly (dense LU, or one sparse LU with K when S is too
// large to hold: structure_operator.hpp), so constraints hold to round-off.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "styk/contact/constraints.hpp"
#include "styk/contact/friction_law.hpp"
#include "styk/contact/structure_operator.hpp"

namespace styk::contact {

// Pressure penetration (docs/contact.md, "Pressure penetration"): a fluid that enters the
// interface at entry nodes and presses both faces apart wherever it reaches. On a node of the
// penetrated zone it acts as a known normal force p A (like a compressive contact force: the
// slave is pushed away from the master). The zone is found with the iterate: the nodes connected
// to an entry node through nodes that are open or whose normal force is below the critical one;
// it moves with the iteration until it is consistent with the contact state.
struct FluidPenetration {
  std::vector<double> force;     // per constraint: fluid pressure x nodal area (0: no fluid)
  std::vector<double> critical;  // per constraint: critical contact pressure x nodal area
  std::vector<std::vector<int>> neighbours;  // per constraint: constraints sharing a slave face
  std::vector<char> entry;                   // per constraint: the fluid enters here
  bool empty() const { return force.empty(); }
};

struct LinearContactSystem {
  Eigen::VectorXd d0;  // 3 m
  Eigen::MatrixXd S;   // 3 m x 3 m; columns of components that cannot carry force may be zero
  // Instead of S (then empty) for contact layers too large for it: S through the structure's
  // sparse factorisation (structure_operator.hpp).
  std::shared_ptr<StructureOperator> structure;
  // Per constraint (empty: none): the tangential components whose direction the slave node's
  // supports prescribe. A mortar row's multiplier drops them (the mortar remedy at boundaries
  // where slave and master are both held along the face: the row also reaches free interior
  // master nodes, and with the held directions kept the stuck rows over-determine the system).
  std::vector<std::array<bool, 3>> held;
  Eigen::MatrixXd G;       // 3 m x k
  Eigen::VectorXd h;       // k
  FluidPenetration fluid;  // empty: no pressure penetration
};

struct ConstraintState {
  NodeStatus status = NodeStatus::Open;
  Eigen::Vector3d lambda = Eigen::Vector3d::Zero();   // generalised multipliers
  Eigen::Vector3d d = Eigen::Vector3d::Zero();        // generalised displacement
  Eigen::Vector3d d_ref = Eigen::Vector3d::Zero();    // at the last converged increment
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();     // accumulated slip along t1, t2 (length)
  Eigen::Vector3d dlambda = Eigen::Vector3d::Zero();  // change of lambda over that increment
  bool penetrated = false;  // in the fluid's penetrated zone (pressure penetration)
  double fluid = 0.0;       // the fluid's normal force on the node (0 outside the zone)
};

// What carries over from increment to increment and from step to step.
struct ContactState {
  std::vector<ConstraintState> nodes;
  Eigen::VectorXd alpha;   // rigid motions of the bodies held by contact (k)
  Eigen::VectorXd dalpha;  // their change over the last converged increment
  bool started = false;    // an increment has converged
};

struct IterationRecord {
  int iteration = 0;
  int open = 0, stick = 0, slip = 0;
  int changes = 0;             // status changes against the status set the iteration solved with
  int penetrated = 0;          // nodes in the fluid's penetrated zone (pressure penetration)
  int anticipated = 0;         // of which sticking nodes sent to slip ahead of the front
  double residual = 0.0;       // max complementarity residual / largest multiplier
  double damping = 1.0;        // step length taken (< 1 after a cycle was detected)
  bool cycle = false;          // this status set was seen before in the increment
  bool regularised = false;    // a body was held by slipping nodes alone: solved with slip springs
  bool reused_factor = false;  // solved by refinement with an earlier iteration's factor
  int sweeps = 0;              // front predictor's Gauss-Seidel sweeps after this solve
};

// How the iteration is steered. The defaults are the measured ones (bench/contact/README.md,
// docs/contact.md); none of them changes a converged solution, only the path to it and when a
// body held by friction counts as free.
struct ActiveSetOptions {
  int max_iterations = 50;
  // An increment whose residual has not gone below its best so far, and whose fluid zone (pressure
  // penetration) has not grown beyond its largest so far, for this many iterations is given up
  // (the driver cuts it back) before max_iterations: SPEC 4.2 model B loaded past its friction
  // capacity never went below its 3rd iteration's residual in 50 iterations (3 s each). The
  // slowest converging increments measured take a new low at least every few iterations
  // (bench/contact/README.md), or have a fluid running through the interface one node per
  // iteration (SPEC 4.6 flange, ring 30 thick: 12 iterations of growth, then converged). 0: off.
  int stagnation_iterations = 12;
  double tolerance = 1e-9;  // on IterationRecord::residual
  // Predictor: the multipliers and rigid motions of the last converged increment plus this
  // multiple of their change over it (the driver passes dt_new / dt_last within a step, 0 at a
  // step's start): exact for proportional loading, a secant guess otherwise.
  double extrapolation = 0.0;
  // Front predictor, in increments that start from the elastic trial (every closed frictional
  // node sticks): the slip front has to travel from there to its place, and the Newton steps move
  // it a few node rows per linearised solve (the SPEC 3.2.3 beams: 5-18 iterations across mu).
  // After the trial's solve, nonsmooth block Gauss-Seidel sweeps on d = d0 - S lambda
  // (gauss_seidel_predictor.cpp; each a product with S, no factorisation) move the front and the
  // multipliers instead, up to `predictor_sweeps` of them (0: off) and until the statuses have
  // not changed for `predictor_settled_sweeps` sweeps; the Newton steps start from where they
  // end. The convergence check is the exact one, so the solution is unchanged. Measured on the
  // beams across 17 coefficients: 3-6 iterations (4-11 sweeps) instead of 5-18; fewer settled
  // sweeps (1, 2) left up to 8 iterations, more (6, 12, 30) 3-7 (bench/contact/README.md).
  // Only where S is held densely and no body is held by contact alone (active_set.cpp,
  // predict_front).
  int predictor_sweeps = 100;
  int predictor_settled_sweeps = 3;
  // Stick/slip front anticipation, in increments that start from the elastic trial (no
  // extrapolated predictor): while the exact classification only moves sticking nodes to
  // slip (the front advancing), a sticking node whose friction ratio |lambda_t| / lambda_n, grown
  // over the last iteration at the same rate `front_lookahead` more times, would leave the cone is
  // switched to slip already, at most as many as the front just moved (0: off). A wrong guess
  // returns to stick by the exact test, and the convergence check is the exact one, so the
  // solution is unchanged.
  double front_lookahead = 1.0;
  // A node that returns from slip to stick with its trial traction within this fraction of the
  // cone (|xi| > (1 - front_kink_band) b, friction_law.hpp cone_ratio) sits at the law's kink: its
  // backward slip is its neighbours' not yet settled slip directions, not the front finding its
  // place, so the anticipation goes on (such a node counts as a moved front node, like a swap with
  // the node that takes its place) instead of stopping for the rest of the increment. 0: every
  // return stops it. Measured on the SPEC 3.2.3 beams at mu = 10 (every return there is within
  // 0.4 % of the cone; 5e-3 and 3e-2 also give 9): 10 -> 9 iterations together with
  // anticipate_on_cone, 10 without it; the other bench/contact models unchanged.
  double front_kink_band = 1e-2;
  // A node sent to slip ahead of the front (still inside the cone) has its slip rows linearised
  // with its tangential multipliers moved onto the cone (friction_law.hpp traction_on_cone): the
  // slip element of the kink, instead of a point inside the cone where the rows' cross-slip
  // coupling changes sign. Measured on the mu = 10 beams with front_kink_band: without it the
  // statuses settle at iteration 7 and the nodes sent ahead converge slowly (residuals 9.7e-8,
  // 3.4e-8, 2.8e-13: 10 iterations); with it at iteration 6, then 3.3e-7, 1.8e-9, 8.3e-13 (9).
  // Alone (kink band 0) it gives 11. The other bench/contact models unchanged either way.
  bool anticipate_on_cone = true;
  // Proximal weight of the slip rows while a body is held by slipping nodes alone
  // (LocalPoint::proximal): springs as stiff as the nodes' own contact stiffness c_t. 0.1 and 1
  // gave the same iteration counts on the SPEC 4.2 models.
  double slip_spring = 1.0;
  // A motion of a body held by contact is a wedge (held by normal forces that grow with it, like
  // a pin pushed into a taper: no friction capacity to exceed, no slip springs) when the RMS of
  // the closing normal components at the closed nodes reaches this fraction of the RMS of the
  // whole relative motion there. A 1:10 taper gives 0.05; a cylinder's nodes stay below 1e-3
  // (the quadratic faces' normal error at symmetry-plane nodes).
  double wedge_ratio = 1e-2;
  // A motion crossing the slip directions is held by the exact slip tangent's P = I - e e^T part,
  // so it does not count as held by slipping nodes alone when the RMS of its components across
  // the slip directions reaches this fraction of its tangential RMS (model B's sector turned past
  // full slip slides axially while its nodes slip around the axis: with slip springs there, no
  // convergence in 50 iterations; 2-6 per increment without).
  double crossing_ratio = 1e-2;
  // A component whose Schur complement in the Gram matrix of its node's rows is at most this
  // fraction of its diagonal only moves what the node's other components move (a tangent on a
  // symmetry plane): it is dropped, its force going to the support. Such a row is dependent
  // exactly, so its Schur complement is round-off of S (~1e-16 of the diagonal); the margin
  // keeps genuinely independent rows of nearly parallel faces.
  double dependent_row_ratio = 1e-8;
  // After a cycle (a status set seen before in the increment) the step length is multiplied by
  // `cycle_damping`, down to `min_damping`; one full step follows once the damped iteration
  // settles.
  double cycle_damping = 0.5;
  double min_damping = 1.0 / 64.0;
  // A damped step that changes no status is followed by a full step on that status set (Newton
  // near its solution) instead of damped steps to the tolerance; if that leads back into a cycle
  // the damped steps resume, halved, to the end of the increment. Measured on the SPEC 3.2.3
  // beams at mu = 3.8: a cycle at iteration 8, then 25 damped steps halving the residual each
  // (33 iterations); with the full step 13. Same for mu = 4.2 (34 -> 12); no other bench/contact
  // model damps.
  bool full_step_on_steady_statuses = true;
  // Linearised systems of at least this many unknowns keep their LU factor, and a later
  // iteration with the same closed unknowns, whose statuses differ from the factorised ones at
  // `reuse_status_changes` nodes at most, first solves by GMRES preconditioned with that factor
  // (up to `reuse_krylov_iterations`, then refinement to a direct solve's backward error) before
  // factorising anew: the dense factorisation is cubic in the closed rows (SPEC 4.2 model B: 7206
  // unknowns, 2.2 s against ~0.03 s per GMRES iteration) and, once the status set settles,
  // Newton steps change the system little. A status change rewrites the node's rows, a rank-2
  // change GMRES resolves in about two iterations; the Newton step's new slip directions move
  // every slipping node's rows a little. Measured on model B (bench/contact/README.md): with no
  // status changed GMRES took 6-30 iterations, with 3-4 changed 10-24, with 11 or more it did not
  // converge in 30, hence the gate. The answer is the direct solve's to its backward error
  // either way. Smaller systems factorise every time: below a few thousand unknowns the LU is
  // cheap (model B's 1806-unknown sector: ~0.05 s), so reuse saves nothing, while a solve with
  // an old factor, accurate only to a direct solve's backward error, moves the active-set path
  // (measured with a threshold of 1000 there: 82 iterations against 80, and in three runs its
  // 2-rank answer 1.0e-8 to 1.4e-8 from the serial one, beyond the 1e-8 distributed runs are held
  // to; with every system factorised it stays within it).
  int reuse_factor_size = 4000;
  int reuse_status_changes = 8;
  int reuse_krylov_iterations = 30;
};

// A body held only by contact whose contacts cannot balance the load along one of its free rigid
// motions (one mode, or the direction of the unbalanced load when there are several): every
// closed node resisting it slips and the load exceeds what the friction cones (at the current
// normal forces) can carry. A genuine loss of equilibrium, not a numerical failure.
struct EquilibriumLoss {
  bool lost = false;
  Eigen::VectorXd motion;  // the rigid motion (unit combination of the columns of G, k)
  int slipping = 0;        // closed constraints resisting it, all slipping
  double applied = 0.0;    // |load along the motion - what the normal forces carry along it|
  double capacity = 0.0;   // the most the friction forces can carry along it
};

struct IncrementOutcome {
  bool converged = false;
  int iterations = 0;
  std::vector<IterationRecord> history;
  std::string reason;          // why it stopped unconverged
  std::vector<int> offending;  // constraints that changed status in the last iterations
  std::string offending_role = "nodes changing status";  // what `offending` lists
  // The contact law has no equilibrium at this load (the EXPONENTIAL law's nodes below its least
  // force): a smaller increment cannot help, the step stops here.
  bool no_equilibrium = false;
  EquilibriumLoss loss;  // set when the increment failed because equilibrium is lost
};

// Runs the iteration from `state` (the last converged increment). On convergence `state` holds
// the new solution and the increment is committed (d_ref advanced, slip accumulated); otherwise
// `state` is left as it was. `log` (may be empty) sees every iteration.
IncrementOutcome solve_increment(const std::vector<ContactConstraint>& constraints,
                                 const LinearContactSystem& system, ContactState& state,
                                 const ActiveSetOptions& options,
                                 const std::function<void(const IterationRecord&)>& log);

}  // namespace styk::contact
