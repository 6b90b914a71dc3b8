// Shape-function library of the wedges (triangular prisms; CalculiX/Abaqus C3D6, C3D15) on the
// reference prism: the triangle xi, eta >= 0, xi + eta <= 1 times zeta in [-1, 1]. Node tables,
// faces 1..5, DER and the integration rules CalculiX uses. Public so that plug-ins can build
// wedge variants.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk {

// Corners 1 (0,0,-1), 2 (1,0,-1), 3 (0,1,-1), 4-6 above them at zeta = +1; the 15-node element
// adds the mid-edge nodes 7 (1-2), 8 (2-3), 9 (3-1), 10 (4-5), 11 (5-6), 12 (6-4), 13 (1-4),
// 14 (2-5), 15 (3-6).
std::vector<Vec3> wedge6_natural_nodes();
std::vector<Vec3> wedge15_natural_nodes();

// Faces as CalculiX numbers them: 1: 1-2-3, 2: 4-5-6, 3: 1-2-5-4, 4: 2-3-6-5, 5: 3-1-4-6
// (corners first, then the mid-edge nodes of the edges in the same order when `quadratic`).
// Parametrised from their corners (FaceDef::axis = -1).
std::vector<FaceDef> wedge_faces(bool quadratic);

// N (6) and dN (6 x 3) of the linear wedge: L_i(xi, eta) (1 -+ zeta) / 2.
void wedge6_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// N (15) and dN (15 x 3) of the quadratic (serendipity) wedge.
void wedge15_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// Triangle rule x Gauss rule in zeta, the triangle's points fastest (CalculiX's order, checked
// with *EL PRINT, COORD): `triangle_points` 1 (the centroid, weight 1/2) or 3 ((1/6, 1/6),
// (2/3, 1/6), (1/6, 2/3), weights 1/6); `zeta_points` 1..3 Gauss points. C3D6 integrates with
// 1 x 2, C3D15 with 3 x 3.
IntegrationRule wedge_rule(int triangle_points, int zeta_points);

}  // namespace styk
