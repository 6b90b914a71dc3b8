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
// the physical contact condition (SPEC §2.2): its corner nodes carry no pressure.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hex_model_builder.hpp"
#include "styk/studies/results/convergence.hpp"
#include "styk/studies/study/families.hpp"
#include "styk/studies/study/run.hpp"

namespace styk::studies {
namespace {

constexpr double kTolerance = 0.3;

class AtlasRates : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { full_ = test::registry_with_plugins().release(); }
  static void TearDownTestSuite() {
    delete full_;
    full_ = nullptr;
  }

  // Runs levels first..first+2 of `problem` for `family` in this process (one solve each).
  static std::vector<RunRecord> series(const std::string& problem, const std::string& family,
                                       int first) {
    std::vector<RunRecord> runs;
    for (int level = first; level < first + 3; ++level) {
      runs.push_back(run_in_process({"accuracy", problem, family, level, 1}, full_->registry));
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

  static test::FullRegistry* full_;
};
test::FullRegistry* AtlasRates::full_ = nullptr;

TEST_F(AtlasRates, EveryFamilyConvergesAtItsOrderOnTheLameCylinder) {
  for (const ElementFamily& f : family_catalogue()) expect_theoretical_orders("lame", f.name, 1);
}

TEST_F(AtlasRates, EveryConductingFamilyConvergesAtItsOrderOnTheHeatedWall) {
  for (const ElementFamily& f : family_catalogue())
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

}  // namespace
}  // namespace styk::studies
