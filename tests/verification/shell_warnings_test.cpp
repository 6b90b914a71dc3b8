// The shell warnings before solving (solver/src/shell_warnings.hpp, SPEC §7.3): a thin S8 or S8R
// plate on a coarse mesh warns with its measured slenderness, the estimated loss and the remedies;
// spurious modes that a small reduced-integration mesh's supports leave free are counted and
// warned of; the locking-free types stay silent.
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "shell_decks.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

// Tab 7.1b's quarter plate (n x n elements, 2 x 2 of size 0.25 unless asked) of thickness t:
// the warnings and the centre deflection.
struct PlateRun {
  std::vector<std::string> warnings;
  double w = 0.0;
};

PlateRun quarter_plate(const std::string& type, double t, int n = 2) {
  const ElementRegistry& registry = test::shared_builtin_registry();
  test::ShellGrid g;
  g.type = type;
  g.nx = g.ny = n;
  g.map = [](double s, double r) { return std::array<double, 3>{0.5 * s, 0.5 * r, 0.0}; };
  g.fixed = [](int i, int j, int imax, int jmax) {
    std::vector<int> dofs;
    if (i == 0)
      for (const int d : {3, 4}) dofs.push_back(d);
    if (j == 0)
      for (const int d : {3, 5}) dofs.push_back(d);
    if (i == imax)
      for (const int d : {1, 5, 6}) dofs.push_back(d);
    if (j == jmax)
      for (const int d : {2, 4, 6}) dofs.push_back(d);
    return dofs;
  };
  g.thickness = t;
  g.young = 10.92e5;
  g.load = "*DLOAD\nSHELL, P, 10.\n";
  AnalysisReport report;
  const int centre = test::grid_order(g) * n;
  const Vec3 u = test::solve_grid(
      g, "warn_" + type + "_" + std::to_string(n) + "_" + std::to_string(t) + ".inp", centre,
      centre, registry, &report);
  return {report.warnings, std::abs(u[2])};
}

std::vector<std::string> plate_warnings(const std::string& type, double t) {
  return quarter_plate(type, t).warnings;
}

int count_containing(const std::vector<std::string>& warnings, const std::string& text) {
  int n = 0;
  for (const std::string& w : warnings) n += w.find(text) != std::string::npos ? 1 : 0;
  return n;
}

// SPEC §7.3 Tab 7.1b on its 2 x 2 quarter (tests/verification/spec_7_3_plates_test.cpp): S8
// 0.125 of the Mindlin series at t = 0.001 (size / t 250), S8R 0.46; both warned with the loss
// their locking law estimates (solver/src/shell_locking.cpp: f = 6.9 and 1.1, 87 % and 53 %).
TEST(ShellWarnings, ThinS8PlateWarnsOfShearLockingWithItsSlenderness) {
  // size 0.25 / t 0.001 = 250: the message states it and the remedies.
  const std::vector<std::string> w = plate_warnings("S8", 0.001);
  ASSERT_EQ(count_containing(w, "S8 elements of element set SHELL are thin"), 1) << w.size();
  EXPECT_EQ(count_containing(w, "element size / thickness up to 250 (element"), 1);
  EXPECT_EQ(count_containing(w, "on a shell 0.5 across"), 1);
  EXPECT_EQ(count_containing(w, "its deflection estimated 87 % short"), 1);
  EXPECT_EQ(count_containing(w, "remedy: reduced integration (S8R), the 9-node Lagrange shell"), 1);
  const std::vector<std::string> r = plate_warnings("S8R", 0.001);
  ASSERT_EQ(count_containing(r, "S8R elements of element set SHELL are thin"), 1) << r.size();
  EXPECT_EQ(count_containing(r, "its deflection estimated 53 % short"), 1);
  EXPECT_EQ(count_containing(r, "remedy: the 9-node Lagrange shell (S9R or S9)"), 1);
  // Thick (size / t = 2.5, 0.7 % too stiff) and S8R at size / t 25 (1.1 % short): no warning.
  EXPECT_EQ(count_containing(plate_warnings("S8", 0.1), "are thin"), 0);
  EXPECT_EQ(count_containing(plate_warnings("S8R", 0.01), "are thin"), 0);
  // The 9-node and 4-node elements do not lock: silent at any thickness.
  for (const char* type : {"S9", "S4", "S9R", "STRI3"})
    EXPECT_EQ(count_containing(plate_warnings(type, 0.001), "are thin"), 0) << type;
}

