// Decks written as text, solved with the built-in elements, and the lookups the keyword tests
// (issue 15 items 1-3 and 5) need to compare results with hand values.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../../support/test_scratch.hpp"
#include "styk/core/results.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk::test {

struct Solved {
  Model model;
  Results results;
};

inline Solved solve_text(const std::string& name, const std::string& deck) {
  const std::filesystem::path dir = test::test_scratch_dir("tests/keyword_decks");
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << deck;
  ElementRegistry registry = test::builtin_registry();
  Solved out;
  out.model = read_inp(path.string(), registry);
  out.results = run_static_analysis(out.model, registry, SolveOptions{}, nullptr, nullptr);
  return out;
}

// A unit cube of 2 x 2 x 2 C3D8 (nodes 1..27, i fastest), sets NALL, EALL, X0, Y0, Z0 (the
// faces at 0) and X1, Z1 (the faces at 1). `material` is the *MATERIAL block of material M,
// `section_extra` is appended to the *SOLID SECTION line.
inline std::string unit_cube(const std::string& material, const std::string& section_extra = "",
                             const std::string& etype = "C3D8") {
  std::ostringstream d;
  d << "*NODE, NSET=NALL\n";
  auto id = [](int i, int j, int k) { return 1 + i + 3 * j + 9 * k; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        d << id(i, j, k) << ", " << 0.5 * i << ", " << 0.5 * j << ", " << 0.5 * k << "\n";
  d << "*ELEMENT, TYPE=" << etype << ", ELSET=EALL\n";
  int e = 1;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        d << e++ << ", " << id(i, j, k) << ", " << id(i + 1, j, k) << ", " << id(i + 1, j + 1, k)
          << ", " << id(i, j + 1, k) << ", " << id(i, j, k + 1) << ", " << id(i + 1, j, k + 1)
          << ", " << id(i + 1, j + 1, k + 1) << ", " << id(i, j + 1, k + 1) << "\n";
  auto face = [&](const char* name, int axis, int value) {
    d << "*NSET, NSET=" << name << "\n";
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          if ((axis == 0 ? i : axis == 1 ? j : k) == value) d << id(i, j, k) << "\n";
  };
  face("X0", 0, 0);
  face("Y0", 1, 0);
  face("Z0", 2, 0);
  face("X1", 0, 2);
  face("Z1", 2, 2);
  d << material << "*SOLID SECTION, ELSET=EALL, MATERIAL=M" << section_extra << "\n";
  return d.str();
}

// Normal supports on the three faces at 0: the cube strains freely under uniform loads.
inline const char* kSymmetricSupports = "*BOUNDARY\nX0, 1\nY0, 2\nZ0, 3\n";

// The maximum over all integration points of |field component - value|.
inline double max_deviation(const std::vector<Tensor6>& field, int component, double value) {
  double worst = 0.0;
  for (const Tensor6& t : field) worst = std::max(worst, std::abs(t[component] - value));
  return worst;
}

inline Vec3 displacement(const Solved& s, Id node, std::size_t increment = 0) {
  return s.results.increments.at(increment).U.at(s.model.node_index(node));
}

}  // namespace styk::test
