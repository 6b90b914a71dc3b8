// Small .inp decks of plane and truss models for the solver-level tests: written to a temporary
// file and read with the real reader, so the keyword path (section thickness/area, *DLOAD P1..P4,
// dof numbers) is exercised with line numbers. Deterministic.
#pragma once

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk::test {

// Writes `text` to a fresh file in the temporary directory and returns its path.
inline std::string write_deck(const std::string& name, const std::string& text) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("styk_planar_" + name + ".inp");
  std::ofstream(path) << text;
  return path.string();
}

// 1-based line of the first line of `text` containing `needle` (0 if none).
inline int line_of(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return 0;
}

inline std::string number(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// A structured quadrilateral mesh of nx x ny CPS4/CPE4 (nodes_per_element 4) or CPS8/CPE8 (8)
// elements on a grid of (order*nx + 1) x (order*ny + 1) points, order = 1 or 2; node (i, j) has
// id 1 + i + j * (order*nx + 1) and position place(i, j). 8-node elements skip the grid points
// with i and j both odd (element centres).
struct QuadMesh {
  int nx = 1, ny = 1, order = 1;
  std::function<Vec3(int, int)> place;

  int columns() const { return order * nx + 1; }
  int rows() const { return order * ny + 1; }
  int id(int i, int j) const { return 1 + i + j * columns(); }
  bool exists(int i, int j) const { return order == 1 || i % 2 == 0 || j % 2 == 0; }

  std::string nodes_card() const {
    std::string out = "*NODE, NSET=ALL\n";
    for (int j = 0; j < rows(); ++j)
      for (int i = 0; i < columns(); ++i)
        if (exists(i, j)) {
          const Vec3 x = place(i, j);
          out += std::to_string(id(i, j)) + ", " + number(x[0]) + ", " + number(x[1]) + ", " +
                 number(x[2]) + "\n";
        }
    return out;
  }

  std::string elements_card(const std::string& type) const {
    std::string out = "*ELEMENT, TYPE=" + type + ", ELSET=PLATE\n";
    int e = 1;
    for (int ej = 0; ej < ny; ++ej)
      for (int ei = 0; ei < nx; ++ei, ++e) {
        const int I = order * ei, J = order * ej, o = order;
        out += std::to_string(e) + ", " + std::to_string(id(I, J)) + ", " +
               std::to_string(id(I + o, J)) + ", " + std::to_string(id(I + o, J + o)) + ", " +
               std::to_string(id(I, J + o));
        if (order == 2)
          out += ", " + std::to_string(id(I + 1, J)) + ", " + std::to_string(id(I + 2, J + 1)) +
                 ", " + std::to_string(id(I + 1, J + 2)) + ", " + std::to_string(id(I, J + 1));
        out += "\n";
      }
    return out;
  }
};

// The material/section block for element set PLATE.
inline std::string plate_section(double young, double poisson, const std::string& thickness) {
  return "*MATERIAL, NAME=STEEL\n*ELASTIC\n" + number(young) + ", " + number(poisson) +
         "\n*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL\n" + thickness + "\n";
}

inline Results solve_deck(const std::string& name, const std::string& text, Model* out = nullptr) {
  const ElementRegistry registry = builtin_registry();
  Model model = read_inp(write_deck(name, text), registry);
  SolveOptions options;
  options.threads = 2;
  Results results = run_static_analysis(model, registry, options, nullptr, nullptr);
  if (out != nullptr) *out = std::move(model);
  return results;
}

}  // namespace styk::test
