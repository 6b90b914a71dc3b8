// Segment-to-segment (mortar) integrals between a slave face and a master face (docs/contact.md,
// "Mortar contact"). The slave face carries the dual multiplier basis phi_a (Wohlmuth 2000): the
// functions of the face's shape-function space that are biorthogonal to the shape functions,
// integral phi_a N_b dA = delta_ab integral N_a dA, so the slave side of the mortar coupling is
// diagonal and every slave node's row is one ContactConstraint. The master side needs
// M_ak = integral over the overlap of phi_a N_k dA, computed on the slave face's auxiliary plane
// (its tangent plane at the face centre): both faces' boundaries are projected onto it, the master
// polygon is clipped by the slave polygon, and the clipped polygon is integrated triangle by
// triangle, each Gauss point mapped back onto the two faces along the plane's normal.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "styk/core/diagnostics.hpp"
#include "surface_geometry.hpp"

namespace styk::contact {

// A face of a contact surface: the placed face, the element-local indices of its nodes and the
// model indices of the same nodes (same order).
struct MortarFace {
  PlacedFace placed;
  std::vector<int> local;
  std::vector<int> nodes;
  // The slave basis N^ = basis N the multipliers are biorthogonal to (empty: N itself).
  Eigen::MatrixXd basis;
};

// The face's shape functions at in-face coordinates (p, q), one per face node (MortarFace order).
Eigen::VectorXd face_shape_values(const MortarFace& f, double p, double q);

// The slave basis of a face (Popp, Wohlmuth, Gee, Wall 2012, "Dual quadratic mortar finite element
// methods for 3D finite deformation contact"): on an 8-node quadrilateral or 6-node triangle,
// whose corner integrals are negative or zero, N^_corner = N_corner + 1/5 (sum of the N of the
// two mid-edge nodes beside it) and N^_mid = 3/5 N_mid (a partition of unity with positive
// integrals: A/20 and A/5 on a flat 8-node face); every other face keeps N (identity).
Eigen::MatrixXd slave_basis_transform(const MortarFace& f);

// The face's unit normal at its centre, out of its element.
Eigen::Vector3d face_centre_normal(const PlacedFace& f);

// The dual basis of a slave face: phi_a = sum_b coefficients(a, b) N^_b, biorthogonal to the
// slave basis N^ (MortarFace::basis), and the nodal integrals D_a = integral N^_a dA
// (= integral phi_a dA). Throws InputError at `where` when a nodal integral
// is not positive (the serendipity 8-node and 6-node faces without their transformed basis: their
// corner integrals are negative or zero, and phi_a would not exist or would pull).
struct DualBasis {
  Eigen::MatrixXd coefficients;
  Eigen::VectorXd nodal_integrals;
};
DualBasis dual_basis(const MortarFace& slave, const SourceLoc& where);

// Whether the dual basis exists on the face: every nodal integral positive.
bool admits_dual_basis(const MortarFace& slave);

// Adds integral over (slave face ∩ master face) of phi_a N_k dA_slave to coupling(a, k) (slave face
// nodes x master face nodes, sized by the caller). Returns the overlap area (0: no overlap).
double integrate_overlap(const MortarFace& slave, const DualBasis& dual, const MortarFace& master,
                         Eigen::MatrixXd& coupling);

}  // namespace styk::contact
