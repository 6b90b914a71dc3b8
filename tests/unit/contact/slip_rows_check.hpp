// The slip rows of a linearised contact law (friction_law.hpp) against finite differences: Q and
// D of rows 1-2 must be the derivatives of F_t = slip_function(point) with respect to d and
// lambda (central differences of step h, relative tolerance `tolerance`). Shared by the friction,
// penalty and exponential law tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Core>

#include "styk/contact/friction_law.hpp"

namespace styk::contact::test {

inline void expect_slip_rows_match_finite_differences(const LocalPoint& p, const LocalRows& rows,
                                                      double h, double tolerance) {
  for (int j = 0; j < 3; ++j) {
    LocalPoint plus = p, minus = p;
    plus.lambda[j] += h;
    minus.lambda[j] -= h;
    const Eigen::Vector2d dl = (slip_function(plus) - slip_function(minus)) / (2 * h);
    plus = p;
    minus = p;
    plus.d[j] += h;
    minus.d[j] -= h;
    const Eigen::Vector2d dd = (slip_function(plus) - slip_function(minus)) / (2 * h);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(rows.D(1 + i, j), dl[i], tolerance * (1 + std::abs(dl[i]))) << i << "," << j;
      EXPECT_NEAR(rows.Q(1 + i, j), dd[i], tolerance * (1 + std::abs(dd[i]))) << i << "," << j;
    }
  }
}

}  // namespace styk::contact::test
