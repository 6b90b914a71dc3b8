// Convergence rates of every element family (MFEM style, STYLE.md practice 10), on the quick
// subset of the atlas (docs/accuracy.md; the full atlas is `styk study accuracy --docs docs`):
// each family's refinement series on two problems with exact solutions, the fitted order of the
// L2 displacement error within +-0.3 of p + 1 and that of the energy-norm (stress) error within
// +-0.3 of p, p the family's complete polynomial degree (1: C3D8, C3D8R, C3D8I, C3D14; 2: C3D20,
// C3D20R, C3D27, C3D21, C3D28). Problems and levels:
//   Lamé cylinder, nu = 0.3 (SPEC §3.1.7 geometry), levels 1-3 (nr = 4, 8, 16): every family;
//   steady heat through the wall (SPEC §6.2), levels 0-2 (nr = 2, 4, 8): every family but
//   C3D8R (one point cannot carry a conduction; the solver refuses it);
//   SPEC §3.2.2 cylinders in contact, levels 0-2: C3D8R's second problem.
// And the documented exceptions, measured (SPEC's "method fails" cases): C3D8 locks at
// nu = 0.4999 (SPEC §3.1.7) where C3D8R keeps its order (levels 2-4); C3D20's contact faces fail
// the physical contact condition (SPEC §2.2): its corner nodes carry no pressure. Beams and plates
// (no 3D field): the orders of their named points' errors, 2p, on the beam cantilever and the
// simply supported plate (tests at the end of this file).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hex_model_builder.hpp"
#include "styk/studies/results/convergence.hpp"
#include "styk/studies/study/families.hpp"
#include "styk/studies/study/run.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk::studies {
namespace {

constexpr double kTolerance = 0.3;

class AtlasRates : public test::PluginRegistrySuite<> {
 protected:
  // Runs levels first..first+2 of `problem` for `family` in this process (one solve each).
  static std::vector<RunRecord> series(const std::string& problem, const std::string& family,
                                       int first) {
    std::vector<RunRecord> runs;
    for (int level = first; level < first + 3; ++level) {
      runs.push_back(run_in_process({"accuracy", problem, family, level, 1}, registry()));
      EXPECT_TRUE(runs.back().ok())
          << problem << " " << family << " level " << level << ": " << runs.back().failure;
    }
    return runs;
  }

  static double order(const std::vector<RunRecord>& runs, Measure m) {
    const auto s = series_of(runs, runs.at(0).problem, runs.at(0).family, m);
    const auto fit = convergence_fit(s, m, Cost::Size);
    EXPECT_TRUE(fit) << measure_key(m);
    return fit ? fit->slope : -1.0;
  }