// The locking estimate on a finer mesh, 8 x 8 on the quarter (h / extent = 1/8): the loss
// against the Kirchhoff plate w = 0.00406235 q a^4 / D (D = E t^3 / (12 (1 - nu^2)) = 1e5 t^3;
// the Mindlin shear term, 5.2 (t / a)^2, is below 1e-8 here) is warned of from an estimated
// 10 %: S8 1.3 % short at t = 3e-4 (size / t 208, silent), 57 % at 3e-5 (warned); S8R 1.6 % at
// 3e-5 (silent), 15 % at 1e-5 (warned). Measured values to 0.5 %.
TEST(ShellWarnings, TheLockingEstimateSeparatesAFinerMesh) {
  const auto loss = [](const PlateRun& r, double t) {
    return 1.0 - r.w / (0.00406235 * 10.0 / (1e5 * t * t * t));
  };
  const struct {
    const char* type;
    double t, loss;
    bool warned;
  } cases[] = {{"S8", 3e-4, 0.013, false},
               {"S8", 3e-5, 0.567, true},
               {"S8R", 3e-5, 0.016, false},
               {"S8R", 1e-5, 0.146, true}};
  for (const auto& c : cases) {
    const PlateRun r = quarter_plate(c.type, c.t, 8);
    EXPECT_NEAR(loss(r, c.t), c.loss, 0.005) << c.type << " " << c.t;
    EXPECT_EQ(count_containing(r.warnings, "locks in shear"), c.warned ? 1 : 0)
        << c.type << " " << c.t;
  }
}

// The plates of Tab 7.1b hold every mode with their supports and symmetry planes: no
// zero-energy-mode warning for any type, S9R included (a 2 x 2 S9R patch held only against its
// rigid motions keeps 4 such modes: below).
TEST(ShellWarnings, SupportedPlatesCarryNoSpuriousModes) {
  for (const char* type : {"S4", "S4R", "S8", "S8R", "S9", "S9R", "STRI3"})
    EXPECT_EQ(count_containing(plate_warnings(type, 0.01), "zero-energy modes"), 0) << type;
}

// Small meshes of reduced-integration shells are checked whole with their supports (at most 16
// elements). Clamped on one edge, a single S8R element and strips and patches of S8R solve and
// stay silent: the clamp holds the single element's two spurious modes. Held only at three
// corners against the rigid motions, the single S8R element keeps its 2 modes and a 2 x 2 S9R
// patch its 4: warned, then refused as singular by the solver.
std::vector<std::string> mesh_warnings(
    const std::string& type, int nx, int ny,
    const std::function<std::vector<int>(int, int, int, int)>& fixed) {
  const ElementRegistry& registry = test::shared_builtin_registry();
  test::ShellGrid g;
  g.type = type;
  g.nx = nx;
  g.ny = ny;
  g.map = [nx](double s, double r) { return std::array<double, 3>{0.25 * nx * s, 0.25 * r, 0.0}; };
  g.fixed = fixed;
  g.thickness = 0.01;
  g.young = 10.92e5;
  g.load = "*DLOAD\nSHELL, P, 10.\n";
  AnalysisReport report;
  try {
    test::solve_grid(g,
                     "mesh_" + type + "_" + std::to_string(nx) + "x" + std::to_string(ny) + ".inp",
                     0, 0, registry, &report);
  } catch (const InputError& e) {
    report.warnings.push_back(std::string("refused: ") + e.what());
  }
  for (const std::string& w : report.warnings)
    std::printf("%s %dx%d: %s\n", type.c_str(), nx, ny, w.c_str());
  return report.warnings;
}

std::vector<int> clamped_edge(int i, int, int, int) {
  return i == 0 ? std::vector<int>{1, 2, 3, 4, 5, 6} : std::vector<int>{};
}

// x, y, z at one corner, y and z at the next along x, z at the next along y: the rigid motions.
std::vector<int> three_corners(int i, int j, int imax, int jmax) {
  if (i == 0 && j == 0) return {1, 2, 3};
  if (i == imax && j == 0) return {2, 3};
  if (i == 0 && j == jmax) return {3};
  return {};
}

TEST(ShellWarnings, SmallReducedMeshesAreCheckedWholeWithTheirSupports) {
  for (const auto& [nx, ny] : {std::pair{1, 1}, {2, 1}, {4, 1}, {4, 2}})
    EXPECT_EQ(count_containing(mesh_warnings("S8R", nx, ny, clamped_edge), "zero-energy modes"), 0)
        << nx << "x" << ny;
  const std::vector<std::string> single = mesh_warnings("S8R", 1, 1, three_corners);
  EXPECT_EQ(count_containing(single, "has 2 zero-energy modes that its supports leave free"), 1);
  EXPECT_EQ(count_containing(single, "refused: "), 1);
  const std::vector<std::string> patch = mesh_warnings("S9R", 2, 2, three_corners);
  EXPECT_EQ(count_containing(patch, "has 4 zero-energy modes that its supports leave free"), 1);
  for (const char* type : {"S4R", "S8", "S9", "STRI3"})
    EXPECT_EQ(count_containing(mesh_warnings(type, 1, 1, three_corners), "zero-energy modes"), 0)
        << type;
}

}  // namespace
}  // namespace styk
