// SPEC §3.1.7: thick-walled cylinder, near incompressible, plane strain, with CPE8 (the thesis'
// CPE8 column of Tab 3.13 row 7). R1 = 3, R2 = 9, E = 1000, unit internal pressure, a 10 degree
// sector with symmetry on its radial edges (theta = 0: uy = 0; theta = 10 deg: tangential
// displacement 0 through a cylindrical *TRANSFORM about z), 5 CPE8 radially graded 4:1 (element
// sizes in ratio 1 : sqrt2 : 2 : 2 sqrt2 : 4 from the bore), 1 element around, arcs with their
// mid-node on the circle, thickness 1 (default), pressure as *DLOAD P4 on the bore edge.
//
// Theory: u(R1) = (1+nu) p R1^2 / (E (R2^2 - R1^2)) [R2^2 / R1 + (1 - 2 nu) R1].
//   nu      theory      thesis CPE8   Styk CPE8 (this mesh, measured)
//   0.3     4.5825e-3   -             4.5821e-3  (-0.01 %: the element itself is exact enough)
//   0.49    5.0399e-3   5.0386e-3     5.0334e-3  (-0.13 % theory, -0.10 % thesis)
//   0.499   5.0602e-3   5.0471e-3     4.9961e-3  (-1.27 % theory, -1.01 % thesis)
//   0.4999  5.0623e-3   4.9344e-3     4.4872e-3  (-11.4 % theory, -9.1 % thesis)
// Asserted: nu = 0.3 and 0.49 within 0.3 % of theory, 0.49 within 0.3 % of the thesis (grade A);
// nu = 0.499 within 2 % of theory (grade A, SPEC Tab 3.12) and 1.5 % of the thesis; nu = 0.4999
// locks (fully integrated CPE8, SPEC §3.1.7 "every element locks"): 5-15 % below theory and
// below the nu = 0.499 value. Not reproduced: the thesis' 4.9344e-3 at nu = 0.4999. The locked
// value depends strongly on the mesh, which only the lost figure shows (elements around the
// sector, mid-node placement): reversing the grading (fine at the outside) gives 1.10e-3, so a
// -2.5 % thesis value and our -11 % are both "locking", not a defect of the element (nu = 0.3
// agrees to 1e-4).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kR1 = 3.0, kR2 = 9.0, kE = 1000.0, kPressure = 1.0;

