// Shape-function library of the tetrahedra (CalculiX/Abaqus C3D4, C3D10) on the reference
// tetrahedron xi, eta, zeta >= 0, xi + eta + zeta <= 1: node tables, faces 1..4, DER and the
// integration rules CalculiX uses. Public so that plug-ins can build tetrahedral variants.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk {

// Corners 1 (0,0,0), 2 (1,0,0), 3 (0,1,0), 4 (0,0,1); the 10-node element adds the mid-edge nodes
// 5 (1-2), 6 (2-3), 7 (3-1), 8 (1-4), 9 (2-4), 10 (3-4).
std::vector<Vec3> tet4_natural_nodes();
std::vector<Vec3> tet10_natural_nodes();

// Faces as CalculiX numbers them: 1: 1-2-3, 2: 1-4-2, 3: 2-4-3, 4: 3-4-1 (corners first, then the
// mid-edge nodes of the edges in the same order when `quadratic`). They lie off the coordinate
// planes of a cube, so they are parametrised from their corners (FaceDef::axis = -1).
std::vector<FaceDef> tet_faces(bool quadratic);

// N (4) and dN (4 x 3) of the linear tetrahedron: N = 1 - xi - eta - zeta, xi, eta, zeta.
void tet4_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// N (10) and dN (10 x 3) of the quadratic tetrahedron: corners L (2L - 1), mid-edges 4 L_i L_j
// (L: the volume coordinates 1 - xi - eta - zeta, xi, eta, zeta).
void tet10_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// The centroid rule (1 point, weight 1/6) and the 4-point rule of degree 2 at
// a = (5 - sqrt 5)/20, b = (5 + 3 sqrt 5)/20: (a,a,a), (b,a,a), (a,b,a), (a,a,b), weights 1/24,
// in CalculiX's order (checked with *EL PRINT, COORD).
IntegrationRule tet_rule_1();
IntegrationRule tet_rule_4();

}  // namespace styk
