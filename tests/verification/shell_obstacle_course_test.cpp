// The shell obstacle course (MacNeal & Harder 1985, "A proposed standard set of problems to test
// finite element accuracy", Finite Elements in Analysis and Design 1; Belytschko et al. 1985),
// SPEC §7.3 "Structural benchmarks outside the thesis", solved from CalculiX decks through the
// reader and the solver. Symmetric parts are modelled with symmetry conditions:
// - Scordelis-Lo roof: R = 25, length 50, 80 degree arc, t = 0.25, E = 4.32e8, nu = 0, weight
//   90 per unit area (GRAV with density 360 over t = 0.25), curved ends on rigid diaphragms
//   (uy = uz = 0), straight edges free; vertical deflection at the middle of a free edge 0.3024
//   (MacNeal-Harder's reference; 0.3086 is the deep-shell value some sources give). Quarter.
// - Pinched cylinder with end diaphragms (uy = uz = rx = 0): R = 300, length 600, t = 3,
//   E = 3e6, nu = 0.3, two opposite radial loads P = 1 at mid-length; radial deflection under a
//   load 1.8248e-5. Octant, carrying P / 4.
// - Pinched hemisphere with an 18 degree hole: R = 10, t = 0.04, E = 6.825e7, nu = 0.3, radial
//   loads 2 at the equator, alternating out and in every 90 degrees; deflection at a load point
//   0.094 (MacNeal-Harder; 0.093 in Belytschko's). Quarter (longitude 0-90 degrees, each load
//   halved by its symmetry plane), uz fixed at one point against the rigid motion.
// - Twisted beam: length 12, width 1.1, twisted 90 degrees from the clamped root to the tip,
//   E = 29e6, nu = 0.22, t = 0.32 (and the thin t = 0.0032 with the force scaled by 1e-6); a
//   unit tip force spread over the tip edge, in the tip's plane (z) or out of it (y); tip
//   deflection along the force at the edge's middle node 5.424e-3 and 1.754e-3 (MacNeal-Harder;
//   thin: 5.256e-3 and 1.294e-3). Whole beam.
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shell_decks.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The quarter roof: x = 25 s (x = 0 mid-span), angle 40 r degrees from the crown.
test::ShellGrid scordelis_lo(const std::string& type, int n) {
  test::ShellGrid g;
  g.type = type;
  g.nx = g.ny = n;
  g.map = [](double s, double r) {
    const double phi = 40.0 * kPi / 180.0 * r;
    return std::array<double, 3>{25.0 * s, 25.0 * std::sin(phi), 25.0 * std::cos(phi)};
  };
  g.fixed = [](int i, int j, int imax, int) {
    std::vector<int> dofs;
    if (i == 0)
      for (const int d : {1, 5, 6}) dofs.push_back(d);  // mid-span symmetry
    if (j == 0)
      for (const int d : {2, 4, 6}) dofs.push_back(d);  // crown symmetry
    if (i == imax)
      for (const int d : {2, 3}) dofs.push_back(d);  // diaphragm
    return dofs;
  };
  g.thickness = 0.25;
  g.young = 4.32e8;
  g.poisson = 0.0;
  g.material_extra = "*DENSITY\n360.\n";
  g.load = "*DLOAD\nSHELL, GRAV, 1., 0., 0., -1.\n";
  return g;
}

// With `exact_normals`, a *NORMAL line per node gives the roof's radius there (on the crown's
// symmetry edge and the free edge the average sees the elements of one side only).
double scordelis_lo_deflection(const std::string& type, int n, const ElementRegistry& registry,
                               bool exact_normals = false) {
  test::ShellGrid g = scordelis_lo(type, n);
  const int jmax = test::grid_order(g) * n;
  if (exact_normals) {
    std::ostringstream normals;
    normals.precision(17);
    normals << "*NORMAL\n";
    const int imax = test::grid_order(g) * n;
    for (int j = 0; j <= jmax; ++j)
      for (int i = 0; i <= imax; ++i) {
        if (type[1] == '8' && i % 2 == 1 && j % 2 == 1) continue;
        const double phi = 40.0 * kPi / 180.0 * j / jmax;
        normals << "SHELL, " << test::grid_node(g, i, j) << ", 0., " << std::sin(phi) << ", "
                << std::cos(phi) << "\n";
      }
    g.model_extra = normals.str();
  }
  return -test::solve_grid(
      g,
      "scordelis_lo_" + type + "_" + std::to_string(n) + (exact_normals ? "_normals" : "") + ".inp",
      0, jmax, registry)[2];
}

