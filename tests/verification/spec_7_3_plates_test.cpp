// SPEC §7.3 Tab 7.1b and Tab 7.2 "where methods fail" for plates, solved from CalculiX decks
// (*SHELL SECTION, *DLOAD P) through the reader and the solver.
//
// The plate: square, side a = 1, simply supported on all four edges, uniform load q = 10,
// E = 10.92e5, nu = 0.3, thickness t = 1 ... 0.001. The table's values are 1000 w D1 / (q a^4)
// with D1 = E / (12 (1 - nu^2)), the bending stiffness of t = 1 (Kirchhoff: 4.06235 / t^3,
// Timoshenko's 0.00406235 q a^4 / D). Truth is analytic: the Navier series of the Kirchhoff plate
// and, for the Mindlin plate with hard simple supports (w = 0 and no rotation along the edge),
// Kirchhoff plus the Marcus moment over k G t (k = 5/6), both summed here to 1e-10.
// The thesis does not state its mesh. Styk models a quarter (symmetry on x = a/2 and y = a/2)
// with 2 x 2 elements, i.e. 4 x 4 on the whole plate, for Tab 7.1b; Tab 7.2's "n x n" meshes are
// whole-plate meshes, here n/2 x n/2 on the quarter.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shell_decks.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 10.92e5, kNu = 0.3, kQ = 10.0;
const double kD1 = kE / (12.0 * (1.0 - kNu * kNu));

// Centre deflection of the hard simply supported square (side 1) in the table's units:
// Kirchhoff (shear = false) or Mindlin (k = 5/6).
double series_centre(double t, bool shear) {
  const double D = kE * t * t * t / (12.0 * (1.0 - kNu * kNu));
  const double kGt = 5.0 / 6.0 * kE / (2.0 * (1.0 + kNu)) * t;
  double w = 0.0;
  for (int m = 1; m < 4000; m += 2)
    for (int n = 1; n < 4000; n += 2) {
      const double sign = ((m + n) / 2) % 2 == 1 ? 1.0 : -1.0;  // sin(m pi/2) sin(n pi/2)
      const double k2 = (m * m + n * n) * kPi * kPi;
      w += sign * 16.0 * kQ / (kPi * kPi * m * n) *
           (1.0 / (D * k2 * k2) + (shear ? 1.0 / (kGt * k2) : 0.0));
    }
  return 1000.0 * w * kD1 / kQ;
}

// The quarter plate [0, 1/2]^2: simply supported (uz, and the rotation along the edge) on x = 0
// and y = 0, symmetric on x = 1/2 (ux, ry, rz) and y = 1/2 (uy, rx, rz).
test::ShellGrid quarter_plate(const std::string& type, int n, double t, bool soft = false) {
  test::ShellGrid g;
  g.type = type;
  g.nx = g.ny = n;
  g.map = [](double s, double r) { return std::array<double, 3>{0.5 * s, 0.5 * r, 0.0}; };
  g.fixed = [soft](int i, int j, int imax, int jmax) {
    std::vector<int> dofs;
    if (i == 0)
      for (const int d : {3, soft ? 3 : 4}) dofs.push_back(d);
    if (j == 0)
      for (const int d : {3, soft ? 3 : 5}) dofs.push_back(d);
    if (i == imax)
      for (const int d : {1, 5, 6}) dofs.push_back(d);
    if (j == jmax)
      for (const int d : {2, 4, 6}) dofs.push_back(d);
    return dofs;
  };
  g.thickness = t;
  g.young = kE;
  g.poisson = kNu;
  g.load = "*DLOAD\nSHELL, P, 10.\n";
  return g;
}

// Centre deflection of the quarter plate of n x n elements in the table's units (P pushes
// along the +z normal, as in CalculiX: w > 0).
double centre(const std::string& type, int n, double t, const ElementRegistry& registry,
              bool soft = false) {
  const test::ShellGrid g = quarter_plate(type, n, t, soft);
  const int last = test::grid_order(g) * n;
  const Vec3 u = test::solve_grid(g,
                                  "plate_" + type + (soft ? "_soft_" : "_") + std::to_string(n) +
                                      "_" + std::to_string(t) + ".inp",
                                  last, last, registry);
  return 1000.0 * u[2] * kD1 / kQ;
}

TEST(Spec73Plates, SeriesSolutionsOfTheSimplySupportedSquare) {
  // Timoshenko & Woinowsky-Krieger: 0.00406235 q a^4 / D.
  EXPECT_NEAR(series_centre(1.0, false), 4.06235, 5e-6);
  EXPECT_NEAR(series_centre(0.001, false) * 1e-9, 4.06235, 5e-6);
}

