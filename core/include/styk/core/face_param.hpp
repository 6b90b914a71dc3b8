// The natural parametrisation of an element face that does not lie on a coordinate plane of the
// reference cube (FaceDef::axis = -1: the faces of tetrahedra and wedges), derived from its
// corners' natural coordinates alone, so any formulation's faces are integrated, projected on and
// drawn the same way:
// - 3 corners: the triangle p, q >= 0, p + q <= 1, xi = c0 + p (c1 - c0) + q (c2 - c0);
// - 4 corners: the square (p, q) in [-1, 1]^2 mapped bilinearly onto the corners in their order.
// The corners are the face's first 3 or 4 nodes (3 when the fourth lies in the triangle of the
// first three). outward() is the sign that turns dxi/dp x dxi/dq away from the element's inside
// (the mean of its natural nodes); an
// element with a positive Jacobian keeps it for x,p x x,q, so the physical area vector
// outward() * (x,p x x,q) points out of the element whatever order the face lists its corners.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk {

class FaceParam {
 public:
  // Throws std::invalid_argument for a face with fewer than 3 nodes.
  FaceParam(const TElement& element, const FaceDef& face);

  bool triangle() const { return corners_ == 3; }
  // Natural point at in-face coordinates (p, q).
  Vec3 point(double p, double q) const;
  // dxi/dp and dxi/dq there.
  void tangents(double p, double q, Eigen::Vector3d& dp, Eigen::Vector3d& dq) const;
  double outward() const { return outward_; }
  // How far (p, q) lies outside the face (0 inside): the largest violated bound.
  double outside(double p, double q) const;
  // The face's centre in (p, q).
  std::array<double, 2> centre() const;

 private:
  int corners_ = 0;
  std::array<Eigen::Vector3d, 4> c_;
  double outward_ = 1.0;
};

// A quadrature rule over the face domain in (p, q): `order` x `order` Gauss points on the square;
// on the triangle the collapsed (Duffy) rule with `order` x `order` points, exact for polynomials
// of total degree 2 order - 2. Weights sum to the domain's area (4 or 1/2).
struct FaceRule {
  std::vector<std::array<double, 2>> points;
  std::vector<double> weights;
};
FaceRule face_rule(bool triangle, int order);

}  // namespace styk
