// Shape-function library of the plane quadrilaterals on the reference square [-1, 1]^2 (zeta is
// ignored and stays 0): node tables, Abaqus edges P1..P4, DER of the 4-node bilinear and the
// 8-node serendipity interpolation, and the plane Gauss rules.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk {

// Natural coordinates in Abaqus/CalculiX order: corners 1-4 counter-clockwise from (-1, -1), then
// (8-node) the mid-edge nodes 5-8 of the edges 1-2, 2-3, 3-4, 4-1.
std::vector<Vec3> quad4_natural_nodes();
std::vector<Vec3> quad8_natural_nodes();

// Edges P1..P4: edge k runs from corner k to corner k+1 (then its mid-edge node when
// `with_mid_edges`), on the natural line it lies on (P1 eta=-1, P2 xi=+1, P3 eta=+1, P4 xi=-1).
std::vector<FaceDef> quad_edges(bool with_mid_edges);

// N (4) and dN (4 x 3, third column zero) of the bilinear quadrilateral at (xi, eta).
void quad4_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// N (8) and dN (8 x 3, third column zero) of the 8-node serendipity quadrilateral at (xi, eta).
void quad8_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN);

// Tensor-product Gauss rule n x n on the square (zeta = 0), xi fastest; weights sum to 4.
IntegrationRule quad_gauss_rule(int n);

}  // namespace styk
