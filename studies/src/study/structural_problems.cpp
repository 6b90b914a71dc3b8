// The beam and plate problems of the studies: the refinement series of the accuracy atlas
// (docs/accuracy.md, "Beams and plates") and the thin-limit sweeps (docs/stability.md).

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "problem_support.hpp"
#include "structural_decks.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/inp/reader.hpp"
#include "styk/studies/study/plate_series.hpp"

namespace styk::studies::detail {
namespace {

double relative(double computed, double exact) {
  return std::abs(computed - exact) / std::max(std::abs(exact), 1e-300);
}

double bending_moment_1(const Vec3& sm) { return sm[0]; }
double moment_sum(const Vec3& sm) { return sm[0] + sm[1]; }

// A private directory under the system's temporary directory, removed with everything in it.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "styk-study-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw InputError({"styk study", 0}, "cannot create a temporary directory for a deck");
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// ---- beams ----

const char* kBeamSource =
    "Timoshenko beam theory, closed form: tip deflection q L^4 / (8 E I) + q L^2 / (2 k G A), "
    "k = 5/6 (Cowper 1966, rectangle), bending moment q (L - x)^2 / 2";

ErrorArray beam_errors(const BeamDeck& beam, const Model& model, const IncrementResult& r,
                       const ElementRegistry& registry) {
  ErrorArray out{};
  const int tip = model.node_count() - 1;
  out[static_cast<int>(Measure::PointDisplacement)] =
      relative(r.U.at(tip)[1], beam_tip_deflection(beam));
  // SM1 is the moment about section axis 1 (-z): its sign is the convention's; the measure
  // compares magnitudes.
  out[static_cast<int>(Measure::PointStress)] =
      relative(std::abs(station_mean(model, r, registry, 0, bending_moment_1)),
               beam_root_element_moment(beam));
  return out;
}

ProblemSetup beam_problem(const BeamDeck& beam) {
  ProblemSetup s;
  s.builder = "beam-cantilever";
  s.h = beam.length / beam.elements;
  s.deck = [beam](const ElementFamily& family) { return beam_deck(family, beam); };
  s.measure = [beam](const Model& model, const IncrementResult& r,
                     const ElementRegistry& registry) {
    return beam_errors(beam, model, r, registry);
  };
  return s;
}

ReferenceProblem beam_cantilever() {
  ReferenceProblem p;
  p.name = "beam-cantilever";
  p.title = "Cantilever of beam elements under a uniform load";
  p.kind = ElementKind::Beam;
  p.headline = Measure::PointDisplacement;
  p.source = kBeamSource;
  p.details =
      "L = 1, RECT section 1 x 0.05 (L/h = 20), E = 1e7, nu = 0.3, q = 1 along the section's "
      "axis 2 (*DLOAD P2), root clamped; n = 2, 4, 8, ... elements along the axis (a CalculiX "
      "deck per run). Named points: the tip deflection, and the root element's bending moment "
      "SM1 averaged over its stations (the weights of its rule) against the exact mean over the "
      "element (magnitudes). A beam has no 3D field: no L2 or energy norm. Theory: the nodal "
      "deflection and the element's mean moment converge at 2p (p the element's polynomial "
      "degree); the default (reduced) rule reproduces the nodal deflection exactly, and "
      "the quadratic beams also the mean moment (errors at the solver's round-off, below the "
      "fits' floor of 1e-6: tests/verification/atlas_rates_test.cpp asserts them below "
      "1e-9). The mesh is refined along the axis only, so order p shows as a DOF slope of -p "
      "in the charts; solves of these few DOF take well below a millisecond, where the wall "
      "times are the timer's and the system's noise.";
  p.levels = 7;
  p.point_orders = [](const ElementFamily& f) {
    return std::array<int, 2>{2 * f.order, 2 * f.order};
  };
  p.setup = [](int level) {
    BeamDeck beam;
    beam.elements = 2 << level;
    return beam_problem(beam);
  };
  return p;
}

ReferenceProblem thin_beam() {
  ReferenceProblem p;
  p.name = "thin-beam";
  p.title = "Thin limit of beams: slenderness L/h";
  p.kind = ElementKind::Beam;
  p.source = std::string("SPEC §7.3 (shear locking, Tab 7.1a); ") + kBeamSource;
  p.details =
      "The cantilever of `beam-cantilever` (L = 1, RECT 1 x h, E = 1e7, nu = 0.3, uniform load) "
      "with 8 elements and h = L / slenderness.";
  p.parameter = "slenderness L/h";
  p.values = {1, 3, 10, 30, 100, 300, 1000, 3000, 10000};
  p.log_parameter = true;
  p.setup = [values = p.values](int level) {
    BeamDeck beam;
    beam.height = beam.length / values.at(level);
    return beam_problem(beam);
  };
  return p;
}

// ---- plates ----

const char* kPlateSource =
    "Navier series of the uniformly loaded simply supported square (Timoshenko & "
    "Woinowsky-Krieger §30), the Mindlin plate with hard supports adding the Marcus moment over "
    "k G t (k = 5/6), as SPEC §7.3 Tab 7.1b in docs/verification.md";

// `mindlin_truth`: measure the deflection against the Mindlin series (false: against the
// Kirchhoff series for the Kirchhoff element STRI3, true for the Mindlin elements).
ErrorArray plate_errors(const PlateDeck& plate, bool kirchhoff_element, bool mindlin_truth,
                        const Model& model, const IncrementResult& r,
                        const ElementRegistry& registry) {
  SquarePlate series;
  series.side = plate.side;
  series.thickness = plate.thickness;
  series.young = plate.young;
  series.poisson = plate.poisson;
  series.pressure = plate.load;
  const double c = plate.side / 2.0, cell = c / plate.elements;
  ErrorArray out{};
  const int centre = model.node_count() - 1;
  out[static_cast<int>(Measure::PointDisplacement)] =
      relative(r.U.at(centre)[2], plate_deflection(series, c, c, mindlin_truth));
  // The cell at the plate's centre: its element, or its two triangles (equal areas).
  const int cells = plate.elements * plate.elements;
  double moment = 0.0;
  if (kirchhoff_element)
    moment = 0.5 * (station_mean(model, r, registry, 2 * cells - 2, moment_sum) +
                    station_mean(model, r, registry, 2 * cells - 1, moment_sum));
  else
    moment = station_mean(model, r, registry, cells - 1, moment_sum);
  out[static_cast<int>(Measure::PointStress)] =
      relative(moment, plate_moment_sum_mean(series, c - cell, c, c - cell, c));
  return out;
}

ProblemSetup plate_problem(const PlateDeck& plate, bool mindlin_for_all) {
  ProblemSetup s;
  s.builder = "plate";
  s.h = plate.side / 2.0 / plate.elements;
  s.deck = [plate](const ElementFamily& family) { return plate_deck(family, plate); };
  s.measure = [plate, mindlin_for_all](const Model& model, const IncrementResult& r,
                                       const ElementRegistry& registry) {
    const bool kirchhoff = model.element_count() > 0 && model.elements[0].node_count == 3;
    return plate_errors(plate, kirchhoff, mindlin_for_all || !kirchhoff, model, r, registry);
  };
  return s;
}

ReferenceProblem plate() {
  ReferenceProblem p;
  p.name = "plate";
  p.title = "Simply supported square plate under uniform pressure, t/L = 0.01";
  p.kind = ElementKind::Shell;
  p.headline = Measure::PointDisplacement;
  p.source = kPlateSource;
  p.details =
      "Side 1, t = 0.01, E = 10.92e5, nu = 0.3, q = 1 (*DLOAD P), hard simple supports; a "
      "quarter with symmetry conditions, n x n elements, n = 1, 2, 4, ... (STRI3: each cell cut "
      "into two triangles; a CalculiX deck per run). Named points: the centre deflection "
      "against the Mindlin series (STRI3, a Kirchhoff element: against the Kirchhoff series, "
      "0.052 % below the Mindlin value at this thickness), and the moment sum M11 + M22 of the "
      "centre cell averaged over its stations against the series' mean over the cell (the same "
      "for both theories).";
  p.levels = 7;
  p.point_orders = [](const ElementFamily& f) {
    return std::array<int, 2>{2 * f.order, 2 * f.order};
  };
  for (const char* f : {"S8", "S9"})
    p.deviations[f] =
        "the fully integrated (3 x 3) quadratic shells still lock in shear on these meshes "
        "(element size / thickness 50 ... 0.8): pre-asymptotic, the factor by which their "
        "errors fall per halving grows level by level towards the 16 of order 4";
  for (const char* f : {"S8R", "S9R"})
    p.deviations[f] =
        "superconvergent on these regular meshes: the errors of the reduced quadratic shells "
        "fall faster than h^4 on the coarse levels and pass the fits' floor of 1e-6 within "
        "three to five levels, so the fit spans the steep start";
  p.setup = [](int level) {
    PlateDeck plate;
    plate.elements = 1 << level;
    return plate_problem(plate, false);
  };
  return p;
}

ReferenceProblem thin_plate() {
  ReferenceProblem p;
  p.name = "thin-plate";
  p.title = "Thin limit of plates: thickness t/L";
  p.kind = ElementKind::Shell;
  p.source = std::string("SPEC §7.3 (shear locking, Tab 7.1b); ") + kPlateSource;
  p.details =
      "The plate of `plate` (side 1, E = 10.92e5, nu = 0.3, q = 1) on the quarter's 4 x 4 "
      "elements (8 x 8 on the whole plate; element size / thickness = 0.125 / t), every family "
      "against the Mindlin series: the Kirchhoff element STRI3 lacks the shear deflection, "
      "which matters on the thick plates.";
  p.parameter = "thickness t/L";
  p.values = {0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.001, 1e-4};
  p.log_parameter = true;
  p.setup = [values = p.values](int level) {
    PlateDeck plate;
    plate.thickness = values.at(level);
    return plate_problem(plate, true);
  };
  return p;
}

}  // namespace

std::vector<ReferenceProblem> structural_accuracy_problems() {
  return {beam_cantilever(), plate()};
}

std::vector<ReferenceProblem> structural_sweeps() { return {thin_beam(), thin_plate()}; }

Model read_study_deck(const std::string& text, const std::string& name,
                      const ElementRegistry& registry) {
  const TemporaryDirectory directory;
  const std::filesystem::path path = directory.path() / (name + ".inp");
  {
    std::ofstream out(path);
    out << text;
    if (!out) throw InputError({path.string(), 0}, "cannot write the study's deck");
  }
  Model model = read_inp(path.string(), registry);
  model.source = name + ".inp";  // the temporary file goes; messages name the deck
  return model;
}

}  // namespace styk::studies::detail
