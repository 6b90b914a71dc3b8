// The edge quadrature shared by the elements that live in the x-y plane (plane stress/strain and
// axisymmetric rings): their faces are their edges.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "styk/core/element.hpp"

namespace styk::elements_detail {

// Gauss points of `face` (an edge: face.axis is the natural coordinate held at face.value) and
// their weighted area vectors: the solid's x,s x x,t with the out-of-plane direction scaled by
// width(N) at the point (a plane element's thickness, a ring's circumference 2 pi r), which points
// along +axis for a counter-clockwise element (xi edges: t x e_z; eta edges: e_z x t).
template <class Width>
void edge_quadrature(const TElement& element, const ElementGeometry& g, const FaceDef& face,
                     const Width& width, std::vector<Vec3>& points,
                     std::vector<Eigen::Vector3d>& weighted_normals) {
  std::vector<double> gauss, weights;
  gauss_legendre(element.face_rule_order(), gauss, weights);
  const int along = 1 - face.axis;  // the natural coordinate running along the edge
  const int n = element.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  points.clear();
  weighted_normals.clear();
  for (std::size_t a = 0; a < gauss.size(); ++a) {
    Vec3 xi{};
    xi[face.axis] = face.value;
    xi[along] = gauss[a];
    element.der(xi, N, dN);
    const Eigen::Vector2d tangent = g.X.leftCols<2>().transpose() * dN.col(along);
    const Eigen::Vector3d normal = face.axis == 0 ? Eigen::Vector3d(tangent.y(), -tangent.x(), 0.0)
                                                  : Eigen::Vector3d(-tangent.y(), tangent.x(), 0.0);
    points.push_back(xi);
    weighted_normals.push_back(weights[a] * width(N) * normal);
  }
}

}  // namespace styk::elements_detail
