// Geometry of element faces as the isoparametric map of their element: points, outward normals,
// nodal areas and closest-point projection. Everything is evaluated with the element's own shape
// functions (TElement::der), so curved quadratic faces are treated exactly, not as facets.
// In-face coordinates (p, q): on a face of the reference cube (FaceDef::axis >= 0) the two free
// natural coordinates in increasing axis order, over [-1, 1]^2; on any other face (tetrahedra,
// wedges) the corner parametrisation of face_param.hpp (a triangle or a bilinear square); on an
// edge of a plane or axisymmetric element p runs along the edge over [-1, 1] and q stands for z
// (the edge's second tangent is e_z, so its normal lies in the x-y plane).
#pragma once

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk::contact {

// One element face placed in the model.
struct PlacedFace {
  const TElement* element = nullptr;
  ElementGeometry geometry;  // all element nodes
  int face = 0;              // 0-based (0 = S1)
};

// The natural point of the face at in-face coordinates (p, q).
Vec3 face_point(const PlacedFace& f, double p, double q);

// The in-face coordinates of natural point xi on the face (exact for a node of the face).
std::array<double, 2> face_coordinates(const PlacedFace& f, const Vec3& xi);

// Position and the two tangent vectors x,p and x,q at in-face coordinates (p, q).
void face_map(const PlacedFace& f, double p, double q, Eigen::Vector3d& x, Eigen::Vector3d& xp,
              Eigen::Vector3d& xq);

// Unit normal pointing out of the element at (p, q); zero vector when the face is degenerate.
Eigen::Vector3d outward_normal(const PlacedFace& f, double p, double q);

// Closest point of the face to `point`: in-face coordinates (p, q) (may lie outside the face
// when the point is beyond it), the point on the (extended) face and its outward normal.
struct Projection {
  double p = 0.0, q = 0.0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  bool converged = false;
  double beyond = 0.0;  // how far (p, q) lies outside the face, 0 inside
  double outside() const { return beyond; }
};
Projection project_on_face(const PlacedFace& f, const Eigen::Vector3d& point);

// Shape-function values of the element at natural point xi (n).
Eigen::VectorXd shape_values(const TElement& element, const Vec3& xi);

}  // namespace styk::contact