// Styk's values (table units) and the thesis' (SPEC §7.3) per thickness, columns S8R (8-node
// serendipity 2x2), S8 (3x3), S9R (9-node Lagrange 2x2), S9 (3x3); quarter plate of 2 x 2.
struct Row {
  double t;
  double styk[4];
  const char* thesis[4];
};
const Row kTab71b[] = {
    {1.0, {25.0678, 25.0652, 25.1412, 25.1119}, {"4.61", "4.49", "4.63", "4.50"}},
    {0.1, {4270.13, 4242.61, 4281.18, 4255.90}, {"4144.28", "3735.05", "4189.70", "3938.95"}},
    {0.01, {4.02044e6, 3.73126e6, 4.07258e6, 3.98447e6}, {"3.83e6", "5.13e5", "4.18e6", "3.98e6"}},
    {0.001,
     {1.86786e9, 5.06526e8, 4.07049e9, 3.98000e9},
     {"3.79e9", "5.86e6", "4.18e9", "3.98e9"}}};
const char* const kTypes71b[4] = {"S8R", "S8", "S9R", "S9"};

// Tab 7.1b. Asserted: every Styk cell to 5e-4 (docs/verification.md prints it to 4 digits); the
// trends against the Mindlin series: the 9-node elements stay within 0.3 % (2x2) and 2.1 % (3x3)
// at every thickness, the 3x3 serendipity plate locks (w / w_Mindlin 0.998, 0.993, 0.918, 0.125
// as t falls), and on this coarse mesh the 2x2 serendipity plate locks too at t = 0.001 (0.46;
// it converges on finer meshes, Tab72MeshSeries). The 9-node 3x3 plate reproduces the thesis'
// printed 3.98e6 and 3.98e9; the thesis' t = 1 row (4.5-4.6) is not a Mindlin plate of side 1
// (the series gives 25.11, the shear term alone 5.2 times the Kirchhoff value), so there the
// thesis and Styk differ by a factor 5.4, a definition the thesis does not state.
TEST(Spec73Plates, Tab71bSerendipityLocksLagrangeStays) {
  const ElementRegistry registry = test::builtin_registry();
  double previous_s8 = 1.0;
  for (const Row& row : kTab71b) {
    const double mindlin = series_centre(row.t, true);
    for (int c = 0; c < 4; ++c) {
      const double w = centre(kTypes71b[c], 2, row.t, registry);
      std::printf("t = %g %-4s Styk %.6g (thesis %s), Mindlin %.6g, Styk / Mindlin %.4f\n", row.t,
                  kTypes71b[c], w, row.thesis[c], mindlin, w / mindlin);
      EXPECT_NEAR(w, row.styk[c], 5e-4 * row.styk[c]) << kTypes71b[c] << " t = " << row.t;
      if (c == 2) {
        EXPECT_NEAR(w / mindlin, 1.0, 0.003) << "S9R t = " << row.t;
      }
      if (c == 3) {
        EXPECT_NEAR(w / mindlin, 1.0, 0.021) << "S9 t = " << row.t;
      }
      if (c == 1) {
        EXPECT_LT(w / mindlin, previous_s8) << "S8 locks more as t falls";
        previous_s8 = w / mindlin;
      }
    }
  }
  EXPECT_LT(previous_s8, 0.13);                                    // S8 at t = 0.001
  EXPECT_NEAR(centre("S9", 2, 0.01, registry), 3.98e6, 0.005e6);   // thesis 3.98e6
  EXPECT_NEAR(centre("S9", 2, 0.001, registry), 3.98e9, 0.005e9);  // thesis 3.98e9
}

