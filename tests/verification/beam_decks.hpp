// Beam cantilever decks for the verification tests (SPEC §7.3, §3.1.1): written as CalculiX text
// and read by the .inp reader, so they exercise *BEAM SECTION and the whole input path.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/test_scratch.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::test {

struct Cantilever {
  std::string type = "B21";  // B21, B22, B31, B32, ...
  int elements = 1;
  double length = 4.0;
  double young = 1000.0;
  double poisson = 1.0 / 3.0;  // G = 375 with E = 1000
  std::string section = "RECT";
  std::string dimensions = "1., 1.";
  std::string integration;     // "", "FULL" or "REDUCED"
  std::string load = "2, 1.";  // "dof, value" at the tip node, or a *DLOAD line (label, value)
  bool line_load = false;      // `load` is "P2, q" on every element
  std::string extra_step;      // more step lines (outputs)
};

inline std::string cantilever_deck(const Cantilever& c) {
  const bool quadratic = c.type.size() > 2 && c.type[2] == '2';  // B22, B32, B32R
  const int nodes = quadratic ? 2 * c.elements + 1 : c.elements + 1;
  std::ostringstream deck;
  deck.precision(17);
  deck << "*HEADING\ncantilever of " << c.elements << " " << c.type << "\n*NODE, NSET=NALL\n";
  for (int i = 0; i < nodes; ++i) deck << i + 1 << ", " << c.length * i / (nodes - 1) << ", 0, 0\n";
  deck << "*NSET, NSET=TIP\n" << nodes << "\n*ELEMENT, TYPE=" << c.type << ", ELSET=BEAM\n";
  for (int e = 0; e < c.elements; ++e) {
    if (quadratic)
      deck << e + 1 << ", " << 2 * e + 1 << ", " << 2 * e + 2 << ", " << 2 * e + 3 << "\n";
    else
      deck << e + 1 << ", " << e + 1 << ", " << e + 2 << "\n";
  }
  deck << "*MATERIAL, NAME=M\n*ELASTIC\n"
       << c.young << ", " << c.poisson << "\n"
       << "*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=" << c.section
       << (c.integration.empty() ? "" : ", INTEGRATION=" + c.integration) << "\n"
       << c.dimensions << "\n*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n";
  if (c.line_load)
    deck << "*DLOAD\nBEAM, " << c.load << "\n";
  else
    deck << "*CLOAD\nTIP, " << c.load << "\n";
  deck << c.extra_step << "*END STEP\n";
  return deck.str();
}

inline Model read_deck(const std::string& name, const std::string& text,
                       const ElementRegistry& registry) {
  const std::filesystem::path dir = test::test_scratch_dir("tests/beam_decks");
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return read_inp(path.string(), registry);
}

// Solves the cantilever and returns its last increment.
inline IncrementResult solve_cantilever(const Cantilever& c, const ElementRegistry& registry,
                                        AnalysisReport* report = nullptr,
                                        Model* model_out = nullptr) {
  const std::string name = c.type + "_" + std::to_string(c.elements) + "_" +
                           (c.integration.empty() ? "default" : c.integration) + ".inp";
  Model model = read_deck(name, cantilever_deck(c), registry);
  Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, report);
  if (model_out) *model_out = std::move(model);
  return std::move(results.increments.back());
}

// Tip deflection along y of a cantilever built by solve_cantilever (the last node).
inline double tip_uy(const IncrementResult& inc) { return inc.U.back()[1]; }

}  // namespace styk::test
