// Geometry of element faces as the isoparametric map of their element: points, outward normals,
// nodal areas and closest-point projection. Everything is evaluated with the element's own shape
// functions (TElement::der), so curved quadratic faces are treated exactly, not as facets.
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

// The natural point of `face` at in-face coordinates (p, q) in [-1, 1]^2: the face's fixed axis
// takes its value, the two other axes (in increasing order) take p and q.
Vec3 face_point(const FaceDef& face, double p, double q);

// Position and the two tangent vectors x,p and x,q at natural point xi (on the face).
void face_map(const PlacedFace& f, const Vec3& xi, Eigen::Vector3d& x, Eigen::Vector3d& xp,
              Eigen::Vector3d& xq);

// Unit normal pointing out of the element at natural point xi on the face; zero vector when the
// face is degenerate there.
Eigen::Vector3d outward_normal(const PlacedFace& f, const Vec3& xi);

// Closest point of the face to `point`: in-face coordinates (p, q) (may lie outside [-1, 1] when
// the point is beyond the face), the point on the (extended) face and its outward normal.
struct Projection {
  double p = 0.0, q = 0.0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  bool converged = false;
  double outside() const;  // how far (p, q) lies outside [-1, 1]^2 in the max norm, 0 inside
};
Projection project_on_face(const PlacedFace& f, const Eigen::Vector3d& point);

// Shape-function values of the element at natural point xi (n).
Eigen::VectorXd shape_values(const TElement& element, const Vec3& xi);

}  // namespace styk::contact
