// Shape-function library of the hexahedral family on the reference cube [-1, 1]^3: node tables,
// Abaqus faces, and DER (values and natural derivatives) of the 8-node trilinear, the 20-node
// serendipity and the 27-node Lagrange interpolation. Kept apart from the element classes so that
// derived formulations (reduced rules, incompatible modes, the contact hexahedra C3D14/C3D21/C3D28
// built on these nodes) reuse the basis without copying it.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk {

// Natural coordinates of the nodes in Abaqus/CalculiX order (elements-ref/README.md section 1):
// corners 1-8, then (20-node) mid-edges 9-12 on zeta=-1, 13-16 on zeta=+1, 17-20 vertical.
std::vector<Vec3> hex8_natural_nodes();
std::vector<Vec3> hex20_natural_nodes();

// Faces S1..S6 with their Abaqus node lists (0-based; corners first, then the mid-edge nodes when
// `with_mid_edges`), on the natural coordinate plane each lies on.
std::vector<FaceDef> hex_faces(bool with_mid_edges);

// N (8) and dN (8 x 3) of the trilinear hexahedron at xi.
void hex8_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// N (20) and dN (20 x 3) of the 20-node serendipity hexahedron at xi.
void hex20_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// The 27-node Lagrange hexahedron (hex27_shapes.cpp): nodes 1-20 as the 20-node element, then the
// face centres 21-26 on S1..S6 in face order (21 (0,0,-1), 22 (0,0,+1), 23 (0,-1,0), 24 (+1,0,0),
// 25 (0,+1,0), 26 (-1,0,0)) and the centre 27 (0,0,0).
std::vector<Vec3> hex27_natural_nodes();
// Faces S1..S6 with 9 nodes each: the 20-node face list, then the face centre.
std::vector<FaceDef> hex27_faces();
// N (27) and dN (27 x 3) of the triquadratic Lagrange hexahedron at xi.
void hex27_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

}  // namespace styk
