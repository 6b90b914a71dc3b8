#include "styk/core/local_axes.hpp"

#include <algorithm>

#include <Eigen/Geometry>

namespace styk {
namespace {

Eigen::Vector3d vec(const Vec3& v) { return {v[0], v[1], v[2]}; }

double scale_of(const LocalAxes& axes) { return std::max(vec(axes.a).norm(), vec(axes.b).norm()); }

// The component of x - a normal to the axis a -> b (cylindrical systems).
Eigen::Vector3d radial(const LocalAxes& axes, const Vec3& x) {
  const Eigen::Vector3d a = vec(axes.a), e3 = (vec(axes.b) - a).normalized();
  const Eigen::Vector3d from_axis = vec(x) - a;
  return from_axis - from_axis.dot(e3) * e3;
}

}  // namespace

std::string axes_defect(const LocalAxes& axes) {
  const Eigen::Vector3d a = vec(axes.a), b = vec(axes.b);
  const double scale = scale_of(axes);
  if (!a.allFinite() || !b.allFinite()) return "the points a and b must be finite numbers";
  if (axes.system == CoordinateSystem::Rectangular) {
    if (!(a.norm() > kAxesTolerance * scale))
      return "point a must not be the origin (it gives local x)";
    if (!(a.cross(b).norm() > kAxesTolerance * a.norm() * b.norm()) || b.norm() == 0.0)
      return "point b must not lie on the line of a (it gives the local x-y plane)";
    return "";
  }
  if (!((b - a).norm() > kAxesTolerance * scale)) return "the two axis points a and b must differ";
  return "";
}

std::string axes_defect_at(const LocalAxes& axes, const Vec3& x) {
  if (axes.system == CoordinateSystem::Rectangular || !axes_defect(axes).empty()) return "";
  const double scale = std::max(scale_of(axes), vec(x).norm());
  if (!(radial(axes, x).norm() > kAxesTolerance * scale))
    return "lies on the axis: it has no radial direction";
  return "";
}

bool local_axes_at(const LocalAxes& axes, const Vec3& x, Eigen::Matrix3d& R) {
  if (!axes_defect(axes).empty() || !axes_defect_at(axes, x).empty()) return false;
  const Eigen::Vector3d a = vec(axes.a), b = vec(axes.b);
  Eigen::Vector3d e1, e2, e3;
  if (axes.system == CoordinateSystem::Rectangular) {
    e1 = a.normalized();
    e2 = (b - b.dot(e1) * e1).normalized();
    e3 = e1.cross(e2);
  } else {
    e3 = (b - a).normalized();
    e1 = radial(axes, x).normalized();
    e2 = e3.cross(e1);
  }
  R.col(0) = e1;
  R.col(1) = e2;
  R.col(2) = e3;
  return true;
}

}  // namespace styk