// The octant: x = 300 s (x = 0 mid-length, the load), angle 90 r degrees from the loaded top.
test::ShellGrid pinched_cylinder(const std::string& type, int n) {
  test::ShellGrid g;
  g.type = type;
  g.nx = g.ny = n;
  g.map = [](double s, double r) {
    const double phi = 0.5 * kPi * r;
    return std::array<double, 3>{300.0 * s, 300.0 * std::sin(phi), 300.0 * std::cos(phi)};
  };
  g.fixed = [](int i, int j, int imax, int jmax) {
    std::vector<int> dofs;
    if (i == 0)
      for (const int d : {1, 5, 6}) dofs.push_back(d);  // mid-length symmetry
    if (j == 0)
      for (const int d : {2, 4, 6}) dofs.push_back(d);  // plane y = 0
    if (j == jmax)
      for (const int d : {3, 4, 5}) dofs.push_back(d);  // plane z = 0
    if (i == imax)
      for (const int d : {2, 3, 4}) dofs.push_back(d);  // diaphragm
    return dofs;
  };
  g.thickness = 3.0;
  g.young = 3e6;
  g.poisson = 0.3;
  g.load = "*CLOAD\n" + std::to_string(test::grid_node(g, 0, 0)) + ", 3, -0.25\n";
  return g;
}

double pinched_cylinder_deflection(const std::string& type, int n,
                                   const ElementRegistry& registry) {
  const test::ShellGrid g = pinched_cylinder(type, n);
  return -test::solve_grid(g, "pinched_cylinder_" + type + "_" + std::to_string(n) + ".inp", 0, 0,
                           registry)[2];
}

// The quarter hemisphere: longitude 90 s degrees from the x axis, latitude 72 r degrees.
test::ShellGrid hemisphere(const std::string& type, int n) {
  test::ShellGrid g;
  g.type = type;
  g.nx = g.ny = n;
  g.map = [](double s, double r) {
    const double lon = 0.5 * kPi * s, lat = 72.0 * kPi / 180.0 * r;
    return std::array<double, 3>{10.0 * std::cos(lat) * std::cos(lon),
                                 10.0 * std::cos(lat) * std::sin(lon), 10.0 * std::sin(lat)};
  };
  g.fixed = [](int i, int j, int imax, int) {
    std::vector<int> dofs;
    if (i == 0)
      for (const int d : {2, 4, 6}) dofs.push_back(d);  // plane y = 0
    if (i == imax)
      for (const int d : {1, 5, 6}) dofs.push_back(d);  // plane x = 0
    if (i == 0 && j == 0) dofs.push_back(3);            // the rigid motion along z
    return dofs;
  };
  g.thickness = 0.04;
  g.young = 6.825e7;
  g.poisson = 0.3;
  return g;
}

double hemisphere_deflection(const std::string& type, int n, const ElementRegistry& registry) {
  test::ShellGrid g = hemisphere(type, n);
  const int imax = test::grid_order(g) * n;
  g.load = "*CLOAD\n" + std::to_string(test::grid_node(g, 0, 0)) + ", 1, 1.\n" +
           std::to_string(test::grid_node(g, imax, 0)) + ", 2, -1.\n";
  return test::solve_grid(g, "hemisphere_" + type + "_" + std::to_string(n) + ".inp", 0, 0,
                          registry)[0];
}

// The twisted beam: x = 12 s along the axis, the width 1.1 (r - 1/2) turning from y at the root
// (s = 0) to z at the tip, clamped at the root (all six dofs).
test::ShellGrid twisted_beam(const std::string& type, int nx, int ny, double t) {
  test::ShellGrid g;
  g.type = type;
  g.nx = nx;
  g.ny = ny;
  g.map = [](double s, double r) {
    const double twist = 0.5 * kPi * s, across = 1.1 * (r - 0.5);
    return std::array<double, 3>{12.0 * s, across * std::cos(twist), across * std::sin(twist)};
  };
  g.fixed = [](int i, int, int, int) {
    return i == 0 ? std::vector<int>{1, 2, 3, 4, 5, 6} : std::vector<int>{};
  };
  g.thickness = t;
  g.young = 29e6;
  g.poisson = 0.22;
  return g;
}