// Tab 7.2 (t = 0.001): the 9-node reduced plate on whole-plate meshes 2x2 ... 64x64 (thesis
// 4.65, 4.18, 4.09, 4.07, 4.06, 4.06 e9) converges from above to the Kirchhoff 4.06235e9
// (64x64: within 1e-5), as the thesis' does, from a smaller start (2x2: 4.219). The thesis'
// 4-node Kirchhoff column has no Styk element; the 4-node Mindlin S4 (MITC4) series is shown in
// its place (from below). Each value asserted to 5e-4 (table units / 1e9).
TEST(Spec73Plates, Tab72MeshSeries) {
  const ElementRegistry registry = test::builtin_registry();
  const int quarter[6] = {1, 2, 4, 8, 16, 32};
  const double s9r[6] = {4.21877, 4.07049, 4.06285, 4.06240, 4.06238, 4.06237};
  const double s4[6] = {3.18880, 3.96901, 4.04144, 4.05723, 4.06109, 4.06205};
  for (int k = 0; k < 6; ++k) {
    const double a = centre("S9R", quarter[k], 0.001, registry) * 1e-9;
    const double b = centre("S4", quarter[k], 0.001, registry) * 1e-9;
    std::printf("whole plate %dx%d: S9R %.6g, S4 %.6g\n", 2 * quarter[k], 2 * quarter[k], a, b);
    EXPECT_NEAR(a, s9r[k], 5e-4 * s9r[k]);
    EXPECT_NEAR(b, s4[k], 5e-4 * s4[k]);
    if (k == 5) {
      EXPECT_NEAR(a, 4.06235, 4.06235e-5);  // 64 x 64 against Kirchhoff
    }
  }
  // The 2x2 serendipity plate, locked at 4 x 4 (Tab 7.1b), converges on finer meshes.
  EXPECT_NEAR(centre("S8R", 4, 0.001, registry) * 1e-9, 4.04576, 5e-4 * 4.04576);
  EXPECT_NEAR(centre("S8R", 8, 0.001, registry) * 1e-9, 4.06228, 5e-4 * 4.06228);
}

// Tab 7.2's Kirchhoff column: STRI3 (Styk's discrete-Kirchhoff triangle; each cell of the
// quarter plate cut into two along its diagonal, the whole plate being the quarter mirrored) on
// the meshes of Tab72MeshSeries, t = 0.001, against the Kirchhoff series 4.06235 (table units /
// 1e9). The thesis' Kirchhoff element has 4 nodes (4.13, 4.08, 4.07, 4.06 from 8x8 on): a
// different element, so the values differ; the trend is the same (convergence to the Kirchhoff
// plate from above on the fine meshes). Asserted: every value to 5e-4; 64x64 within 5e-5 of the
// series; from 8x8 on the error is positive and falls by 1.9, 3.2, 3.5 per halving (measured,
// approaching the h^2 rate 4; the last ratio asserted within 3 ... 4.5); the element has no
// shear strain, so its t^3 w is the same at every thickness (16x16, t = 1 ... 0.001, to 1e-9).
TEST(Spec73Plates, Tab72KirchhoffTriangleSeries) {
  const ElementRegistry registry = test::builtin_registry();
  const int quarter[6] = {1, 2, 4, 8, 16, 32};
  const double stri3[6] = {4.16146, 4.05587, 4.06485, 4.06367, 4.06277, 4.06247};
  const double kirchhoff = series_centre(0.001, false) * 1e-9;
  double previous_error = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double w = centre("STRI3", quarter[k], 0.001, registry) * 1e-9;
    std::printf("whole plate %dx%d: STRI3 %.6g (Kirchhoff %.6g)\n", 2 * quarter[k], 2 * quarter[k],
                w, kirchhoff);
    EXPECT_NEAR(w, stri3[k], 5e-4 * stri3[k]);
    const double error = w - kirchhoff;
    if (k >= 3) {
      EXPECT_GT(error, 0.0) << "from above";
      EXPECT_GT(previous_error / error, 1.5) << "falls";
    }
    if (k == 5) {
      EXPECT_GT(previous_error / error, 3.0);
      EXPECT_LT(previous_error / error, 4.5);
    }
    previous_error = error;
    if (k == 5) {
      EXPECT_NEAR(w, kirchhoff, 5e-5 * kirchhoff);
    }
  }
  const double thin = centre("STRI3", 8, 0.001, registry) * 1e-9;
  for (const double t : {1.0, 0.1, 0.01}) {
    const double scaled = centre("STRI3", 8, t, registry) * t * t * t;
    EXPECT_NEAR(scaled, thin, 1e-9 * thin) << "t = " << t;
  }
}

