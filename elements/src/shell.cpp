// The shell element types: names, node layout, shape functions and rules. The mechanics
// (kinematics, stiffness, loads, stresses, section forces) is in shell_mechanics.cpp.
#include "styk/elements/shell.hpp"

#include <Eigen/Dense>

#include "shell_kinematics.hpp"
#include "styk/elements/quad_shapes.hpp"

namespace styk {
namespace {

struct TypeInfo {
  const char* name;
  int nodes;
  bool reduced_name;  // the name fixes the reduced rule
};

TypeInfo info(ShellType type) {
  switch (type) {
    case ShellType::S4:
      return {"S4", 4, false};
    case ShellType::S4R:
      return {"S4R", 4, true};
    case ShellType::S8:
      return {"S8", 8, false};
    case ShellType::S8R:
      return {"S8R", 8, true};
    case ShellType::S9:
      return {"S9", 9, false};
    case ShellType::S9R:
      return {"S9R", 9, true};
  }
  return {"?", 4, false};
}

// The 9-node Lagrange quadrilateral: products of the 1D quadratic functions; nodes in the
// Abaqus order (corners, mid-edges, centre).
void quad9_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const auto l = [](int k, double x) {
    return k == 0 ? 0.5 * x * (x - 1.0) : k == 1 ? 1.0 - x * x : 0.5 * x * (x + 1.0);
  };
  const auto dl = [](int k, double x) { return k == 0 ? x - 0.5 : k == 1 ? -2.0 * x : x + 0.5; };
  // (index along xi, index along eta) of each node: 0 at -1, 1 at 0, 2 at +1.
  static const int ix[9] = {0, 2, 2, 0, 1, 2, 1, 0, 1};
  static const int iy[9] = {0, 0, 2, 2, 0, 1, 2, 1, 1};
  dN.setZero();
  for (int a = 0; a < 9; ++a) {
    N(a) = l(ix[a], xi[0]) * l(iy[a], xi[1]);
    dN(a, 0) = dl(ix[a], xi[0]) * l(iy[a], xi[1]);
    dN(a, 1) = l(ix[a], xi[0]) * dl(iy[a], xi[1]);
  }
}

}  // namespace

Shell::Shell(ShellType type) : type_(type) {
  nodes_ = info(type).nodes == 4 ? quad4_natural_nodes() : quad8_natural_nodes();
  if (info(type).nodes == 9) nodes_.push_back({0.0, 0.0, 0.0});
}

std::string Shell::name() const { return info(type_).name; }

std::string Shell::description() const {
  const int n = node_count();
  if (n == 4)
    return std::string(
               "4-node Reissner-Mindlin shell, 2x2 Gauss with assumed transverse shear "
               "(MITC4)") +
           (type_ == ShellType::S4R ? "; the CalculiX name, same element as S4" : "");
  const std::string kind = n == 8 ? "8-node serendipity" : "9-node Lagrange";
  if (info(type_).reduced_name) return kind + " Reissner-Mindlin shell, 2x2 Gauss (reduced)";
  return kind + " Reissner-Mindlin shell, 3x3 Gauss (full)" +
         (n == 9 ? "; Styk's name (CalculiX has no 9-node shell)" : "");
}

int Shell::surface_order(RuleKind kind) const {
  if (node_count() == 4) return 2;
  return kind == RuleKind::Full && !info(type_).reduced_name ? 3 : 2;
}

void Shell::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  switch (node_count()) {
    case 4:
      quad4_shape(xi, N, dN);
      return;
    case 8:
      quad8_shape(xi, N, dN);
      return;
    default:
      quad9_shape(xi, N, dN);
  }
}

IntegrationRule Shell::rule(RuleKind kind) const {
  const int n = surface_order(kind);
  return shell_detail::with_fibres(quad_gauss_rule(n),
                                   std::to_string(n) + "x" + std::to_string(n) +
                                       " Gauss in the surface x bottom, middle and top fibre");
}

int Shell::section_stations(RuleKind kind) const {
  const int n = surface_order(kind);
  return n * n;
}

double Shell::point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>&,
                            const Eigen::Ref<const Eigen::MatrixXd>& dN,
                            Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  return shell_detail::surface_point_measure(
      *this, g, dN, dNdx, point, "degenerate surface (its tangents are parallel or zero)");
}

}  // namespace styk