  static void expect_theoretical_orders(const std::string& problem, const std::string& family,
                                        int first) {
    const ElementFamily* f = find_family(family);
    ASSERT_NE(f, nullptr);
    const std::vector<RunRecord> runs = series(problem, family, first);
    SCOPED_TRACE(problem + " " + family);
    EXPECT_NEAR(order(runs, Measure::DisplacementL2), f->order + 1, kTolerance);
    EXPECT_NEAR(order(runs, Measure::Energy), f->order, kTolerance);
  }
};

TEST_F(AtlasRates, EveryFamilyConvergesAtItsOrderOnTheLameCylinder) {
  for (const ElementFamily& f : families_of_kind(ElementKind::Solid))
    expect_theoretical_orders("lame", f.name, 1);
}

TEST_F(AtlasRates, EveryConductingFamilyConvergesAtItsOrderOnTheHeatedWall) {
  for (const ElementFamily& f : families_of_kind(ElementKind::Solid))
    if (f.name != "C3D8R") expect_theoretical_orders("heat", f.name, 0);
}

TEST_F(AtlasRates, ReducedBrickConvergesAtItsOrderOnTheContactCylinders) {
  expect_theoretical_orders("contact", "C3D8R", 0);
}

// SPEC §3.1.7: fully integrated C3D8 locks at nu = 0.4999: over levels 2-4 (nr = 8, 16, 32) its
// L2 error falls from 93 % to 47 %, order 0.5 (asserted below 1, half its order), while C3D8R
// (one point, hourglass control) converges at 2 +- 0.3 from 27 % to 2 % over the same meshes.
TEST_F(AtlasRates, FullyIntegratedBrickLocksNearIncompressibility) {
  const std::vector<RunRecord> full = series("lame-incompressible", "C3D8", 2);
  EXPECT_LT(order(full, Measure::DisplacementL2), 1.0);
  EXPECT_GT(*full.back().error_of(Measure::DisplacementL2), 0.4);
  EXPECT_NEAR(order(series("lame-incompressible", "C3D8R", 2), Measure::DisplacementL2), 2.0,
              kTolerance);
}

// SPEC §2.2: the serendipity face of C3D20 has negative corner nodal areas, so node-to-surface
// contact on it opens the corner nodes: the worst slave node's pressure error stays 1 (no
// pressure where 3.294 is due) at every level, where C3D21's nine-node face converges.
TEST_F(AtlasRates, SerendipityContactFacesLeaveTheirCornersOpen) {
  for (const RunRecord& r : series("contact", "C3D20", 0)) {
    ASSERT_TRUE(r.error_of(Measure::ContactPressure));
    EXPECT_NEAR(*r.error_of(Measure::ContactPressure), 1.0, 1e-9) << "level " << r.level;
  }
  const std::vector<RunRecord> c3d21 = series("contact", "C3D21", 0);
  EXPECT_LT(*c3d21.back().error_of(Measure::ContactPressure), 0.01);
}

// Beams (docs/accuracy.md `beam-cantilever`: L/h = 20, uniform load, n = 2, 4, 8, ... elements;
// Timoshenko beam theory, closed form). The nodal tip deflection converges at 2p (nodal
// superconvergence of the exactly integrated bending): the fully integrated B31/B21 (p = 1) at
// 2 +- 0.3 once out of the locked range (levels 4-6, n = 32 ... 128: 11 %, 3.0 %, 0.77 %), the
// fully integrated B32/B22 (p = 2) at 4 +- 0.3 (levels 2-4, n = 8 ... 32: 1.5e-3 ... 7.9e-6). The
// root element's mean moment converges at 2 +- 0.3 for B31/B21 (levels 1-3; with INTEGRATION=FULL
// out of the locked range, levels 4-6). The
// documented exceptions: the reduced-integration beams reproduce the nodal deflection exactly,
// and the quadratic ones the element's mean moment too (errors asserted below 1e-9, the round-off
// of these solves), so they have no order to fit.
TEST_F(AtlasRates, BeamsConvergeAtTheirOrdersOnTheCantilever) {
  for (const char* family : {"B31-FULL", "B21-FULL"})
    EXPECT_NEAR(order(series("beam-cantilever", family, 4), Measure::PointDisplacement), 2.0,
                kTolerance)
        << family;
  for (const char* family : {"B32-FULL", "B22-FULL"})
    EXPECT_NEAR(order(series("beam-cantilever", family, 2), Measure::PointDisplacement), 4.0,
                kTolerance)
        << family;
  for (const char* family : {"B31", "B21"})
    EXPECT_NEAR(order(series("beam-cantilever", family, 1), Measure::PointStress), 2.0, kTolerance)
        << family;
  for (const char* family : {"B31-FULL", "B21-FULL"})
    EXPECT_NEAR(order(series("beam-cantilever", family, 4), Measure::PointStress), 2.0, kTolerance)
        << family;
  for (const char* family : {"B31", "B21", "B32", "B22"})
    for (const RunRecord& r : series("beam-cantilever", family, 0)) {
      EXPECT_LT(*r.error_of(Measure::PointDisplacement), 1e-9) << family << " " << r.level;
      if (std::string(family) == "B32" || std::string(family) == "B22") {
        EXPECT_LT(*r.error_of(Measure::PointStress), 1e-9) << family << " " << r.level;
      }
    }
}

// Plates (docs/accuracy.md `plate`: simply supported square, t/L = 0.01, quarter of n x n
// elements; Navier series). Centre deflection at 2p: S4 (MITC4) and the discrete-Kirchhoff
// triangle STRI3 (p = 1, against the Kirchhoff series) at 2 +- 0.3, S9R (p = 2) at 4 +- 0.3
// (levels 2-4; its level-4 error 4.5e-7 is below the fits' round-off floor of 1e-6, so the order
// is that of levels 2-3). The centre cell's mean moment sum converges at 2 +- 0.3 for S4 and
// STRI3 (1.76 on levels 4-6 for STRI3). Documented exceptions on the page: S8 and S9 (3 x 3
// rule) are pre-asymptotic at this thickness (the factor by which their error falls per halving
// grows towards 16), S8R and S9R fall faster than h^4 on the coarse levels.
TEST_F(AtlasRates, PlatesConvergeAtTheirOrdersOnTheSimplySupportedSquare) {
  const std::vector<RunRecord> s4 = series("plate", "S4", 2);
  EXPECT_NEAR(order(s4, Measure::PointDisplacement), 2.0, kTolerance);
  EXPECT_NEAR(order(s4, Measure::PointStress), 2.0, kTolerance);
  const std::vector<RunRecord> stri3 = series("plate", "STRI3", 4);
  EXPECT_NEAR(order(stri3, Measure::PointDisplacement), 2.0, kTolerance);
  EXPECT_NEAR(order(stri3, Measure::PointStress), 2.0, kTolerance);
  EXPECT_NEAR(order(series("plate", "S9R", 2), Measure::PointDisplacement), 4.0, kTolerance);
}

}  // namespace
}  // namespace styk::studies
