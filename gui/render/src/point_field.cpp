// Where the integration points lie (evaluate_point_field, which shares the tensor functions of the
// nodal fields, is in field.cpp).
#include "styk/render/point_field.hpp"

#include <Eigen/Core>

#include "styk/core/diagnostics.hpp"

namespace styk::render {

std::vector<Vec3> point_coordinates(const TElement& formulation) {
  return formulation.rule(RuleKind::Full).points;
}

void check_point_count(const Model& model, const PointField& field, int element,
                       std::size_t rule_points) {
  if (static_cast<std::size_t>(field.count(element)) == rule_points) return;
  throw InputError({}, "element " + std::to_string(model.elements[element].id) + " (" +
                           model.elements[element].type + ") has " +
                           std::to_string(field.count(element)) + " stored values of " +
                           field.name + ", its integration rule " + std::to_string(rule_points) +
                           " points");
}

std::vector<PointValue> element_point_values(const Model& model, const TElement& formulation,
                                             const PointField& field, int element) {
  const std::vector<Vec3> points = point_coordinates(formulation);
  check_point_count(model, field, element, points.size());
  const int* conn = model.element_nodes(element);
  std::vector<Vec3> nodes(static_cast<std::size_t>(model.elements[element].node_count));
  for (std::size_t k = 0; k < nodes.size(); ++k) nodes[k] = model.coords[conn[k]];
  std::vector<PointValue> out;
  for (std::size_t q = 0; q < points.size(); ++q)
    out.push_back(PointValue{int(q) + 1, points[q],
                             map_natural_point(formulation, points[q], nodes),
                             field.values[field.offset[element] + int(q)]});
  return out;
}

Vec3 map_natural_point(const TElement& formulation, const Vec3& xi,
                       const std::vector<Vec3>& node_positions) {
  const int n = formulation.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  formulation.der(xi, N, dN);
  Vec3 x{};
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k) x[k] += N(a) * node_positions[a][k];
  return x;
}

}  // namespace styk::render
