// Small programmatic models for the thermal-load, *EQUATION and *TRANSFORM tests: a structured
// C3D8 grid whose nodes are NOT merged with other grids (so two grids can meet with duplicated
// nodes and be tied by equations), deck parsing from a string, and a solve with the built-in
// elements plus the build-tree plug-ins.
#pragma once

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../../support/test_scratch.hpp"
#include "hex_model_builder.hpp"
#include "styk/inp/reader.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk::test {

// Adds an nx x ny x nz grid of C3D8 elements of size h filling [x0, x0 + nx h] x [0, ny h] x
// [0, nz h] to `model` (new nodes, ids continuing the model's), all in section 0 / set EALL.
inline void add_c3d8_grid(Model& model, double x0, std::array<int, 3> n, double h) {
  const int first = model.node_count();
  auto node = [&](int i, int j, int k) { return first + i + (n[0] + 1) * (j + (n[1] + 1) * k); };
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i)
        model.add_node(model.node_count() + 1, {x0 + i * h, j * h, k * h}, {});
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const std::vector<int> nodes{node(i, j, k),
                                     node(i + 1, j, k),
                                     node(i + 1, j + 1, k),
                                     node(i, j + 1, k),
                                     node(i, j, k + 1),
                                     node(i + 1, j, k + 1),
                                     node(i + 1, j + 1, k + 1),
                                     node(i, j + 1, k + 1)};
        const int e = model.add_element(model.element_count() + 1, "C3D8", nodes, {});
        model.elements[e].section = 0;
        model.elsets["EALL"].elements.push_back(e);
      }
}

// An empty model with one material (E, nu) and the section on EALL, plus one step.
inline Model grid_model_shell(double young, double poisson) {
  Model model;
  model.source = "grid.inp";
  Material material;
  material.name = "M";
  material.young = young;
  material.poisson = poisson;
  model.materials.push_back(material);
  Section section;
  section.elset = "EALL";
  section.material = "M";
  section.material_index = 0;
  model.sections.push_back(section);
  model.elsets["EALL"].name = "EALL";
  Step step;
  step.name = "STEP";
  step.has_procedure = true;
  model.steps.push_back(step);
  return model;
}

// Nodes whose coordinate `axis` equals `value` (to 1e-9).
inline std::vector<int> nodes_at(const Model& model, int axis, double value) {
  std::vector<int> out;
  for (int n = 0; n < model.node_count(); ++n)
    if (std::abs(model.coords[n][axis] - value) < 1e-9) out.push_back(n);
  return out;
}

inline Results solve_with_plugins(const Model& model,
                                  const SolveOptions& options = SolveOptions{}) {
  const auto registry = registry_with_plugins();
  return run_static_analysis(model, registry->registry, options, nullptr, nullptr);
}

// Parses `deck` (written to a scratch file named `name`) with the built-in elements.
inline Model parse_deck(const std::string& name, const std::string& deck) {
  const std::filesystem::path dir = test::test_scratch_dir("tests/constraints_decks");
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << deck;
  ElementRegistry registry = test::builtin_registry();
  return read_inp(path.string(), registry);
}

}  // namespace styk::test
