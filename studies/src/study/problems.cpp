// The refinement series of `styk study accuracy` (docs/accuracy.md, "Problems").
#include "styk/studies/study/problems.hpp"

#include <cstdio>

#include "problem_support.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/studies/study/exact_conditions.hpp"

namespace styk::studies {
namespace detail {

std::string text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::function<void(const mesher::BuildResult&, Model&, const ElementRegistry&)> exact_ends(
    std::shared_ptr<const ExactSolution> exact, std::string fixed, std::string loaded) {
  return [exact, fixed, loaded](const mesher::BuildResult& build, Model& model,
                                const ElementRegistry& registry) {
    model.boundaries.clear();
    for (Step& step : model.steps) {
      step.boundaries.clear();
      step.cloads.clear();
      step.dloads.clear();
    }
    prescribe_exact_displacements(model, registry, build.mesh.surfaces.at(fixed), *exact);
    model.steps.at(0).cloads =
        exact_traction_loads(model, registry, build.mesh.surfaces.at(loaded), *exact);
  };
}

ProblemSetup lame_setup(int nr, int ntheta, double nu) {
  ProblemSetup s;
  s.builder = "thick-cylinder";
  s.args = {{"nr", text(nr)},      {"ntheta", text(ntheta)}, {"grading", "1"},
            {"poisson", text(nu)}, {"young", "1000"},        {"layer", "bottom"}};
  s.h = 6.0 / nr;
  s.exact = lame_cylinder(3, 9, 1, 0, 1000, nu);
  s.probes.displacement = {"u_r at r = 3 (bore)", {3, 0, 0}, {1, 0, 0}};
  s.probes.stress = {"hoop stress at r = 3", {3, 0, 0}, {0, 1, 0}, {0, 1, 0}};
  return s;  // the builder's deck is the exact problem: pressure 1 inside, plane strain
}

ProblemSetup beam_setup(const BeamSpec& beam) {
  ProblemSetup s;
  s.builder = "cantilever";
  s.args = {{"mesh", text(beam.nx) + "x" + text(beam.nz)},
            {"length", text(beam.L)},
            {"width", text(beam.b)},
            {"height", text(beam.h)},
            {"young", text(beam.E)},
            {"poisson", "0"},
            {"force", text(beam.P)},
            {"layer", "side"},
            {"distortion", beam.distortion},
            {"angle", text(beam.angle)}};
  s.h = beam.h / beam.nz;
  s.exact = timoshenko_cantilever(beam.L, beam.h, beam.b, beam.P, beam.E);
  // A parallelogram mesh turns the end faces about their mid-height: the tip's mid-height node
  // stays at x = L, the root's top corner moves by h/2 tan(angle).
  const double shift =
      beam.distortion == "parallelogram" ? beam.h / 2 * std::tan(beam.angle * kPi / 180) : 0.0;
  s.probes.displacement = {"tip deflection u_z at mid-height", {beam.L, 0, beam.h / 2}, {0, 0, 1}};
  s.probes.stress = {
      "bending stress sigma_xx at the root's top edge", {shift, 0, beam.h}, {1, 0, 0}, {1, 0, 0}};
  s.impose = exact_ends(s.exact, "ROOTFACE", "TIPFACE");
  return s;
}

}  // namespace detail

namespace {

using detail::text;

ReferenceProblem lame(const std::string& name, double nu) {
  ReferenceProblem p;
  p.name = name;
  p.title = "Lamé thick cylinder, nu = " + text(nu);
  p.source = "SPEC §3.1.7 geometry; Lamé (Timoshenko & Goodier §28), plane strain";
  p.details =
      "R 3-9, quarter, one element along the axis (uz = 0 on both ends: plane strain), unit "
      "internal pressure, E = 1000; nr = 2, 4, 8, ... elements through the wall, ntheta = 1.5 nr "
      "around, uniform; C3D21/C3D28 layer on z = 0 (every element). Named points: u_r and the "
      "hoop stress at the bore (3, 0, 0).";
  p.levels = 8;
  p.setup = [nu](int level) { return detail::lame_setup(2 << level, 3 << level, nu); };
  if (nu > 0.49) {
    const std::string locking =
        "volumetric locking (SPEC §3.1.7): the fully integrated rule imposes near "
        "incompressibility at too many points, so the coarse meshes are locked and the fit mixes "
        "the locked and the asymptotic range: below the theory while the locking lasts over the "
        "series, above it where the error drops steeply once the mesh is fine enough";
    for (const char* f : {"C3D8", "C3D14", "C3D20", "C3D27", "C3D21", "C3D28"})
      p.deviations[f] = locking;
    p.deviations["C3D8R"] =
        "its hourglass control's stiffness grows with the bulk modulus: locked on coarse "
        "meshes, converging at its order once the mesh is fine";
    p.deviations["C3D8I"] =
        "the point and L2 errors converge at order 2; the energy norm carries the volumetric "
        "strain error of the incompatible modes, weighted by the bulk modulus";
  }
  return p;
}

ReferenceProblem cantilever() {
  ReferenceProblem p;
  p.name = "cantilever";
  p.title = "Cantilever with an exact solution (nu = 0)";
  p.source = "SPEC §2.1 beam; Timoshenko & Goodier §21 (exact in 3D for nu = 0)";
  p.details =
      "Beam l 150 x h 5 x b 2.5, E = 70 000, nu = 0, P = 5: the root face takes the exact "
      "displacements, the free end the exact parabolic shear (consistent nodal forces); meshes "
      "12 x 2, 24 x 4, ... (one element across the width, C3D21/C3D28 layer on the side face: "
      "every element). Named points: tip deflection at mid-height (exact P l^3 / 3EI = 3.0857) "
      "and sigma_xx at the root's top edge.";
  p.levels = 8;
  for (const char* f : {"C3D20", "C3D27", "C3D21", "C3D28"})
    p.deviations[f] =
        "superconvergence: the exact displacement is a cubic polynomial and the meshes are "
        "rectangular, so the L2 error falls faster than h^3";
  p.deviations["C3D20R"] =
      "the reduced rule reproduces the beam solution at the nodes: its errors reach the solver's "
      "round-off (1e-7) on coarse meshes and stay out of the fits";
  for (const char* f : {"C3D8", "C3D14"})
    p.deviations[f] =
        "shear locking in bending: pre-asymptotic on these meshes (the element's bending "
        "stiffness is wrong until the elements are short against the beam's height, so the "
        "fitted slope includes the steep fall out of the locked range)";
  p.setup = [](int level) {
    detail::BeamSpec beam;
    beam.nx = 12 << level;
    beam.nz = 2 << level;
    return detail::beam_setup(beam);
  };
  return p;
}

ReferenceProblem curved_beam() {
  ReferenceProblem p;
  p.name = "curved-beam";
  p.title = "Curved beam (MacNeal-Harder geometry), exact curved-bar solution";
  p.source =
      "SPEC §3.1.3 stand-in geometry; curved bar bent by an end force (Timoshenko & Goodier §31), "
      "nu = 0";
  p.details =
      "90° arc r 4.12-4.32, thickness 0.1, E = 1e7, nu = 0, unit radial end force: root face "
      "(theta = 0) on the exact displacements, tip face with the exact shear; nr = 1, 2, 4, ... "
      "through the depth, 8 nr along the arc, C3D21/C3D28 layer on z = 0 (every element). Named "
      "points: radial tip displacement at r = 4.12 and the hoop stress at the inner fibre at 45°.";
  p.levels = 8;
  for (const char* f : {"C3D8", "C3D14"})
    p.deviations[f] =
        "shear locking in bending: pre-asymptotic on these meshes (the fitted slope includes the "
        "steep fall out of the locked range)";
  for (const char* f : {"C3D20", "C3D27", "C3D21", "C3D28", "C3D20R"})
    p.deviations[f] =
        "superconvergence of the displacements on the bar's regular polar meshes (the energy "
        "norm keeps its order 2)";
  p.deviations["C3D8I"] =
      "the incompatible modes capture the bending exactly on these near-rectangular elements: "
      "displacements converge faster than h^2 while the energy norm keeps its order";
  p.deviations["C3D8R"] = "pre-asymptotic on the coarse levels (hourglass control in bending)";
  p.setup = [](int level) {
    ProblemSetup s;
    const int nr = 1 << level;
    s.builder = "curved-beam";
    s.args = {{"nr", text(nr)}, {"n", text(8 * nr)}, {"poisson", "0"}, {"young", "1e7"}};
    s.h = 0.2 / nr;
    s.exact = curved_bar(4.12, 4.32, 0.1, 1.0, 1e7);
    const double c = std::cos(detail::kPi / 4), a = 4.12;
    s.probes.displacement = {"radial tip displacement at r = 4.12", {0, a, 0}, {0, 1, 0}};
    s.probes.stress = {"hoop stress at r = 4.12, 45°", {a * c, a * c, 0}, {-c, c, 0}, {-c, c, 0}};
    s.impose = detail::exact_ends(s.exact, "ROOTFACE", "TIPFACE");
    return s;
  };
  return p;
}

ReferenceProblem heat() {
  ReferenceProblem p;
  p.name = "heat";
  p.title = "Steady heat through a cylinder wall";
  p.source = "SPEC §6.2: T(r) = T1 - (T1 - T2) ln(r/r1) / ln(r2/r1)";
  p.details =
      "Wall r 2-3, T = 100 on r = 2 and 25 on r = 3, k = 1, full ring, one element along the axis "
      "(length 1); nr = 2, 4, 8, ... through the wall, 16 nr around; C3D21/C3D28 layer on "
      "z = 0 (every element). Named points: T at r = 2.5 and the radial heat flux at r = 2. "
      "C3D8R is left out: its one-point rule cannot carry a conduction (the solver refuses it).";
  p.levels = 8;
  p.skip_families = {"C3D8R"};
  p.setup = [](int level) {
    ProblemSetup s;
    const int nr = 2 << level;
    s.builder = "cylinder-wall";
    s.args = {{"nr", text(nr)}, {"ntheta", text(16 * nr)}, {"nz", "1"}, {"layer", "bottom"}};
    s.h = 1.0 / nr;
    s.exact = cylinder_wall_heat(2, 3, 100, 25, 1);
    s.probes.displacement = {"T at r = 2.5", {2.5, 0, 0}, {1, 0, 0}};
    s.probes.stress = {"radial heat flux at r = 2", {2, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    return s;
  };
  return p;
}

ReferenceProblem contact() {
  ReferenceProblem p;
  p.name = "contact";
  p.title = "Concentric cylinders in contact (Lamé)";
  p.source = "SPEC §3.2.2: analytic contact pressure 3.294 (compound Lamé cylinders)";
  p.details =
      "Inner r 1-2 (E 10, nu 0.3, 5 inside), outer r 2-3 (E 20, nu 0.2, 3 outside), plane "
      "strain, quarter, frictionless node-to-surface contact; nr = 2, 4, 8, ... per wall, 2 nr "
      "around; C3D21/C3D28 on the two contact layers (C3D20 elsewhere). Named points: u_r at the "
      "bore (1, 0, 0), the hoop stress at the rim (3, 0, 0); the contact pressure at every slave "
      "node against "
      "3.294.";
  p.levels = 8;
  for (const char* f : {"C3D20", "C3D20R"})
    p.deviations[f] =
        "the serendipity contact face fails the physical contact condition (SPEC §2.2): its "
        "corner nodes have negative nodal areas and open, so the contact pressure never "
        "converges and the displacements converge below their order";
  p.setup = [](int level) {
    ProblemSetup s;
    const int nr = 2 << level;
    s.builder = "cylinders";
    s.args = {{"nr", text(nr)}, {"ntheta", text(2 * nr)}};
    s.h = 1.0 / nr;
    std::shared_ptr<const CompoundCylinders> exact =
        compound_cylinders(1, 2, 3, 5, 3, 10, 0.3, 20, 0.2);
    s.probes.contact_pressure = exact->contact_pressure();
    s.exact = exact;
    s.probes.displacement = {"u_r at r = 1 (bore)", {1, 0, 0}, {1, 0, 0}};
    // The outer rim: the inner body's hoop stress at the bore is only -0.45 against pressures of
    // 3 and 5, so its relative error would magnify any error.
    s.probes.stress = {"hoop stress at r = 3 (rim)", {3, 0, 0}, {0, 1, 0}, {0, 1, 0}};
    return s;
  };
  return p;
}

}  // namespace

const std::vector<ReferenceProblem>& accuracy_problems() {
  static const std::vector<ReferenceProblem> problems = [] {
    std::vector<ReferenceProblem> all = {
        lame("lame", 0.3), lame("lame-incompressible", 0.4999), cantilever(), curved_beam(), heat(),
        contact()};
    for (ReferenceProblem& p : detail::structural_accuracy_problems()) all.push_back(std::move(p));
    return all;
  }();
  return problems;
}

const ReferenceProblem* find_problem(const std::string& name) {
  for (const auto* list : {&accuracy_problems(), &stability_sweeps(), &model_size_problems()})
    for (const ReferenceProblem& p : *list)
      if (p.name == name) return &p;
  return nullptr;
}

Model build_problem_model(const ProblemSetup& setup, const std::string& family,
                          const ElementRegistry& registry) {
  if (setup.deck) {
    const ElementFamily* f = find_family(family);
    if (!f) throw InputError({"styk study", 0}, "unknown element family '" + family + "'");
    return detail::read_study_deck(setup.deck(*f), setup.builder + "-" + family, registry);
  }
  std::map<std::string, std::string> args = setup.args;
  args["element"] = family;
  const mesher::BuildResult build = mesher::run_builder(setup.builder, args, registry);
  Model model = build.model;
  if (setup.impose) setup.impose(build, model, registry);
  return model;
}

}  // namespace styk::studies
