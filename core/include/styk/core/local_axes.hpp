// Where the axes of a *TRANSFORM / *ORIENTATION system point at a given node: the one routine and
// the one validity rule every module uses (reader, GUI dialogs, solver, contact, .dat output).
#pragma once

#include <string>

#include <Eigen/Core>

#include "styk/core/model.hpp"

namespace styk {

// Degeneracy is judged relative to the size of the points (never in absolute units), with this
// relative tolerance: a quantity below kAxesTolerance x the points' scale counts as zero.
constexpr double kAxesTolerance = 1e-12;

// Why `axes` defines no local system, or an empty string when it does. Rectangular: a must not be
// (relatively) zero and b must not lie on the line of a; cylindrical: the axis points a and b must
// differ.
std::string axes_defect(const LocalAxes& axes);

// Why the system has no axes at point x although axes_defect() is empty, or an empty string.
// Cylindrical: x on the axis has no radial direction ("lies on the axis: ...", to follow the name
// of the node in messages).
std::string axes_defect_at(const LocalAxes& axes, const Vec3& x);

// R = [e1 e2 e3] (unit local axes as columns, global components) of `axes` at point x.
// Rectangular: e1 along a, e2 in the plane of a and b; cylindrical: e3 along the axis a -> b, e1
// radial through x, e2 = e3 x e1. False (R untouched) where axes_defect() or axes_defect_at() is
// not empty.
bool local_axes_at(const LocalAxes& axes, const Vec3& x, Eigen::Matrix3d& R);

}  // namespace styk
