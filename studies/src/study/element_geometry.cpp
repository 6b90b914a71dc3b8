#include "element_geometry.hpp"

#include <cmath>

#include "styk/core/diagnostics.hpp"

namespace styk::studies::detail {

const TElement& formulation_of(const Model& model, const ElementRegistry& registry, int e) {
  const TElement* f = registry.find(model.elements[e].type);
  if (!f)
    throw InputError(model.elements[e].where,
                     "element type " + model.elements[e].type + " is not registered");
  return *f;
}

ElementGeometry geometry_of(const Model& model, int e) {
  const Element& element = model.elements[e];
  ElementGeometry g;
  g.X.resize(element.node_count, 3);
  g.id = element.id;
  g.where = element.where;
  const int* nodes = model.element_nodes(e);
  for (int a = 0; a < element.node_count; ++a)
    for (int d = 0; d < 3; ++d) g.X(a, d) = model.coords[nodes[a]][d];
  return g;
}

Vec3 map_point(const Eigen::VectorXd& N, const ElementGeometry& g) {
  const Eigen::Vector3d x = g.X.transpose() * N;
  return {x[0], x[1], x[2]};
}

bool is_hexahedron(const TElement& element) {
  const DofSet active = element.active_dofs();
  if (!(active[0] && active[1] && active[2]) || element.section_measure() != SectionMeasure::None)
    return false;
  bool corner = false;
  for (const Vec3& xi : element.natural_nodes()) {
    for (double c : xi)
      if (std::abs(c) > 1.0 + 1e-12) return false;
    corner |= xi[0] == 1.0 && xi[1] == 1.0 && xi[2] == 1.0;
  }
  return corner;
}

}  // namespace styk::studies::detail
