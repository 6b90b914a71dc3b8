// The complementarity conditions of one contact constraint (hard contact + Coulomb friction) and
// their semi-smooth Newton linearisation, after Hueber, Stadler and Wohlmuth (SIAM J. Sci. Comput.
// 30, 2008). Everything is in the generalised variables of ContactConstraint::row(): component 0
// is normal, 1 and 2 tangential scaled by mu, so the friction cone is the unit-slope cone
// |lambda_t| <= lambda_n for every law (elliptic anisotropy included).
//
// With b = lambda_n + c_n (d_n - gap0) and xi = lambda_t + c_t (d_t - d_t_ref):
//   open  (b <= 0):            lambda = 0
//   stick (b > 0, |xi| <= b):  d_n = gap0, d_t = d_t_ref          (tied: always stick)
//   slip  (b > 0, |xi| > b):   d_n = gap0, F_t = lambda_t - b xi / |xi| = 0
// A penalty law (penalty_law.hpp) puts a spring in series: the closed conditions become
// d_n - gap0 = H(lambda_n) (the overclosure that carries lambda_n) and
// b = lambda_n + c_n (d_n - gap0 - H(lambda_n)); with H = 0 they are the exact ones. LINEAR:
// H = e lambda_n, e = 1 / (K A). EXPONENTIAL: H = (1/beta) ln(lambda_n / (A p0)), no less than -c0
// (spring_overclosure). A bonded (TIED) node is closed for good, with springs in all three
// directions: d = gap0 n + e lambda.
// c_n, c_t > 0 are complementarity parameters (force per length; any positive values give the same
// solution, they only steer the iteration). b > eps counts as closed (eps >= 0 absorbs round-off).
#pragma once

#include <array>

#include <Eigen/Core>

namespace styk::contact {

enum class NodeStatus { Open = 0, Stick = 1, Slip = 2 };
const char* status_name(NodeStatus status);

// One constraint at an iterate.
struct LocalPoint {
  Eigen::Vector3d lambda = Eigen::Vector3d::Zero();  // (lambda_n, lambda_t1, lambda_t2)
  Eigen::Vector3d d = Eigen::Vector3d::Zero();       // generalised displacement now
  Eigen::Vector3d d_ref = Eigen::Vector3d::Zero();   // ... at the last converged increment
  double gap0 = 0.0;
  double c_n = 1.0;
  double c_t = 1.0;
  double eps = 0.0;
  std::array<bool, 3> live{true, false, false};  // components taking part
  bool tied = false;                             // no slip
  double compliance = 0.0;  // penalty spring 1 / (K A), length per force (0: exact contact)
  // EXPONENTIAL penalty law: the force A p0 at zero clearance (0: not exponential) and the decay
  // beta = ln(100) / c0 (per length).
  double exponential_force0 = 0.0;
  double exponential_beta = 0.0;
  bool bonded = false;      // TIED penalty law: never opens, springs in all directions
  bool frictional = false;  // the law has friction (a closed node whose tangential components
                            // are all held by supports then sticks; frictionless ones slide)
  // Proximal weight gamma >= 0 of the slip rows (0: the exact tangent). The exact tangent of a
  // slipping node does not depend on the displacement along the slip direction e, so a body held
  // only by slipping nodes has no stiffness along it and the linearised system is singular. With
  // gamma > 0 the rows get -gamma c_t e e^T (d_t_new - d_t) on the left: a spring of stiffness
  // gamma c_t along e, relative to the current iterate. Only the Jacobian changes, not the
  // residual, so a converged iterate still satisfies the law exactly.
  double proximal = 0.0;
};

NodeStatus classify(const LocalPoint& point);

// The overclosure d_n - gap0 that the normal force lambda_n of a closed node needs, H(lambda_n):
// 0 for exact contact, e lambda_n for a linear spring, (1/beta) ln(lambda_n / (A p0)) for the
// exponential law. Below the exponential law's least force A p0 / 100 (at the clearance c0) it is
// -c0: such a node rests at the clearance (the law has no equilibrium there; the iteration
// reports it, active_set.cpp).
double spring_overclosure(const LocalPoint& point, double lambda_n);

// H linearised at the iterate's lambda_n: H ~ offset + compliance lambda_n. Linear and exact laws:
// their own e and 0. Exponential: the tangent at max(lambda_n, A p0 / 100), compliance
// 1 / (beta lambda_n). H is concave, so Newton steps approach a root >= A p0 / 100 from below
// monotonically once below it.
struct SpringTangent {
  double compliance = 0.0;
  double offset = 0.0;
};
SpringTangent spring_tangent(const LocalPoint& point);

// The exponential law's least force A p0 / 100 (0 for the other laws).
double exponential_least_force(const LocalPoint& point);

// The linearised equations Q d_new + D lambda_new = r (3 rows: normal, t1, t2) of the node for
// `status` at `point`. Rows of components that are not live are lambda_c = 0.
struct LocalRows {
  Eigen::Matrix3d Q = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
};
LocalRows linearise(const LocalPoint& point, NodeStatus status);

// The slip-branch function F_t(lambda, d) = lambda_t - b xi / |xi| (2 components, t1, t2) whose
// exact derivative linearise() uses for a slipping node (exposed for the finite-difference test).
// (The polynomial form |xi| lambda_t - b xi of Hueber et al. has the same roots, but its Newton
// steps only halve the error far from the cone, where a node arrives after leaving stick.)
Eigen::Vector2d slip_function(const LocalPoint& point);

// |xi| / b: the trial traction over the cone's radius at a closed node with tangential
// components (classify() says slip above 1, stick at or below it); 0 when the node is open, tied,
// bonded or has no tangential component. Near 1 a node sits at the law's kink, where both the
// stick and the slip rows are valid linearisations (active_set.cpp, the slip-front anticipation).
double cone_ratio(const LocalPoint& point);

// The return mapping of the trial traction onto the cone: b xi / |xi| (t1, t2; components that do
// not take part 0). A slip row linearised at a point inside the cone has beta = b / |xi| > 1, which
// turns the sign of its cross-slip coupling (I - beta P); at this point it is the kink's slip
// element. Zero when cone_ratio() is 0 or xi = 0.
Eigen::Vector2d traction_on_cone(const LocalPoint& point);

// Residual of the complementarity conditions in force units: lambda - proj(lambda + c (...)),
// the projection onto R+ (normal) and onto the disk of radius max(lambda_n, 0) (tangential; an
// unbounded disk when tied and closed). Zero exactly at a solution.
Eigen::Vector3d complementarity_residual(const LocalPoint& point);

}  // namespace styk::contact
