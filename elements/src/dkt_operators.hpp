// The strain operators of the flat discrete-Kirchhoff triangle (STRI3, stri3.hpp) in the element's
// own plane: the constant-strain membrane and the discrete-Kirchhoff (DKT) bending of Batoz,
// Bathe and Ho (1980). Coordinates and dofs are the element's local ones (x1, x2 in its plane):
// per node the plate dofs (w, theta1, theta2) for bending, (u1, u2) for the membrane.
#pragma once

#include <Eigen/Core>

namespace styk::dkt {

// The corners' in-plane coordinates, one row per node.
using Corners = Eigen::Matrix<double, 3, 2>;

// The normal's rotations beta = (beta1, beta2) at the 3 corners and 3 mid-sides (rows 2m, 2m + 1
// for node m: corners 0-2, then the sides 1-2, 2-0, 0-1 in the order of the quadratic triangle's
// mid-side functions) from the plate dofs (w, theta1, theta2) of the corners. A corner's beta is
// (theta2, -theta1) (u = z theta x e3). Along a side the Kirchhoff constraint w,s + beta_s = 0
// holds at the corners and, integrated, along the side with w cubic: the mid-side tangential
// rotation is -3 (w_j - w_i) / (2 l) - (beta_s,i + beta_s,j) / 4; the normal rotation is linear.
Eigen::Matrix<double, 12, 9> midside_rotations(const Corners& x);

// Curvatures (beta1,1, beta2,2, beta1,2 + beta2,1) at natural point (xi, eta) of the triangle
// (xi, eta >= 0, xi + eta <= 1) per plate dof: bending strain = z times this.
Eigen::Matrix<double, 3, 9> curvature(const Corners& x, const Eigen::Matrix<double, 12, 9>& T,
                                      double xi, double eta);

// The curvatures' gradients, constant over the element (beta is quadratic): rows d/dx1 and
// d/dx2 of (kappa11, kappa22, kappa12) as d kappa_i / dx_j at row 3 j + i.
Eigen::Matrix<double, 6, 9> curvature_gradient(const Corners& x,
                                               const Eigen::Matrix<double, 12, 9>& T);

// Membrane strains (eps11, eps22, gamma12) per (u1, u2) of the corners, constant.
Eigen::Matrix<double, 3, 6> membrane(const Corners& x);

// The membrane's in-plane rotation (u2,1 - u1,2) / 2 per (u1, u2) of the corners, constant.
Eigen::Matrix<double, 1, 6> in_plane_rotation(const Corners& x);

// Twice the signed area (positive when the corners turn anticlockwise).
double twice_area(const Corners& x);

}  // namespace styk::dkt