// Tip displacement (middle node of the tip edge) along global `dof` (2: y, out of the tip's
// plane; 3: z, in the tip's plane) under the force P along it, spread over the tip edge's nodes
// as a uniform edge shear (consistent nodal weights of the element's edge).
double twisted_beam_tip(const std::string& type, int nx, int ny, double t, double P, int dof,
                        const ElementRegistry& registry) {
  test::ShellGrid g = twisted_beam(type, nx, ny, t);
  const int p = test::grid_order(g), imax = p * nx, jmax = p * ny;
  std::ostringstream load;
  load.precision(17);
  load << "*CLOAD\n";
  for (int j = 0; j <= jmax; ++j) {
    double share = 0.0;  // of one element edge's force
    if (p == 1)
      share = (j == 0 || j == jmax) ? 0.5 : 1.0;
    else
      share = j % 2 == 1 ? 2.0 / 3.0 : (j == 0 || j == jmax) ? 1.0 / 6.0 : 1.0 / 3.0;
    load << test::grid_node(g, imax, j) << ", " << dof << ", " << P * share / ny << "\n";
  }
  g.load = load.str();
  const std::string name = "twisted_beam_" + type + "_" + std::to_string(nx) + "x" +
                           std::to_string(ny) + "_" + std::to_string(dof) +
                           (t < 0.1 ? "_thin" : "") + ".inp";
  return test::solve_grid(g, name, imax, jmax / 2, registry)[dof - 1];
}

struct Case {
  const char* type;
  int n;        // elements per side of the modelled part
  double styk;  // asserted to 1e-3 (docs/verification.md prints 4 digits)
  double band;  // |styk / reference - 1| <= band
};

// Scordelis-Lo: the 2x2 quadratic elements converge to 0.3020 (-0.12 % of 0.3024), S4 from below
// (-1.09 % on 16 x 16 with averaged normals; -0.87 % with each facet's own normals, as Styk had
// before it averaged); the fully integrated 3x3 elements lock on coarse meshes (4 x 4: 0.2456,
// -19 %).
TEST(ShellObstacleCourse, ScordelisLoRoof) {
  const ElementRegistry registry = test::builtin_registry();
  const double reference = 0.3024;
  const Case cases[] = {{"S4", 16, 0.29911, 0.012},
                        {"S8R", 8, 0.30207, 0.0015},
                        {"S9R", 8, 0.30207, 0.0015},
                        {"S9", 4, 0.24598, 0.19}};
  for (const Case& c : cases) {
    const double w = scordelis_lo_deflection(c.type, c.n, registry);
    std::printf("Scordelis-Lo %s %dx%d: %.5g (%.2f %%)\n", c.type, c.n, c.n, w,
                100.0 * (w / reference - 1.0));
    EXPECT_NEAR(w, c.styk, 1e-3 * c.styk) << c.type;
    EXPECT_LE(std::abs(w / reference - 1.0), c.band) << c.type;
  }
}

// *NORMAL end to end: the radius given at every node of the faceted S4 roof. The averaged normals
// differ from the radius only on the crown's symmetry edge and the free edge, by half a facet
// angle (1.25 degrees). Measured: averaged 0.29911, given 0.299158 (+0.016 %), both -1.1 % of
// 0.3024.
TEST(ShellObstacleCourse, ScordelisLoRoofWithGivenNormals) {
  const ElementRegistry registry = test::builtin_registry();
  const double reference = 0.3024;
  const double averaged = scordelis_lo_deflection("S4", 16, registry);
  const double given = scordelis_lo_deflection("S4", 16, registry, true);
  std::printf("Scordelis-Lo S4 16x16: averaged normals %.6g, given radial normals %.6g\n", averaged,
              given);
  EXPECT_NEAR(averaged, 0.29911, 1e-4 * 0.29911);
  EXPECT_NEAR(given, 0.299158, 1e-4 * 0.299158);
  EXPECT_NEAR(given / averaged - 1.0, 1.6e-4, 0.2e-4);  // the edges' normals made exact
  EXPECT_LE(std::abs(given / reference - 1.0), 0.012);
}