std::string number(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

double theory(double nu) {
  return (1 + nu) * kPressure * kR1 * kR1 / (kE * (kR2 * kR2 - kR1 * kR1)) *
         (kR2 * kR2 / kR1 + (1 - 2 * nu) * kR1);
}

// Node ids: ring k (0..10: element corners at even k, mid-nodes at odd k), angle index a (0, 1,
// 2 = 0, 5, 10 degrees): id = 1 + 3 k + a; the element centres (odd k, a = 1) are not used.
std::string cylinder_deck(double nu) {
  double sizes[5], total = 0.0;
  for (int e = 0; e < 5; ++e) total += sizes[e] = std::pow(std::sqrt(2.0), e);  // 4:1 graded
  double radius[11];
  radius[0] = kR1;
  for (int e = 0; e < 5; ++e) {
    const double h = sizes[e] * (kR2 - kR1) / total;
    radius[2 * e + 1] = radius[2 * e] + h / 2;
    radius[2 * e + 2] = radius[2 * e] + h;
  }
  std::string deck = "*HEADING\nSPEC 3.1.7 thick cylinder, CPE8\n*NODE, NSET=ALL\n";
  std::string edge0, edge10;
  for (int k = 0; k <= 10; ++k)
    for (int a = 0; a < 3; ++a) {
      if (k % 2 == 1 && a == 1) continue;
      const double theta = a * 5.0 * kPi / 180.0;
      const int id = 1 + 3 * k + a;
      deck += std::to_string(id) + ", " + number(radius[k] * std::cos(theta)) + ", " +
              number(radius[k] * std::sin(theta)) + ", 0\n";
      if (a == 0) edge0 += std::to_string(id) + "\n";
      if (a == 2) edge10 += std::to_string(id) + "\n";
    }
  deck += "*NSET, NSET=EDGE0\n" + edge0 + "*NSET, NSET=EDGE10\n" + edge10;
  deck += "*ELEMENT, TYPE=CPE8, ELSET=WALL\n";
  for (int e = 0; e < 5; ++e) {
    const int k = 2 * e;
    auto id = [](int ring, int a) { return std::to_string(1 + 3 * ring + a); };
    // Corners (r_k, 0), (r_k+2, 0), (r_k+2, 10), (r_k, 10) counter-clockwise, then mid-nodes of
    // the edges 1-2, 2-3, 3-4, 4-1. Edge P4 (node 4 -> 1) lies on the inner arc.
    deck += std::to_string(e + 1) + ", " + id(k, 0) + ", " + id(k + 2, 0) + ", " + id(k + 2, 2) +
            ", " + id(k, 2) + ", " + id(k + 1, 0) + ", " + id(k + 2, 1) + ", " + id(k + 1, 2) +
            ", " + id(k, 1) + "\n";
  }
  deck += "*MATERIAL, NAME=RUBBERLIKE\n*ELASTIC\n" + number(kE) + ", " + number(nu) +
          "\n*SOLID SECTION, ELSET=WALL, MATERIAL=RUBBERLIKE\n"
          "*TRANSFORM, NSET=EDGE10, TYPE=C\n0., 0., 0., 0., 0., 1.\n"
          "*BOUNDARY\nEDGE0, 2, 2\nEDGE10, 2, 2\n"
          "*STEP\n*STATIC\n*DLOAD\n1, P4, " +
          number(kPressure) + "\n*END STEP\n";
  return deck;
}

double bore_displacement(double nu) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("styk_spec_3_1_7_cpe8_" + number(nu) + ".inp");
  std::ofstream(path) << cylinder_deck(nu);
  ElementRegistry registry = test::builtin_registry();
  const Model model = read_inp(path.string(), registry);
  SolveOptions options;
  options.threads = 2;
  const Results results = run_static_analysis(model, registry, options, nullptr, nullptr);
  // Radial displacement of the three bore nodes (0, 5, 10 degrees), averaged.
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const int n = model.node_index(1 + a);
    const Vec3& x = model.coords[n];
    const Vec3& u = results.increments.back().U[n];
    sum += (u[0] * x[0] + u[1] * x[1]) / std::hypot(x[0], x[1]);
  }
  return sum / 3.0;
}

TEST(Spec317ThickCylinderCpe8, CompressibleAndNu049MatchTheoryAndTheThesis) {
  EXPECT_NEAR(bore_displacement(0.3) / theory(0.3), 1.0, 3e-3);  // theory 4.5825e-3
  const double u = bore_displacement(0.49);
  EXPECT_NEAR(u / theory(0.49), 1.0, 3e-3) << u;  // theory 5.0399e-3
  EXPECT_NEAR(u / 5.0386e-3, 1.0, 3e-3) << u;     // thesis CPE8
}

TEST(Spec317ThickCylinderCpe8, Nu0499IsGradeA) {
  const double u = bore_displacement(0.499);
  EXPECT_NEAR(u / theory(0.499), 1.0, 2e-2) << u;  // theory 5.0602e-3
  EXPECT_NEAR(u / 5.0471e-3, 1.0, 1.5e-2) << u;    // thesis CPE8
}

TEST(Spec317ThickCylinderCpe8, Nu04999ShowsVolumetricLocking) {
  const double u = bore_displacement(0.4999);
  const double ratio = u / theory(0.4999);  // theory 5.0623e-3; thesis CPE8 4.9344e-3
  EXPECT_LT(ratio, 0.95) << u;
  EXPECT_GT(ratio, 0.85) << u;
  EXPECT_LT(u, bore_displacement(0.499));  // stiffer as nu -> 0.5, where theory grows
}

}  // namespace
}  // namespace styk
