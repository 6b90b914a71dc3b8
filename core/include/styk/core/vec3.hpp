// The model's plain points (Vec3 = std::array<double, 3>) seen as Eigen vectors and back, so that
// geometry is written with Eigen rather than hand-written 3-vector helpers. Include it only where
// geometry is computed: it brings in Eigen.
#pragma once

#include <Eigen/Core>

#include "styk/core/model.hpp"

namespace styk {

inline Eigen::Map<const Eigen::Vector3d> as_eigen(const Vec3& v) {
  return Eigen::Map<const Eigen::Vector3d>(v.data());
}

inline Vec3 to_vec3(const Eigen::Ref<const Eigen::Vector3d>& v) { return {v[0], v[1], v[2]}; }

}  // namespace styk