// The same radial normals given on the *NODE lines (Abaqus' fields 5-7, docs/input.md) instead of
// *NORMAL lines: the node normals become *NORMAL entries of every shell at the node, so the roof
// deflects exactly as with the *NORMAL lines (to round-off, 1e-12).
TEST(ShellObstacleCourse, ScordelisLoRoofWithNormalsOnTheNodeLines) {
  const ElementRegistry registry = test::builtin_registry();
  constexpr int n = 16;
  const test::ShellGrid g = scordelis_lo("S4", n);
  std::istringstream in(test::shell_grid_deck(g));
  std::ostringstream deck;
  deck.precision(17);
  bool node_lines = false;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '*') {
      node_lines = line == "*NODE";
    } else if (node_lines) {
      const int row = (std::stoi(line) - 1) / (n + 1);  // grid row j: the angle
      const double phi = 40.0 * kPi / 180.0 * row / n;
      std::ostringstream normal;
      normal.precision(17);
      normal << ", 0., " << std::sin(phi) << ", " << std::cos(phi);
      line += normal.str();
    }
    deck << line << "\n";
  }
  const Model model = test::read_shell_deck("scordelis_lo_node_normals.inp", deck.str(), registry);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const double on_nodes =
      -results.increments.back().U[model.node_index(test::grid_node(g, 0, n))][2];
  const double on_normal_lines = scordelis_lo_deflection("S4", n, registry, true);
  EXPECT_NEAR(on_nodes, on_normal_lines, 1e-12 * on_normal_lines);
}

// Pinched cylinder (octant, 16 x 16): S8R 1.8305e-5 (+0.3 %), S9R 1.8671e-5 (+2.3 %), S4 (MITC4)
// 1.6949e-5 (-7.1 %, its known slow convergence under a point load).
TEST(ShellObstacleCourse, PinchedCylinderWithDiaphragms) {
  const ElementRegistry registry = test::builtin_registry();
  const double reference = 1.8248e-5;
  const Case cases[] = {
      {"S8R", 16, 1.8305e-5, 0.004}, {"S9R", 16, 1.8671e-5, 0.024}, {"S4", 16, 1.6949e-5, 0.072}};
  for (const Case& c : cases) {
    const double w = pinched_cylinder_deflection(c.type, c.n, registry);
    std::printf("pinched cylinder %s %dx%d: %.5g (%.2f %%)\n", c.type, c.n, c.n, w,
                100.0 * (w / reference - 1.0));
    EXPECT_NEAR(w, c.styk, 1e-3 * c.styk) << c.type;
    EXPECT_LE(std::abs(w / reference - 1.0), c.band) << c.type;
  }
}

// Pinched hemisphere (quarter, 16 x 16): S4 0.093073 (-0.99 %; -1.21 % with each facet's own
// normals), S8R 0.09371 (-0.3 %), S9R 0.09376
// (-0.3 %); the fully integrated quadratic elements lock in membrane on this doubly curved shell
// (S9 16 x 16: 0.0789, -16 %; 4 x 4: 0.0021).
TEST(ShellObstacleCourse, PinchedHemisphereWithHole) {
  const ElementRegistry registry = test::builtin_registry();
  const double reference = 0.094;
  const Case cases[] = {{"S4", 16, 0.093073, 0.011},
                        {"S8R", 16, 0.09371, 0.004},
                        {"S9R", 16, 0.093759, 0.004},
                        {"S9", 16, 0.078922, 0.17}};
  for (const Case& c : cases) {
    const double w = hemisphere_deflection(c.type, c.n, registry);
    std::printf("hemisphere %s %dx%d: %.5g (%.2f %%)\n", c.type, c.n, c.n, w,
                100.0 * (w / reference - 1.0));
    EXPECT_NEAR(w, c.styk, 1e-3 * c.styk) << c.type;
    EXPECT_LE(std::abs(w / reference - 1.0), c.band) << c.type;
  }
}

// The twisted beam, t = 0.32, unit tip force (MacNeal-Harder's references 5.424e-3 in the tip's
// plane, along z, and 1.754e-3 out of it, along y; Euler-Bernoulli bending of the twisted strip
// gives 5.426e-3 and 1.746e-3). MacNeal-Harder's mesh 12 x 2 and 24 x 4. Measured: S8R and S9R
// within 0.3 % on both loads; S4 (MITC4) -0.8 % in the plane and -8.0 % out of it on 12 x 2
// (-0.4 %, -2.6 % on 24 x 4); the flat STRI3 facets (each warped cell cut into two flat
// triangles) -1.9 % and -16.6 % (24 x 4: -1.1 %, -7.6 %), the stiffness flat triangles are
// known for here.
struct TwistedCase {
  const char* type;
  int refine;                // 1: 12 x 2, 2: 24 x 4
  double in, out;            // asserted to 1e-3
  double band_in, band_out;  // |styk / reference - 1|
};

