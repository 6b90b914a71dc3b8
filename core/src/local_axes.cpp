#include "styk/core/local_axes.hpp"

#include <algorithm>

#include <Eigen/Geometry>

namespace styk {
namespace {

Eigen::Vector3d vec(const Vec3& v) { return {v[0], v[1], v[2]}; }

}  // namespace

bool local_axes_at(const LocalAxes& axes, const Vec3& x, Eigen::Matrix3d& R) {
  const Eigen::Vector3d a = vec(axes.a), b = vec(axes.b);
  Eigen::Vector3d e1, e2, e3;
  if (axes.system == CoordinateSystem::Rectangular) {
    if (!(a.norm() > 0.0)) return false;
    e1 = a.normalized();
    e2 = b - b.dot(e1) * e1;
    if (!(e2.norm() > 1e-12 * b.norm())) return false;
    e2.normalize();
    e3 = e1.cross(e2);
  } else {
    const Eigen::Vector3d axis = b - a;
    if (!(axis.norm() > 0.0)) return false;
    e3 = axis.normalized();
    const Eigen::Vector3d from_axis = vec(x) - a;
    e1 = from_axis - from_axis.dot(e3) * e3;
    // A node within 1e-12 of the axis (relative to the axis points' scale) has no radial
    // direction.
    const double scale = std::max({a.norm(), b.norm(), vec(x).norm(), 1.0});
    if (!(e1.norm() > 1e-12 * scale)) return false;
    e1.normalize();
    e2 = e3.cross(e1);
  }
  R.col(0) = e1;
  R.col(1) = e2;
  R.col(2) = e3;
  return true;
}

}  // namespace styk
