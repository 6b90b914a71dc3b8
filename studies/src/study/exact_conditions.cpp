#include "styk/studies/study/exact_conditions.hpp"

#include <map>
#include <set>
#include <utility>

#include "element_geometry.hpp"

namespace styk::studies {

void prescribe_exact_displacements(Model& model, const ElementRegistry& registry,
                                   const std::vector<mesher::FaceRef>& faces,
                                   const ExactSolution& exact) {
  std::set<int> done;
  for (const mesher::FaceRef& f : faces) {
    const TElement& element = detail::formulation_of(model, registry, f.element);
    const int* nodes = model.element_nodes(f.element);
    const int region = model.elements[f.element].section;
    for (int local : element.faces().at(f.face).nodes) {
      const int n = nodes[local];
      if (!done.insert(n).second) continue;
      const Vec3 u = exact.displacement(model.coords[n], region);
      for (int d = 0; d < 3; ++d) model.boundaries.push_back({n, d + 1, u[d], {}});
    }
  }
}

std::vector<ConcentratedLoad> exact_traction_loads(const Model& model,
                                                   const ElementRegistry& registry,
                                                   const std::vector<mesher::FaceRef>& faces,
                                                   const ExactSolution& exact) {
  std::map<std::pair<int, int>, double> force;  // (node, dof 1..3) -> value
  std::vector<Vec3> points;
  std::vector<Eigen::Vector3d> weighted_normals;
  for (const mesher::FaceRef& f : faces) {
    const TElement& element = detail::formulation_of(model, registry, f.element);
    const ElementGeometry g = detail::geometry_of(model, f.element);
    const FaceDef& face = element.faces().at(f.face);
    const int region = model.elements[f.element].section;
    const int n = element.node_count();
    element.face_quadrature(g, face, points, weighted_normals);
    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3);
    const int* nodes = model.element_nodes(f.element);
    for (std::size_t q = 0; q < points.size(); ++q) {
      element.der(points[q], N, dN);
      const Tensor6 s = exact.stress(detail::map_point(N, g), region);
      // The weighted normal points along +axis of the face's natural coordinate: outward on a
      // +1 face, inward on a -1 face.
      const Eigen::Vector3d dA = weighted_normals[q] * face.value;
      const Eigen::Vector3d t(s[0] * dA[0] + s[3] * dA[1] + s[4] * dA[2],
                              s[3] * dA[0] + s[1] * dA[1] + s[5] * dA[2],
                              s[4] * dA[0] + s[5] * dA[1] + s[2] * dA[2]);
      for (int local : face.nodes)
        for (int d = 0; d < 3; ++d) force[{nodes[local], d + 1}] += N(local) * t[d];
    }
  }
  std::vector<ConcentratedLoad> loads;
  for (const auto& [key, value] : force)
    if (value != 0.0) loads.push_back({key.first, key.second, value, {}});
  return loads;
}

}  // namespace styk::studies