TEST(ShellObstacleCourse, TwistedBeam) {
  const ElementRegistry registry = test::builtin_registry();
  const double in_reference = 5.424e-3, out_reference = 1.754e-3;
  const TwistedCase cases[] = {{"S4", 1, 5.3786e-3, 1.6142e-3, 0.009, 0.081},
                               {"S4", 2, 5.4019e-3, 1.7088e-3, 0.005, 0.027},
                               {"S8R", 1, 5.4107e-3, 1.7497e-3, 0.003, 0.003},
                               {"S9R", 1, 5.4164e-3, 1.7503e-3, 0.003, 0.003},
                               {"STRI3", 1, 5.3230e-3, 1.4631e-3, 0.02, 0.17},
                               {"STRI3", 2, 5.3661e-3, 1.6205e-3, 0.011, 0.077}};
  for (const TwistedCase& c : cases) {
    const int nx = 12 * c.refine, ny = 2 * c.refine;
    const double in = twisted_beam_tip(c.type, nx, ny, 0.32, 1.0, 3, registry);
    const double out = twisted_beam_tip(c.type, nx, ny, 0.32, 1.0, 2, registry);
    std::printf("twisted beam %s %dx%d: in-plane %.5g (%.2f %%), out-of-plane %.5g (%.2f %%)\n",
                c.type, nx, ny, in, 100.0 * (in / in_reference - 1.0), out,
                100.0 * (out / out_reference - 1.0));
    EXPECT_NEAR(in, c.in, 1e-3 * c.in) << c.type;
    EXPECT_NEAR(out, c.out, 1e-3 * c.out) << c.type;
    EXPECT_LE(std::abs(in / in_reference - 1.0), c.band_in) << c.type;
    EXPECT_LE(std::abs(out / out_reference - 1.0), c.band_out) << c.type;
  }
}

// The thin twisted beam, t = 0.0032 with the force 1e-6, so that the deflections stay those of
// the thick beam's order (references 5.256e-3 in the tip's plane and 1.294e-3 out of it: Simo,
// Fox & Rifai 1989, Zupan & Saje 2004, "On 'A proposed standard set of problems to test finite
// element accuracy': the twisted beam", FEAD 40). K's condition number grows as (size / t)^2:
// the solve is accepted on its backward error (docs/solver.md), no longer refused as "nearly
// singular" (backward errors measured 5e-17 ... 1.2e-16, where the relative residual reaches
// 3.7e-6). Measured on 12 x 2 (and 24 x 4 for S4 and STRI3) and asserted to 1e-3 with the band
// of each element's distance from the references: S8R -0.82 % / -0.01 %, S9R +0.39 % / +0.15 %,
// S4 -3.6 % / -2.5 % (24 x 4: -0.88 % / -0.73 %), STRI3 -10.9 % / -10.6 % (24 x 4: -1.8 % /
// -1.7 %); the fully integrated quadratic shells lock (S8 0.086 and 0.085 of the references, S9
// 0.091 and 0.090; below 0.1).
TEST(ShellObstacleCourse, ThinTwistedBeam) {
  const ElementRegistry registry = test::builtin_registry();
  const double in_reference = 5.256e-3, out_reference = 1.294e-3;
  const TwistedCase cases[] = {{"S4", 1, 5.0690e-3, 1.2613e-3, 0.037, 0.026},
                               {"S4", 2, 5.2099e-3, 1.2845e-3, 0.009, 0.008},
                               {"S8R", 1, 5.2127e-3, 1.2939e-3, 0.009, 0.001},
                               {"S9R", 1, 5.2765e-3, 1.2960e-3, 0.004, 0.002},
                               {"STRI3", 1, 4.6850e-3, 1.1574e-3, 0.11, 0.106},
                               {"STRI3", 2, 5.1618e-3, 1.2727e-3, 0.018, 0.017}};
  for (const TwistedCase& c : cases) {
    const int nx = 12 * c.refine, ny = 2 * c.refine;
    const double in = twisted_beam_tip(c.type, nx, ny, 0.0032, 1e-6, 3, registry);
    const double out = twisted_beam_tip(c.type, nx, ny, 0.0032, 1e-6, 2, registry);
    std::printf(
        "thin twisted beam %s %dx%d: in-plane %.5g (%.2f %%), out-of-plane %.5g "
        "(%.2f %%)\n",
        c.type, nx, ny, in, 100.0 * (in / in_reference - 1.0), out,
        100.0 * (out / out_reference - 1.0));
    EXPECT_NEAR(in, c.in, 1e-3 * c.in) << c.type;
    EXPECT_NEAR(out, c.out, 1e-3 * c.out) << c.type;
    EXPECT_LE(std::abs(in / in_reference - 1.0), c.band_in) << c.type;
    EXPECT_LE(std::abs(out / out_reference - 1.0), c.band_out) << c.type;
  }
}

