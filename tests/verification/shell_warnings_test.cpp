// The shell warnings before solving (solver/src/shell_warnings.hpp, SPEC §7.3): a thin fully
// integrated S8 plate warns with its measured slenderness and the remedies; the 2x2 rules' spurious
// modes are counted on a flat patch and warned of; the locking-free types stay silent.
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shell_decks.hpp"

namespace styk {
namespace {

// Tab 7.1b's quarter plate (2 x 2 elements of size 0.25) of thickness t.
std::vector<std::string> plate_warnings(const std::string& type, double t) {
  ElementRegistry registry;
  register_builtin_elements(registry);
  test::ShellGrid g;
  g.type = type;
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
  test::solve_grid(g, "warn_" + type + "_" + std::to_string(t) + ".inp", 0, 0, registry, &report);
  return report.warnings;
}

int count_containing(const std::vector<std::string>& warnings, const std::string& text) {
  int n = 0;
  for (const std::string& w : warnings) n += w.find(text) != std::string::npos ? 1 : 0;
  return n;
}

TEST(ShellWarnings, ThinS8PlateWarnsOfShearLockingWithItsSlenderness) {
  // size 0.25 / t 0.001 = 250: the message states it and the remedies.
  const std::vector<std::string> w = plate_warnings("S8", 0.001);
  ASSERT_EQ(count_containing(w, "S8 elements of element set SHELL are thin"), 1) << w.size();
  EXPECT_EQ(count_containing(w, "element size / thickness up to 250 (element"), 1);
  EXPECT_EQ(count_containing(w, "remedy: reduced integration (S8R), the 9-node Lagrange shell"), 1);
  // Thick (size / t = 2.5, 0.7 % too stiff): no warning.
  EXPECT_EQ(count_containing(plate_warnings("S8", 0.1), "are thin"), 0);
  // The 9-node and 4-node elements do not lock: silent at any thickness.
  for (const char* type : {"S9", "S4", "S8R", "S9R", "STRI3"})
    EXPECT_EQ(count_containing(plate_warnings(type, 0.001), "are thin"), 0) << type;
}

TEST(ShellWarnings, SpuriousModesOfTheReducedRulesAreCounted) {
  // Flat 2x2 patch, measured: S9R four modes beyond the rigid motions; none for S4, S8, S9 and
  // S8R (the single S8R element's two spurious modes do not survive in a patch), none for the
  // discrete-Kirchhoff STRI3 (the patch's squares cut into two triangles each).
  EXPECT_EQ(
      count_containing(plate_warnings("S9R", 0.01), "have 4 zero-energy modes in a flat 2x2 patch"),
      1);
  for (const char* type : {"S4", "S8", "S8R", "S9", "STRI3"})
    EXPECT_EQ(count_containing(plate_warnings(type, 0.01), "zero-energy modes"), 0) << type;
}

// Small meshes of reduced-integration shells are checked whole (at most 16 elements): the
// single S8R element's two spurious modes, which the 2x2 patch does not show, are warned of on
// a one-element plate clamped on one edge (it solves: the clamp restrains them); strips and
// patches of S8R stay silent, as do the types without spurious modes.
std::vector<std::string> clamped_mesh_warnings(const std::string& type, int nx, int ny) {
  ElementRegistry registry;
  register_builtin_elements(registry);
  test::ShellGrid g;
  g.type = type;
  g.nx = nx;
  g.ny = ny;
  g.map = [nx](double s, double r) { return std::array<double, 3>{0.25 * nx * s, 0.25 * r, 0.0}; };
  g.fixed = [](int i, int, int, int) {
    return i == 0 ? std::vector<int>{1, 2, 3, 4, 5, 6} : std::vector<int>{};
  };
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

TEST(ShellWarnings, SmallReducedMeshesAreCheckedWhole) {
  EXPECT_EQ(count_containing(clamped_mesh_warnings("S8R", 1, 1),
                             "(2 zero-energy modes beyond the rigid motions when assembled"),
            1);
  // Two elements side by side restrain each other's modes already (measured: none in 2 x 1,
  // 4 x 1 and 4 x 2).
  for (const int nx : {2, 4})
    EXPECT_EQ(count_containing(clamped_mesh_warnings("S8R", nx, 1), "zero-energy modes"), 0) << nx;
  EXPECT_EQ(count_containing(clamped_mesh_warnings("S8R", 4, 2), "zero-energy modes"), 0);
  for (const char* type : {"S4R", "S8", "S9", "STRI3"})
    EXPECT_EQ(count_containing(clamped_mesh_warnings(type, 1, 1), "zero-energy modes"), 0) << type;
}

}  // namespace
}  // namespace styk
