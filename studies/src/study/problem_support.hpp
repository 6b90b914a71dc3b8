// Pieces shared by the refinement series and the stability sweeps (private to the studies).
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include "styk/studies/study/problems.hpp"

namespace styk::studies::detail {

constexpr double kPi = 3.14159265358979323846;

std::string text(double v);  // "%.10g"
inline std::string text(int v) { return std::to_string(v); }

// Replaces the builder's supports and loads by the exact solution's: exact displacements on the
// build's surface `fixed`, exact tractions on its surface `loaded`.
std::function<void(const mesher::BuildResult&, Model&, const ElementRegistry&)> exact_ends(
    std::shared_ptr<const ExactSolution> exact, std::string fixed, std::string loaded);

// The Lamé cylinder of SPEC §3.1.7 (R 3-9, unit internal pressure, E 1000, plane strain) on an
// nr x ntheta quarter with every element of the family (layer at z = 0).
ProblemSetup lame_setup(int nr, int ntheta, double nu);

// A cantilever along x with the exact nu = 0 solution (root face fixed to the exact
// displacements, parabolic end shear): length L, height h (z), width b (y), nx x nz elements,
// every element of the family (layer on the side face y = 0), optional distortion.
struct BeamSpec {
  double L = 150, h = 5, b = 2.5, E = 70000, P = 5;
  int nx = 12, nz = 2;
  std::string distortion = "none";
  double angle = 0.0;
};
ProblemSetup beam_setup(const BeamSpec& beam);

// The beam and plate problems (structural_problems.cpp): the refinement series of the
// accuracy atlas and the thin-limit sweeps of the stability study.
std::vector<ReferenceProblem> structural_accuracy_problems();
std::vector<ReferenceProblem> structural_sweeps();

// Reads a CalculiX deck given as text (written to a private temporary directory as NAME.inp,
// removed again; the model's source is then "NAME.inp"); throws InputError from the reader.
Model read_study_deck(const std::string& text, const std::string& name,
                      const ElementRegistry& registry);

}  // namespace styk::studies::detail
