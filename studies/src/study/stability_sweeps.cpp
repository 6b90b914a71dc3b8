// The sweeps of `styk study stability` (docs/stability.md): where the methods fail.
#include "problem_support.hpp"
#include "styk/studies/study/problems.hpp"

namespace styk::studies {
namespace {

using detail::text;

// The beam of the element-shape sweeps: 10 x 1 (height) x 1, nu = 0, E = 1000, unit end shear,
// 10 x 2 elements (MacNeal-Harder's slender-beam shape tests, with the exact solution).
detail::BeamSpec sweep_beam() {
  detail::BeamSpec beam;
  beam.L = 10;
  beam.h = 1;
  beam.b = 1;
  beam.E = 1000;
  beam.P = 1;
  beam.nx = 10;
  beam.nz = 2;
  return beam;
}

const char* kBeamDetails =
    "Beam 10 x 1 x 1 (x, z, y), E = 1000, nu = 0, unit end shear, the exact solution's root "
    "displacements and end tractions; 10 x 2 elements (1 x 0.5), one across the width, "
    "C3D21/C3D28 layer on the side face (every element).";

ReferenceProblem distortion(const std::string& kind, std::vector<double> angles) {
  ReferenceProblem p;
  p.name = kind;
  p.title = "Element distortion: " + kind.substr(kind.find('-') + 1) + " elements";
  p.source = "MacNeal & Harder (1985) element-shape tests; exact solution Timoshenko & Goodier §21";
  p.details = std::string(kBeamDetails) +
              (kind == "distortion-parallelogram"
                   ? " Every vertical grid line turns by the angle about mid-height (the end "
                     "faces too): parallelograms."
                   : " Interior grid lines turn by -angle, +angle, ... about mid-height, the "
                     "end faces stay: trapezoids (45° closes them).");
  p.parameter = "angle, degrees";
  p.values = std::move(angles);
  const std::string shape = kind.substr(kind.find('-') + 1);
  p.setup = [values = p.values, shape](int level) {
    detail::BeamSpec beam = sweep_beam();
    beam.distortion = shape;
    beam.angle = values.at(level);
    return detail::beam_setup(beam);
  };
  return p;
}

ReferenceProblem aspect_ratio() {
  ReferenceProblem p;
  p.name = "aspect-ratio";
  p.title = "Element aspect ratio";
  p.source = "exact solution Timoshenko & Goodier §21";
  p.details = std::string(kBeamDetails) +
              " Two elements through the height, 20 / ratio along the length: length / height "
              "of the elements = ratio.";
  p.parameter = "aspect ratio";
  p.values = {1, 2, 4, 5, 10, 20};
  p.log_parameter = true;
  p.setup = [values = p.values](int level) {
    detail::BeamSpec beam = sweep_beam();
    beam.nx = static_cast<int>(std::lround(20 / values.at(level)));
    return detail::beam_setup(beam);
  };
  return p;
}

ReferenceProblem incompressibility() {
  ReferenceProblem p;
  p.name = "poisson";
  p.title = "Near incompressibility: nu -> 0.5";
  p.source = "SPEC §3.1.7 (volumetric locking); Lamé, plane strain";
  p.details =
      "The Lamé cylinder of the accuracy series (R 3-9, unit pressure, E = 1000) on its level-1 "
      "mesh, 4 x 6 elements, nu = 0.3 ... 0.49999 (the parameter is 0.5 - nu).";
  p.parameter = "0.5 - nu";
  p.values = {0.2, 0.1, 0.05, 0.01, 1e-3, 1e-4, 1e-5};
  p.log_parameter = true;
  p.setup = [values = p.values](int level) {
    return detail::lame_setup(4, 6, 0.5 - values.at(level));
  };
  return p;
}

}  // namespace

const std::vector<ReferenceProblem>& stability_sweeps() {
  static const std::vector<ReferenceProblem> sweeps = [] {
    std::vector<ReferenceProblem> all = {
        distortion("distortion-parallelogram", {0, 10, 20, 30, 40, 50, 60}),
        distortion("distortion-trapezoid", {0, 5, 10, 15, 20, 25, 30, 35, 40}), aspect_ratio(),
        incompressibility()};
    for (ReferenceProblem& p : detail::structural_sweeps()) all.push_back(std::move(p));
    return all;
  }();
  return sweeps;
}

}  // namespace styk::studies