TEST(ShellObstacleCourse, ThinTwistedBeamLocksFullyIntegrated) {
  const ElementRegistry registry = test::builtin_registry();
  const double in_reference = 5.256e-3, out_reference = 1.294e-3;
  const struct {
    const char* type;
    double in, out;
  } cases[] = {{"S8", 4.5186e-4, 1.0999e-4}, {"S9", 4.7582e-4, 1.1633e-4}};
  for (const auto& c : cases) {
    const double in = twisted_beam_tip(c.type, 12, 2, 0.0032, 1e-6, 3, registry);
    const double out = twisted_beam_tip(c.type, 12, 2, 0.0032, 1e-6, 2, registry);
    std::printf("thin twisted beam %s 12x2: in-plane %.5g (%.3f), out-of-plane %.5g (%.3f)\n",
                c.type, in, in / in_reference, out, out / out_reference);
    EXPECT_NEAR(in, c.in, 1e-3 * c.in) << c.type;
    EXPECT_NEAR(out, c.out, 1e-3 * c.out) << c.type;
    EXPECT_LT(in / in_reference, 0.1) << c.type;
    EXPECT_LT(out / out_reference, 0.1) << c.type;
  }
}

// The backward-error check accepts the thin beam, but a genuinely singular thin model is still
// refused (docs/solver.md §1, §5): the beam with no support at all (the pre-solve check: free to
// move in x) and held at one root node in translation (free to rotate about an axis through it);
// and a mechanism the pre-solve check cannot see, left to the factorisation's pivots: a single
// thin S8R element (1.1 x 1.1, t = 0.0032) clamped at one corner node, whose two spurious modes
// (docs/elements.md) no support restrains.
TEST(ShellObstacleCourse, ThinTwistedBeamWithoutSupportIsRefusedAsSingular) {
  const ElementRegistry registry = test::builtin_registry();
  const auto refusal = [&](test::ShellGrid g, const char* name,
                           const std::function<std::vector<int>(int, int, int, int)>& fixed) {
    g.fixed = fixed;
    const int imax = test::grid_order(g) * g.nx;
    g.load = "*CLOAD\n" + std::to_string(test::grid_node(g, imax, 1)) + ", 3, 1e-6\n";
    try {
      test::solve_grid(g, name, imax, 1, registry);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("solved");
  };
  const test::ShellGrid beam = twisted_beam("S4", 12, 2, 0.0032);
  const std::string floating = refusal(beam, "thin_beam_floating.inp",
                                       [](int, int, int, int) { return std::vector<int>{}; });
  EXPECT_NE(floating.find("the model can move freely in x"), std::string::npos) << floating;
  const std::string hinged = refusal(beam, "thin_beam_hinged.inp", [](int i, int j, int, int) {
    return i == 0 && j == 1 ? std::vector<int>{1, 2, 3} : std::vector<int>{};
  });
  EXPECT_NE(hinged.find("the model can rotate freely about the axis"), std::string::npos) << hinged;
  test::ShellGrid square = twisted_beam("S8R", 1, 1, 0.0032);
  square.map = [](double s, double r) { return std::array<double, 3>{1.1 * s, 1.1 * r, 0.0}; };
  const std::string modes = refusal(square, "thin_s8r_corner.inp", [](int i, int j, int, int) {
    return i == 0 && j == 0 ? std::vector<int>{1, 2, 3, 4, 5, 6} : std::vector<int>{};
  });
  std::printf("corner-clamped S8R: %s\n", modes.c_str());
  EXPECT_NE(modes.find("the stiffness matrix is singular at node"), std::string::npos) << modes;
}

}  // namespace
}  // namespace styk