// The clamped square (w = 0 and both rotations fixed on the edges), t = 0.001, STRI3 as above,
// against the Kirchhoff plate's centre deflection 0.00126532 q a^4 / D (Timoshenko &
// Woinowsky-Krieger, "Theory of plates and shells", Table 35: 0.00126; the series to six digits
// in Taylor & Govindjee 2004, "Solution of clamped rectangular plate problems"). Measured
// 1.54738e-3, 1.34741e-3, 1.28653e-3, 1.27068e-3 for whole plates of 4x4 ... 32x32, asserted to
// 5e-4; the error falls as h^2 (ratios 3.44, 3.87, 3.91 measured; 3.5 ... 4.5 asserted from 8x8
// on) and 32x32 is within 0.5 %.
TEST(Spec73Plates, ClampedSquareKirchhoffTriangles) {
  const ElementRegistry registry = test::builtin_registry();
  const double reference = 0.00126532;
  const double measured[4] = {1.547384e-3, 1.347411e-3, 1.286532e-3, 1.270678e-3};
  double previous_error = 0.0;
  int k = 0;
  for (const int n : {2, 4, 8, 16}) {
    test::ShellGrid g = quarter_plate("STRI3", n, 0.001);
    g.fixed = [](int i, int j, int imax, int jmax) {
      std::vector<int> dofs;
      if (i == 0 || j == 0) dofs = {3, 4, 5};
      if (i == imax)
        for (const int d : {1, 5, 6}) dofs.push_back(d);
      if (j == jmax)
        for (const int d : {2, 4, 6}) dofs.push_back(d);
      return dofs;
    };
    const Vec3 u =
        test::solve_grid(g, "clamped_stri3_" + std::to_string(n) + ".inp", n, n, registry);
    const double D = kE * 1e-9 / (12.0 * (1.0 - kNu * kNu));
    const double w = u[2] * D / kQ;
    std::printf("clamped %dx%d: w D / (q a^4) = %.7g (Kirchhoff %.6g)\n", 2 * n, 2 * n, w,
                reference);
    EXPECT_NEAR(w, measured[k], 5e-4 * measured[k]);
    const double error = w - reference;
    if (k >= 2) {
      EXPECT_GT(previous_error / error, 3.5);
      EXPECT_LT(previous_error / error, 4.5);
    }
    previous_error = error;
    ++k;
  }
  EXPECT_NEAR(measured[3], reference, 0.005 * reference);
}

}  // namespace
}  // namespace styk

namespace styk {
namespace {

// SPEC §3.1.5, the S8R column: the thick square plate 400 x 400 x 40, E = 2000, nu = 0.15, P = 16
// at the centre; deflection of the centre (the shell's mid-surface; the solids' bottom face),
// whole plate of 6 x 6 and 10 x 10 S8R. "Edge nodes fully fixed" is, for the shell, the three
// translations of the edge nodes with the rotations free (what fixing the nodes of a solid's
// edge does): so Styk reproduces every printed digit of the thesis' Abaqus S8R, 3.2827e-3 and
// 3.3350e-3 (asserted to half a unit of the last digit), within 1.2 % and 0.4 % of the published
// theory 0.003322. Clamping the rotations as well halves the deflection (measured 1.679e-3 and
// 1.729e-3), which no column of the table shows.
double thick_plate_centre(const std::string& type, int n, const ElementRegistry& registry,
                          bool clamp_rotations = false) {
  test::ShellGrid g;
  g.type = type;
  g.nx = g.ny = n;
  g.map = [](double s, double r) { return std::array<double, 3>{400.0 * s, 400.0 * r, 0.0}; };
  g.fixed = [clamp_rotations](int i, int j, int imax, int jmax) {
    if (i == 0 || j == 0 || i == imax || j == jmax)
      return clamp_rotations ? std::vector<int>{1, 2, 3, 4, 5, 6} : std::vector<int>{1, 2, 3};
    return std::vector<int>{};
  };
  g.thickness = 40.0;
  g.young = 2000.0;
  g.poisson = 0.15;
  const int mid = test::grid_order(g) * n / 2;
  g.load = "*CLOAD\n" + std::to_string(test::grid_node(g, mid, mid)) + ", 3, -16.\n";
  return -test::solve_grid(
      g, "thick_plate_" + type + (clamp_rotations ? "_clamped_" : "_") + std::to_string(n) + ".inp",
      mid, mid, registry)[2];
}

TEST(Spec315ThickPlate, S8RColumn) {
  ElementRegistry registry = test::builtin_registry();
  const double w6 = thick_plate_centre("S8R", 6, registry);
  const double w10 = thick_plate_centre("S8R", 10, registry);
  std::printf(
      "SPEC 3.1.5 S8R: 6x6 %.5g (thesis 3.2827e-3), 10x10 %.5g (thesis 3.3350e-3), "
      "theory 3.322e-3\n",
      w6, w10);
  EXPECT_NEAR(w6, 3.2827e-3, 0.00005e-3);
  EXPECT_NEAR(w10, 3.3350e-3, 0.00005e-3);
  EXPECT_NEAR(thick_plate_centre("S8R", 6, registry, true), 1.679e-3, 0.0005e-3);
  EXPECT_NEAR(thick_plate_centre("S8R", 10, registry, true), 1.7291e-3, 0.00005e-3);
}

}  // namespace
}  // namespace styk
