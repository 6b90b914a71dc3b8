// Two solves of one contact model by different paths (the dense and the sparse contact solve,
// docs/contact.md) must give the same answer: same increments, the same status at every slave
// node, and pressures, shears, fluid pressures and displacements within `tolerance` of the
// largest of each. Header-only.
#pragma once

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "styk/core/results.hpp"

namespace styk::test {

inline void expect_same_contact_answer(const Results& expected, const Results& actual,
                                       double tolerance) {
  ASSERT_EQ(expected.increments.size(), actual.increments.size());
  double traction = 0.0, displacement = 0.0;
  for (const IncrementResult& inc : expected.increments) {
    for (const ContactNodeResult& c : inc.contact)
      traction = std::max({traction, std::abs(c.pressure), std::abs(c.shear[0]),
                           std::abs(c.shear[1]), std::abs(c.fluid_pressure)});
    for (const Vec3& u : inc.U)
      for (double v : u) displacement = std::max(displacement, std::abs(v));
  }
  ASSERT_GT(traction, 0.0);
  for (std::size_t i = 0; i < expected.increments.size(); ++i) {
    const IncrementResult& a = expected.increments[i];
    const IncrementResult& b = actual.increments[i];
    ASSERT_EQ(a.step, b.step);
    ASSERT_EQ(a.increment, b.increment);
    ASSERT_EQ(a.contact.size(), b.contact.size());
    for (std::size_t j = 0; j < a.contact.size(); ++j) {
      const ContactNodeResult& p = a.contact[j];
      const ContactNodeResult& q = b.contact[j];
      EXPECT_EQ(p.status, q.status) << "increment " << i << ", slave node index " << p.node;
      EXPECT_NEAR(p.pressure, q.pressure, tolerance * traction);
      EXPECT_NEAR(p.shear[0], q.shear[0], tolerance * traction);
      EXPECT_NEAR(p.shear[1], q.shear[1], tolerance * traction);
      EXPECT_NEAR(p.fluid_pressure, q.fluid_pressure, tolerance * traction);
    }
    ASSERT_EQ(a.U.size(), b.U.size());
    for (std::size_t n = 0; n < a.U.size(); ++n)
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(a.U[n][d], b.U[n][d], tolerance * displacement);
  }
}

}  // namespace styk::test
