// The series solutions of the plate problems (docs/accuracy.md `plate`, docs/stability.md
// `thin-plate`) against the published values of Timoshenko & Woinowsky-Krieger, Theory of Plates
// and Shells (1959), §30 Table 8 (simply supported square, uniform load q, nu = 0.3): centre
// deflection 0.00406 q a^4 / D (six digits: 0.00406235, as in SPEC §7.3 Tab 7.1b's theory column),
// centre moments M_x = M_y = 0.0479 q a^2. Tolerances: half a unit of the printed last digit.
#include <gtest/gtest.h>

#include <cmath>

#include "styk/studies/study/plate_series.hpp"

namespace styk::studies {
namespace {

SquarePlate unit_plate(double t) {
  SquarePlate p;
  p.side = 1.0;
  p.thickness = t;
  p.young = 10.92e5;
  p.poisson = 0.3;
  p.pressure = 1.0;
  return p;
}

double rigidity(const SquarePlate& p) {
  return p.young * p.thickness * p.thickness * p.thickness / (12.0 * (1.0 - p.poisson * p.poisson));
}

TEST(PlateSeries, KirchhoffCentreDeflectionAndMoments) {
  const SquarePlate p = unit_plate(0.01);
  EXPECT_NEAR(plate_deflection(p, 0.5, 0.5, false) * rigidity(p), 0.00406235, 5e-9);
  EXPECT_NEAR(plate_moment_sum(p, 0.5, 0.5), 2 * 0.0479, 1e-4);
}

// The Mindlin plate adds the shear deflection: at t = 1 the table value of SPEC §7.3 Tab 7.1b's
// Mindlin column (1000 w D1 / (q a^4), D1 the rigidity of t = 1) is 25.111
// (docs/verification.md); at t = 0.01 the shear part is 5.18e-4 of the Kirchhoff deflection (the
// note of the `plate` problem: STRI3 is measured against the Kirchhoff series there).
TEST(PlateSeries, MindlinAddsTheShearDeflection) {
  const SquarePlate thick = unit_plate(1.0);
  EXPECT_NEAR(1000 * plate_deflection(thick, 0.5, 0.5, true) * rigidity(thick), 25.111, 5e-4);
  const SquarePlate thin = unit_plate(0.01);
  const double kirchhoff = plate_deflection(thin, 0.5, 0.5, false);
  const double mindlin = plate_deflection(thin, 0.5, 0.5, true);
  EXPECT_NEAR(mindlin / kirchhoff - 1.0, 5.18e-4, 5e-6);
}

// The cell mean is the mean of the point values: over a small cell it is the centre's value, and
// it matches a midpoint sum of plate_moment_sum over a 4 x 4 grid of a coarse cell to 5e-4
// (the midpoint rule's error).
TEST(PlateSeries, MomentMeanOverACell) {
  const SquarePlate p = unit_plate(0.01);
  EXPECT_NEAR(plate_moment_sum_mean(p, 0.5 - 1e-4, 0.5, 0.5 - 1e-4, 0.5),
              plate_moment_sum(p, 0.5, 0.5), 1e-7);
  double sum = 0.0;
  const int n = 4;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      sum += plate_moment_sum(p, 0.25 + 0.25 * (i + 0.5) / n, 0.25 + 0.25 * (j + 0.5) / n);
  EXPECT_NEAR(plate_moment_sum_mean(p, 0.25, 0.5, 0.25, 0.5), sum / (n * n), 5e-4);
}

}  // namespace
}  // namespace styk::studies
