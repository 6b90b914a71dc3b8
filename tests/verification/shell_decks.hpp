// Structured shell decks for the verification tests (SPEC §7.3 plates, the shell obstacle
// course): a grid of S4 / S8 / S9 elements on a map of the unit square, written as CalculiX text
// and read by the .inp reader, so they exercise *SHELL SECTION, *DLOAD P / GRAV and the solver.
#pragma once

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "../support/test_scratch.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::test {

struct ShellGrid {
  std::string type = "S8R";  // S4, S4R, S8, S8R, S9, S9R, STRI3 (each cell cut into two
                             // triangles along its diagonal from its first corner)
  int nx = 2, ny = 2;        // elements along the map's s and r
  // (s, r) in [0, 1]^2 -> position; the element normal is d/ds x d/dr.
  std::function<std::array<double, 3>(double s, double r)> map;
  // The dofs fixed to zero at grid point (i, j) of (imax, jmax) (grid points, mid-edge nodes
  // included).
  std::function<std::vector<int>(int i, int j, int imax, int jmax)> fixed;
  double thickness = 0.1;
  double young = 1.0, poisson = 0.3;
  std::string load;            // step lines, e.g. "*DLOAD\nSHELL, P, 10.\n"
  std::string material_extra;  // e.g. "*DENSITY\n360.\n"
  std::string model_extra;     // model keywords after the section, e.g. "*NORMAL\n..."
};

inline bool grid_triangles(const ShellGrid& g) { return g.type == "STRI3"; }

inline int grid_order(const ShellGrid& g) { return g.type[1] == '4' || grid_triangles(g) ? 1 : 2; }

// The node id of grid point (i, j): row-major over the (order nx + 1) x (order ny + 1) grid.
inline int grid_node(const ShellGrid& g, int i, int j) {
  return j * (grid_order(g) * g.nx + 1) + i + 1;
}

inline std::string shell_grid_deck(const ShellGrid& g) {
  const int p = grid_order(g), imax = p * g.nx, jmax = p * g.ny;
  const bool serendipity = g.type[1] == '8';
  std::ostringstream deck;
  deck.precision(17);
  deck << "*HEADING\n" << g.nx << " x " << g.ny << " " << g.type << " shell grid\n*NODE\n";
  for (int j = 0; j <= jmax; ++j)
    for (int i = 0; i <= imax; ++i) {
      if (serendipity && i % 2 == 1 && j % 2 == 1) continue;  // no centre node
      const std::array<double, 3> x =
          g.map(static_cast<double>(i) / imax, static_cast<double>(j) / jmax);
      deck << grid_node(g, i, j) << ", " << x[0] << ", " << x[1] << ", " << x[2] << "\n";
    }
  deck << "*ELEMENT, TYPE=" << g.type << ", ELSET=SHELL\n";
  int id = 1;
  for (int b = 0; b < g.ny; ++b)
    for (int a = 0; a < g.nx; ++a) {
      const int I = p * a, J = p * b;
      const auto n = [&](int di, int dj) { return grid_node(g, I + di, J + dj); };
      if (grid_triangles(g)) {
        deck << id++ << ", " << n(0, 0) << ", " << n(1, 0) << ", " << n(1, 1) << "\n";
        deck << id++ << ", " << n(0, 0) << ", " << n(1, 1) << ", " << n(0, 1) << "\n";
        continue;
      }
      deck << id++ << ", " << n(0, 0) << ", " << n(p, 0) << ", " << n(p, p) << ", " << n(0, p);
      if (p == 2) deck << ", " << n(1, 0) << ", " << n(2, 1) << ", " << n(1, 2) << ", " << n(0, 1);
      if (g.type[1] == '9') deck << ", " << n(1, 1);
      deck << "\n";
    }
  deck << "*MATERIAL, NAME=M\n*ELASTIC\n"
       << g.young << ", " << g.poisson << "\n"
       << g.material_extra << "*SHELL SECTION, ELSET=SHELL, MATERIAL=M\n"
       << g.thickness << "\n"
       << g.model_extra << "*BOUNDARY\n";
  for (int j = 0; j <= jmax; ++j)
    for (int i = 0; i <= imax; ++i) {
      if (serendipity && i % 2 == 1 && j % 2 == 1) continue;
      for (int dof : g.fixed(i, j, imax, jmax))
        deck << grid_node(g, i, j) << ", " << dof << ", " << dof << "\n";
    }
  deck << "*STEP\n*STATIC\n" << g.load << "*END STEP\n";
  return deck.str();
}

inline Model read_shell_deck(const std::string& name, const std::string& text,
                             const ElementRegistry& registry) {
  const std::filesystem::path dir = test::test_scratch_dir("tests/shell_decks");
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return read_inp(path.string(), registry);
}

// Solves the grid and returns the displacement of grid point (i, j).
inline Vec3 solve_grid(const ShellGrid& g, const std::string& name, int i, int j,
                       const ElementRegistry& registry, AnalysisReport* report = nullptr) {
  const Model model = read_shell_deck(name, shell_grid_deck(g), registry);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, report);
  const int node = model.node_index(grid_node(g, i, j));
  return results.increments.back().U[node];
}

// A cantilever plate strip (length 1 along x, width b = 0.2, t = 0.01, E = 1e6, nu = 0, clamped
// at x = 0) of nx x 2 elements under a uniform shear on its free edge, total P along z, spread
// over the edge nodes with the element edge's consistent weights. `extra_step_lines` go into
// the step after the load (output requests).
inline ShellGrid cantilever_strip(const std::string& type, double P, int nx = 4,
                                  const std::string& extra_step_lines = "") {
  ShellGrid g;
  g.type = type;
  g.nx = nx;
  g.ny = 2;
  g.map = [](double s, double r) { return std::array<double, 3>{s, 0.2 * r, 0.0}; };
  g.fixed = [](int i, int, int, int) {
    return i == 0 ? std::vector<int>{1, 2, 3, 4, 5, 6} : std::vector<int>{};
  };
  g.thickness = 0.01;
  g.young = 1e6;
  g.poisson = 0.0;
  const int p = grid_order(g), imax = p * g.nx, jmax = p * g.ny;
  std::ostringstream load;
  load.precision(17);
  load << "*CLOAD\n";
  for (int j = 0; j <= jmax; ++j) {  // consistent nodal shares of a uniform edge shear
    const double share = p == 1 ? ((j == 0 || j == jmax) ? 0.5 : 1.0)
                                : (j % 2 == 1              ? 2.0 / 3.0
                                   : (j == 0 || j == jmax) ? 1.0 / 6.0
                                                           : 1.0 / 3.0);
    load << grid_node(g, imax, j) << ", 3, " << P * share / g.ny << "\n";
  }
  g.load = load.str() + extra_step_lines;
  return g;
}

}  // namespace styk::test
