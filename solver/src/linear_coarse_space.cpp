#include "linear_coarse_space.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <map>

#include "styk/core/element.hpp"
#include "styk/core/element_description.hpp"

namespace styk::solver_detail {
namespace {

// Weights of the linear parent's corners at natural point xi. Bricks: trilinear on corners at
// +-1; tetrahedra: the affine (barycentric) weights; wedges: barycentric on the triangle times
// linear along zeta (corners at zeta -1 then +1).
std::vector<double> parent_weights(const std::vector<Vec3>& corner, const Vec3& xi) {
  const std::size_t n = corner.size();
  std::vector<double> w(n, 0.0);
  if (n == 8) {
    for (std::size_t i = 0; i < n; ++i)
      w[i] = (1.0 + xi[0] * corner[i][0]) * (1.0 + xi[1] * corner[i][1]) *
             (1.0 + xi[2] * corner[i][2]) / 8.0;
  } else if (n == 4) {
    Eigen::Matrix4d A;
    for (int i = 0; i < 4; ++i) A.col(i) << corner[i][0], corner[i][1], corner[i][2], 1.0;
    const Eigen::Vector4d b(xi[0], xi[1], xi[2], 1.0);
    const Eigen::Vector4d x = A.fullPivLu().solve(b);
    for (int i = 0; i < 4; ++i) w[i] = x[i];
  } else if (n == 6) {
    Eigen::Matrix3d A;
    for (int i = 0; i < 3; ++i) A.col(i) << corner[i][0], corner[i][1], 1.0;
    const Eigen::Vector3d b(xi[0], xi[1], 1.0);
    const Eigen::Vector3d x = A.fullPivLu().solve(b);
    const double top = (1.0 + xi[2]) / 2.0;  // corners 3-5 lie at zeta = +1
    for (int i = 0; i < 3; ++i) {
      w[i] = x[i] * (1.0 - top);
      w[i + 3] = x[i] * top;
    }
  }
  return w;
}

// A linear parent the weights above describe: solid, 8/6/4 corners, bricks' corners at +-1 and
// wedges' top corners after the bottom ones at the same (xi, eta).
bool has_linear_parent(const TElement& type, const std::vector<int>& corners) {
  if (type.form() != ElementForm::Solid) return false;
  const std::vector<Vec3>& xi = type.natural_nodes();
  for (std::size_t i = 0; i < corners.size(); ++i)
    if (corners[i] != static_cast<int>(i)) return false;  // corners first, as Abaqus numbers
  if (corners.size() == 8) {
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d)
        if (std::abs(std::abs(xi[k][d]) - 1.0) > 1e-12) return false;
    return true;
  }
  if (corners.size() == 6) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(xi[k][0] - xi[k + 3][0]) > 1e-12 || std::abs(xi[k][1] - xi[k + 3][1]) > 1e-12 ||
          std::abs(xi[k][2] + 1.0) > 1e-12 || std::abs(xi[k + 3][2] - 1.0) > 1e-12)
        return false;
    return true;
  }
  return corners.size() == 4;
}

// Per element type, once: its corner count and, per local node, the linear parent's weights on
// the corners at the node's natural point (a corner: 1 on itself). Empty when the type has no
// linear parent the weights describe.
struct ParentTable {
  int corners = 0;
  std::vector<std::vector<double>> weights;  // per local node, per corner
};

std::optional<ParentTable> parent_table(const TElement& type) {
  const std::vector<int> corners = corner_nodes(type);
  if (!has_linear_parent(type, corners)) return std::nullopt;
  std::vector<Vec3> corner_xi;
  for (int k : corners) corner_xi.push_back(type.natural_nodes()[k]);
  ParentTable table;
  table.corners = static_cast<int>(corners.size());
  for (const Vec3& xi : type.natural_nodes())
    table.weights.push_back(parent_weights(corner_xi, xi));
  return table;
}

}  // namespace

std::optional<LinearCoarseSpace> linear_coarse_space(const Model& model,
                                                     const PreparedModel& prepared) {
  // Phase 1: the element types' tables; no coarse space unless every type has one and some type
  // has nodes beyond its corners.
  std::map<const TElement*, ParentTable> tables;
  bool quadratic = false;
  for (const TElement* type : prepared.formulation) {
    if (tables.count(type) > 0) continue;
    std::optional<ParentTable> table = parent_table(*type);
    if (!table) return std::nullopt;
    quadratic = quadratic || type->node_count() > table->corners;
    tables.emplace(type, std::move(*table));
  }
  if (!quadratic) return std::nullopt;

  // Phase 2: which active nodes are corners, and for the others one element holding them.
  const int nodes = prepared.active_nodes();
  std::vector<char> corner(nodes, 0);
  std::vector<int> owner_element(nodes, -1), local_index(nodes, -1);
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& type = *prepared.formulation[e];
    const int corners = tables.at(&type).corners;
    const int* element_nodes = model.element_nodes(e);
    for (int k = 0; k < type.node_count(); ++k) {
      const int a = prepared.active_of_node[element_nodes[k]];
      if (a < 0) continue;
      if (k < corners) {
        corner[a] = 1;
      } else if (owner_element[a] < 0) {
        owner_element[a] = e;
        local_index[a] = k;
      }
    }
  }

  // Phase 3: coarse nodes (corners, and nodes of no element) and every node's weights.
  LinearCoarseSpace space;
  std::vector<int> coarse_of(nodes, -1);
  for (int a = 0; a < nodes; ++a)
    if (corner[a] || owner_element[a] < 0) {
      coarse_of[a] = space.coarse_nodes++;
      space.corner_node.push_back(a);
    }
  space.ptr.assign(1, 0);
  for (int a = 0; a < nodes; ++a) {
    if (coarse_of[a] >= 0) {
      space.node.push_back(coarse_of[a]);
      space.weight.push_back(1.0);
    } else {
      const int e = owner_element[a];
      const ParentTable& table = tables.at(prepared.formulation[e]);
      const std::vector<double>& w = table.weights[local_index[a]];
      const int* element_nodes = model.element_nodes(e);
      for (int i = 0; i < table.corners; ++i) {
        if (std::abs(w[i]) < 1e-14) continue;
        space.node.push_back(coarse_of[prepared.active_of_node[element_nodes[i]]]);
        space.weight.push_back(w[i]);
      }
    }
    space.ptr.push_back(static_cast<int>(space.node.size()));
  }
  return space;
}

}  // namespace styk::solver_detail
