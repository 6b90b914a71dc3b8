// The exact solutions the atlas measures against (docs/accuracy.md): each must satisfy
// equilibrium (div sigma = 0), its strains must be the compliance times its stresses (checked by
// central differences of the displacements), and it must meet the boundary conditions of its
// problem. Tolerances: central differences with step 1e-5 of the body size are accurate to
// ~1e-9 relative; asserted at 1e-6 of the stress scale.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "styk/studies/study/exact_solution.hpp"

namespace styk::studies {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Engineering strains from central differences of the displacement at x.
Tensor6 strain_by_differences(const ExactSolution& s, const Vec3& x, int region, double step) {
  double g[3][3];  // g[i][j] = d u_i / d x_j
  for (int j = 0; j < 3; ++j) {
    Vec3 a = x, b = x;
    a[j] -= step;
    b[j] += step;
    const Vec3 ua = s.displacement(a, region), ub = s.displacement(b, region);
    for (int i = 0; i < 3; ++i) g[i][j] = (ub[i] - ua[i]) / (2 * step);
  }
  return {g[0][0], g[1][1], g[2][2], g[0][1] + g[1][0], g[0][2] + g[2][0], g[1][2] + g[2][1]};
}

Tensor6 strain_of_stress(const Tensor6& s, double E, double nu) {
  const double G = E / (2 * (1 + nu));
  return {(s[0] - nu * (s[1] + s[2])) / E,
          (s[1] - nu * (s[0] + s[2])) / E,
          (s[2] - nu * (s[0] + s[1])) / E,
          s[3] / G,
          s[4] / G,
          s[5] / G};
}

// div sigma by central differences.
Vec3 divergence(const ExactSolution& s, const Vec3& x, int region, double step) {
  static const int kIndex[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  Vec3 div{0, 0, 0};
  for (int j = 0; j < 3; ++j) {
    Vec3 a = x, b = x;
    a[j] -= step;
    b[j] += step;
    const Tensor6 sa = s.stress(a, region), sb = s.stress(b, region);
    for (int i = 0; i < 3; ++i) div[i] += (sb[kIndex[i][j]] - sa[kIndex[i][j]]) / (2 * step);
  }
  return div;
}

// Checks strains and equilibrium at every point of `points`, with stresses of scale `scale`.
void expect_elastic_field(const ExactSolution& s, const std::vector<Vec3>& points, int region,
                          double size, double scale) {
  const double step = 1e-5 * size;
  for (const Vec3& x : points) {
    SCOPED_TRACE(testing::Message() << "at (" << x[0] << ", " << x[1] << ", " << x[2] << ")");
    const Tensor6 e = strain_by_differences(s, x, region, step);
    const Tensor6 c = strain_of_stress(s.stress(x, region), s.young(region), s.poisson(region));
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(e[k], c[k], 1e-6 * scale / s.young(region)) << k;
    const Vec3 div = divergence(s, x, region, step);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(div[i], 0.0, 1e-6 * scale / size) << i;
  }
}

std::vector<Vec3> ring_points(double a, double b, double angle_from, double angle_to, double z) {
  std::vector<Vec3> out;
  for (double f : {0.1, 0.5, 0.9})
    for (double t : {0.1, 0.45, 0.8}) {
      const double r = a + f * (b - a), th = angle_from + t * (angle_to - angle_from);
      out.push_back({r * std::cos(th), r * std::sin(th), z});
    }
  return out;
}

Tensor6 polar_stress(const ExactSolution& s, double r, double th, int region, double* srr,
                     double* srt) {
  const Tensor6 t = s.stress({r * std::cos(th), r * std::sin(th), 0.0}, region);
  const double c = std::cos(th), n = std::sin(th);
  *srr = t[0] * c * c + t[1] * n * n + 2 * t[3] * c * n;
  *srt = (t[1] - t[0]) * c * n + t[3] * (c * c - n * n);
  return t;
}

// Lamé (Timoshenko & Goodier §28): sigma_rr = -p on the loaded wall and 0 on the free one; the
// SPEC §3.1.7 bore displacement (1 + nu) p R1^2 / (E (R2^2 - R1^2)) (R2^2 / R1 + (1 - 2 nu) R1).
TEST(ExactSolutions, LameCylinderIsAnElasticFieldWithItsPressures) {
  for (double nu : {0.3, 0.4999}) {
    const auto s = lame_cylinder(3, 9, 1, 0, 1000, nu);
    expect_elastic_field(*s, ring_points(3, 9, 0.0, kPi / 2, 0.3), 0, 9, 1.0);
    double srr = 0, srt = 0;
    polar_stress(*s, 3, 0.7, 0, &srr, &srt);
    EXPECT_NEAR(srr, -1.0, 1e-12);
    polar_stress(*s, 9, 0.7, 0, &srr, &srt);
    EXPECT_NEAR(srr, 0.0, 1e-12);
    EXPECT_NEAR(s->stress({5, 0, 0}, 0)[2], 2 * nu * 9.0 / 72.0, 1e-12);  // plane strain
    const double u = (1 + nu) * 9 / (1000 * 72.0) * (81 / 3.0 + (1 - 2 * nu) * 3);
    EXPECT_NEAR(s->displacement({3, 0, 0}, 0)[0], u, 1e-15);
  }
}

// SPEC §3.2.2: the compound cylinders' analytic contact pressure 3.294 (to the 4 digits given),
// u_r continuous and sigma_rr = -q on both sides of r = 2, the outer pressures met.
TEST(ExactSolutions, CompoundCylindersGiveTheSpecContactPressure) {
  const auto s = compound_cylinders(1, 2, 3, 5, 3, 10, 0.3, 20, 0.2);
  const double q = s->contact_pressure();
  EXPECT_NEAR(q, 3.294, 5e-4);
  EXPECT_NEAR(s->displacement({2, 0, 0}, 0)[0], s->displacement({2, 0, 0}, 1)[0], 1e-14);
  double srr = 0, srt = 0;
  polar_stress(*s, 2, 0.3, 0, &srr, &srt);
  EXPECT_NEAR(srr, -q, 1e-12);
  polar_stress(*s, 2, 0.3, 1, &srr, &srt);
  EXPECT_NEAR(srr, -q, 1e-12);
  polar_stress(*s, 1, 0.3, 0, &srr, &srt);
  EXPECT_NEAR(srr, -5, 1e-12);
  polar_stress(*s, 3, 0.3, 1, &srr, &srt);
  EXPECT_NEAR(srr, -3, 1e-12);
  expect_elastic_field(*s, ring_points(1, 2, 0, kPi / 2, 0.5), 0, 3, 5.0);
  expect_elastic_field(*s, ring_points(2, 3, 0, kPi / 2, 0.5), 1, 3, 5.0);
}

// Timoshenko & Goodier §21 with nu = 0: free top and bottom faces, the end shear sums to P, the
// neutral axis deflects P L^3 / (3 E I) at the tip (SPEC §2.1: 3.0857), the root's neutral axis
// stays in place.
TEST(ExactSolutions, CantileverIsExactWithParabolicEndShear) {
  const double L = 150, h = 5, b = 2.5, P = 5, E = 70000, I = b * h * h * h / 12;
  const auto s = timoshenko_cantilever(L, h, b, P, E);
  std::vector<Vec3> points;
  for (double x : {10.0, 75.0, 140.0})
    for (double z : {0.5, 2.5, 4.5}) points.push_back({x, 1.0, z});
  expect_elastic_field(*s, points, 0, L, P * L * h / I);
  for (double x : {0.0, 60.0, 150.0})
    for (double z : {0.0, 5.0}) {
      const Tensor6 t = s->stress({x, 0, z}, 0);
      EXPECT_NEAR(t[2], 0.0, 1e-12);
      EXPECT_NEAR(t[4], 0.0, 1e-12);
    }
  double resultant = 0;  // Simpson over the height of the end face
  const int n = 100;
  for (int k = 0; k <= n; ++k) {
    const double z = h * k / n, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    resultant += w * s->stress({L, 0, z}, 0)[4] * b * h / (3 * n);
  }
  EXPECT_NEAR(resultant, P, 1e-12 * P);
  EXPECT_NEAR(s->displacement({L, 0, h / 2}, 0)[2], P * L * L * L / (3 * E * I), 1e-12);
  EXPECT_NEAR(s->displacement({L, 0, h / 2}, 0)[2], 3.0857, 5e-5);
  const Vec3 root = s->displacement({0, 0, h / 2}, 0);
  for (double u : root) EXPECT_NEAR(u, 0.0, 1e-15);
  EXPECT_NEAR(s->stress({L, 0, 4}, 0)[0], 0.0, 1e-12);  // no moment at the loaded end
}

// Timoshenko & Goodier §31 (turned): traction-free curved faces, no normal force or moment on
// the tip (theta = 90 deg), whose shear sums to the end force P along +y.
TEST(ExactSolutions, CurvedBarCarriesItsEndForceOnly) {
  const double a = 4.12, b = 4.32, t = 0.1, P = 1, E = 1e7;
  const auto s = curved_bar(a, b, t, P, E);
  const double scale = 6 * P * 4.22 / (t * 0.2 * 0.2);  // bending stress at the root, roughly
  expect_elastic_field(*s, ring_points(a, b, 0.05, kPi / 2 - 0.05, 0.05), 0, 0.2, scale);
  for (double th : {0.0, 0.4, 1.2})
    for (double r : {a, b}) {
      double srr = 0, srt = 0;
      polar_stress(*s, r, th, 0, &srr, &srt);
      EXPECT_NEAR(srr, 0.0, 1e-9 * scale);
      EXPECT_NEAR(srt, 0.0, 1e-9 * scale);
    }
  double force_y = 0, normal = 0;
  const int n = 200;
  for (int k = 0; k <= n; ++k) {
    const double r = a + (b - a) * k / n, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    // At theta = 90 deg the face's outward normal e_theta is -x: traction = -(row x of sigma).
    const Tensor6 st = s->stress({0, r, 0}, 0);
    force_y += -w * st[3] * t * (b - a) / (3 * n);
    normal += w * st[0] * t * (b - a) / (3 * n);
  }
  EXPECT_NEAR(force_y, P, 1e-9);
  EXPECT_NEAR(normal, 0.0, 1e-9);
}

// SPEC §6.2: T(2) = 100, T(3) = 25, Laplace's equation, gradient = derivative of T.
TEST(ExactSolutions, CylinderWallTemperatureIsHarmonic) {
  const auto s = cylinder_wall_heat(2, 3, 100, 25, 1);
  ASSERT_TRUE(s->scalar());
  EXPECT_NEAR(s->temperature({2, 0, 0}), 100, 1e-12);
  EXPECT_NEAR(s->temperature({0, -3, 0.4}), 25, 1e-12);
  const double step = 1e-4;
  for (const Vec3& x : ring_points(2, 3, 0, 2 * kPi, 0.5)) {
    double laplace = 0;
    const Vec3 g = s->gradient(x);
    for (int d = 0; d < 3; ++d) {
      Vec3 a = x, b = x;
      a[d] -= step;
      b[d] += step;
      const double ta = s->temperature(a), tb = s->temperature(b);
      laplace += (tb - 2 * s->temperature(x) + ta) / (step * step);
      EXPECT_NEAR(g[d], (tb - ta) / (2 * step), 1e-6);
    }
    EXPECT_NEAR(laplace, 0.0, 1e-3);  // second differences: ~1e-8 / 1e-8 roundoff
  }
}

}  // namespace
}  // namespace styk::studies
