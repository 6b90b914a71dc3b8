// Where the axes of a *TRANSFORM / *ORIENTATION system point at a given node.
#pragma once

#include <Eigen/Core>

#include "styk/core/model.hpp"

namespace styk {

// R = [e1 e2 e3] (unit local axes as columns, global components) of `axes` at point x.
// Rectangular: e1 along a, e2 in the plane of a and b; cylindrical: e3 along the axis a -> b, e1
// radial through x, e2 = e3 x e1. False where the system is undefined: rectangular with a = 0 or b
// along a; cylindrical with a = b or x on the axis (within 1e-12 of the points' scale).
bool local_axes_at(const LocalAxes& axes, const Vec3& x, Eigen::Matrix3d& R);

}  // namespace styk
