// *MPC BEAM, STRAIGHT and PLANE, linearised about the undeformed geometry (CalculiX solves them
// geometrically nonlinear; for small displacements the two agree to first order in u / L):
//   BEAM (a, b):            (x_b - x_a) . (u_b - u_a) = 0
//   STRAIGHT (a, b, q...):  for each q, two directions e perpendicular to t = x_b - x_a:
//                           (u_q - u_a) . (t x e) + (u_b - u_a) . (e x (x_q - x_a)) = 0
//   PLANE (a, b, c, q...):  for each q, with n = (x_b - x_a) x (x_c - x_a):
//                           (u_q - u_a) . n + (u_b - u_a) . ((x_c - x_a) x (x_q - x_a))
//                             + (u_c - u_a) . ((x_q - x_a) x (x_b - x_a)) = 0
// the first order variations of |x_b - x_a|, (x_q - x_a) x t and (x_q - x_a) . n.
#include <Eigen/Geometry>

#include "constraint_lowering.hpp"

namespace styk::solver_detail {
namespace {

Eigen::Vector3d position(const Model& model, int node) {
  return {model.coords[node][0], model.coords[node][1], model.coords[node][2]};
}

// Two unit vectors perpendicular to t and to each other.
std::pair<Eigen::Vector3d, Eigen::Vector3d> perpendiculars(const Eigen::Vector3d& t) {
  int least = 0;
  t.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e1 = t.cross(Eigen::Vector3d::Unit(least)).normalized();
  return {e1, t.normalized().cross(e1)};
}

}  // namespace

void lower_mpcs(Model& lowered, EquationBuilder& equations) {
  for (const Mpc& mpc : lowered.mpcs) {
    const std::vector<int>& n = mpc.nodes;
    const Eigen::Vector3d xa = position(lowered, n[0]), xb = position(lowered, n[1]);
    const Eigen::Vector3d t = xb - xa;
    const double length = t.norm();
    if (!(length > 0.0))
      throw InputError(mpc.where, "*MPC: its first two nodes coincide; they define no direction");
    if (mpc.type == Mpc::Type::Beam) {
      equations.add({{n[0], -t}, {n[1], t}}, n[0], mpc.where);  // CalculiX: the first node
      continue;
    }
    if (mpc.type == Mpc::Type::Straight) {
      const auto [e1, e2] = perpendiculars(t);
      for (std::size_t k = 2; k < n.size(); ++k) {
        const Eigen::Vector3d r = position(lowered, n[k]) - xa;
        for (const Eigen::Vector3d& e : {e1, e2}) {
          const Eigen::Vector3d on_q = t.cross(e), on_b = e.cross(r);
          equations.add({{n[k], on_q}, {n[1], on_b}, {n[0], -on_q - on_b}}, n[k], mpc.where);
        }
      }
      continue;
    }
    const Eigen::Vector3d xc = position(lowered, n[2]);
    const Eigen::Vector3d normal = t.cross(xc - xa);
    if (!(normal.norm() > 1e-12 * length * (xc - xa).norm()))
      throw InputError(mpc.where,
                       "*MPC PLANE: its first three nodes lie on one line; they define "
                       "no plane");
    for (std::size_t k = 3; k < n.size(); ++k) {
      const Eigen::Vector3d r = position(lowered, n[k]) - xa;
      const Eigen::Vector3d on_b = (xc - xa).cross(r), on_c = r.cross(t);
      equations.add({{n[k], normal}, {n[1], on_b}, {n[2], on_c}, {n[0], -normal - on_b - on_c}},
                    n[k], mpc.where);
    }
  }
}

}  // namespace styk::solver_detail
