// The solver's pre-solve warnings against the stability sweeps of `styk study stability`
// (docs/stability.md): each warning fires where the error at the named point passes 10 % and
// stays silent where it does not. The brackets below are the measured onsets the warnings are
// tuned to (solver/src/model_warnings.cpp, beam_warnings.cpp), each checked on both sides; where
// a warning cannot separate the two with a threshold, the measured miss or false alarm is
// asserted with its cause.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "hex_model_builder.hpp"
#include "styk/core/element.hpp"
#include "styk/studies/study/problems.hpp"
#include "styk/studies/study/run.hpp"
#include "styk/studies/study/stability_verdict.hpp"

namespace styk::studies {
namespace {

class AtlasWarnings : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { full_ = test::registry_with_plugins().release(); }
  static void TearDownTestSuite() {
    delete full_;
    full_ = nullptr;
  }

  static RunRecord run(const std::string& sweep, const std::string& family, double value,
                       bool solved = true) {
    const ReferenceProblem* p = find_problem(sweep);
    EXPECT_NE(p, nullptr);
    const auto it = std::find(p->values.begin(), p->values.end(), value);
    EXPECT_NE(it, p->values.end()) << value;
    const int level = static_cast<int>(it - p->values.begin());
    RunRecord r = run_in_process({"stability", sweep, family, level, 1}, full_->registry);
    if (solved) {
      EXPECT_TRUE(r.ok()) << r.failure;
    }
    return r;
  }

  // Below 10 % and silent at `passing`; above 10 % with warning `kind` at `failing`.
  static void expect_bracket(const std::string& sweep, const std::string& family, double passing,
                             double failing, const std::string& kind) {
    SCOPED_TRACE(sweep + " " + family);
    const RunRecord pass = run(sweep, family, passing);
    EXPECT_LT(*pass.error_of(kStabilityMeasure), kStabilityLimit) << passing;
    EXPECT_TRUE(pass.warnings.empty()) << passing << ": " << pass.warnings.front();
    if (failing < 0) return;
    const RunRecord fail = run(sweep, family, failing);
    EXPECT_GT(*fail.error_of(kStabilityMeasure), kStabilityLimit) << failing;
    EXPECT_EQ(fail.warnings, std::vector<std::string>{kind}) << failing;
  }

  // The smallest min/max det J over the 2 x 2 x 2 Gauss points of any C3D8I element of a sweep's
  // model at `level`.
  static double smallest_jacobian_ratio(const std::string& sweep, int level) {
    const Model model =
        build_problem_model(find_problem(sweep)->setup(level), "C3D8I", full_->registry);
    const TElement& element = *full_->registry.find("C3D8I");
    const IntegrationRule rule = element.rule(RuleKind::Full);
    double smallest = 1.0;
    for (int e = 0; e < model.element_count(); ++e) {
      ElementGeometry g;
      g.X.resize(8, 3);
      for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d) g.X(a, d) = model.coords[model.element_nodes(e)[a]][d];
      Eigen::VectorXd N(8);
      Eigen::MatrixXd dN(8, 3), dNdx(8, 3);
      double lo = INFINITY, hi = 0;
      for (int q = 0; q < rule.size(); ++q) {
        element.der(rule.points[q], N, dN);
        const double detJ = element.jacobian(g, dN, dNdx, q + 1);
        lo = std::min(lo, detJ);
        hi = std::max(hi, detJ);
      }
      smallest = std::min(smallest, lo / hi);
    }
    return smallest;
  }

  static test::FullRegistry* full_;
};
test::FullRegistry* AtlasWarnings::full_ = nullptr;

// Sweep "poisson" (0.5 - nu): the SPEC §3.1.7 cylinder on 4 x 6 elements.
TEST_F(AtlasWarnings, LockingWarningsFireFromEachFamilysOnset) {
  expect_bracket("poisson", "C3D8", 0.1, 0.05, "locking");  // nu 0.4 / 0.45
  for (const char* family : {"C3D8R", "C3D14", "C3D20", "C3D27", "C3D21"})
    expect_bracket("poisson", family, 0.01, 1e-3, "locking");  // nu 0.49 / 0.499
  expect_bracket("poisson", "C3D28", 1e-4, 1e-5, "locking");   // nu 0.4999 / 0.49999
  for (const char* family : {"C3D8I", "C3D20R"})
    expect_bracket("poisson", family, 1e-5, -1, "");  // no locking up to nu = 0.49999
}

// Sweeps "distortion-trapezoid" and "distortion-parallelogram": the exact cantilever, 10 x 2. The
// quadratic families stay below 10 % (below 2 %) up to 40 deg: no warning.
TEST_F(AtlasWarnings, QuadraticFamiliesStaySilentOnDistortedBeams) {
  for (const char* family : {"C3D20", "C3D20R", "C3D27", "C3D21", "C3D28"}) {
    expect_bracket("distortion-trapezoid", family, 40, -1, "");
    expect_bracket("distortion-parallelogram", family, 60, -1, "");
  }
  expect_bracket("distortion-parallelogram", "C3D8I", 60, -1, "");  // exact on parallelograms
}

// What no pre-solve check can see (docs/stability.md): fully integrated linear bricks shear-lock
// in bending whatever their shape, and C3D8R with two elements through the height is too
// flexible; the warnings stay silent there, because the same elements are accurate in the
// atlas' membrane and thermal problems.
TEST_F(AtlasWarnings, BendingFailuresOfLinearBricksAreNotWarned) {
  for (const char* family : {"C3D8", "C3D14", "C3D8R"}) {
    const RunRecord r = run("distortion-parallelogram", family, 0);
    EXPECT_GT(*r.error_of(kStabilityMeasure), kStabilityLimit) << family;
    EXPECT_TRUE(r.warnings.empty()) << family;
  }
}

// C3D8I loses its bending accuracy on trapezoids from 15 deg (min/max det J of its elements
// 0.84) without a warning: on the "poisson" sweep's ring (4 x 6) its elements taper more
// (min/max det J 0.79) and stay within 4 %, so det J cannot tell the two apart and a warning on
// it would be a false alarm there.
TEST_F(AtlasWarnings, IncompatibleModesOnTrapezoidsAreNotWarned) {
  EXPECT_NEAR(smallest_jacobian_ratio("distortion-trapezoid", 3), 0.836, 0.001);  // 15 deg
  EXPECT_NEAR(smallest_jacobian_ratio("poisson", 0), 0.793, 0.001);
  const RunRecord trapezoid = run("distortion-trapezoid", "C3D8I", 15);
  EXPECT_GT(*trapezoid.error_of(kStabilityMeasure), kStabilityLimit);
  EXPECT_TRUE(trapezoid.warnings.empty());
  const RunRecord ring = run("poisson", "C3D8I", 0.2);
  EXPECT_LT(*ring.error_of(kStabilityMeasure), 0.04);
  EXPECT_TRUE(ring.warnings.empty());
}

// Sweep "thin-beam" (slenderness L/h, 8 elements, uniform load; Timoshenko beam theory, SPEC
// §7.3): the shear-locking warning of the fully integrated 2-node beams fires from a bending
// stiffening k G A l^2 / (12 E I) of 0.11 (solver/src/beam_warnings.cpp): silent at L/h = 3
// (factor 0.045, error 3.9 %), warned at L/h = 10 (factor 0.50, error 33 %). The default
// (reduced) beams reproduce the tip deflection at every slenderness the solver accepts (below
// 1e-6 up to L/h = 1e4 for B31/B21).
TEST_F(AtlasWarnings, BeamLockingWarningBracketsTheThinLimit) {
  for (const char* family : {"B31-FULL", "B21-FULL"}) {
    expect_bracket("thin-beam", family, 3, 10, "locking");
    EXPECT_NEAR(*run("thin-beam", family, 3).error_of(kStabilityMeasure), 0.0387, 0.0005);
    EXPECT_NEAR(*run("thin-beam", family, 10).error_of(kStabilityMeasure), 0.330, 0.001);
  }
  for (const char* family : {"B31", "B21"}) {
    const RunRecord r = run("thin-beam", family, 10000);
    EXPECT_LT(*r.error_of(kStabilityMeasure), 1e-6) << family;
    EXPECT_TRUE(r.warnings.empty()) << family;
  }
}

// What the beam warnings get wrong on this sweep, measured (docs/stability.md): the quadratic
// beams with INTEGRATION=FULL are warned of from L/h = 10 on (their factor k G A l^2 / (60 E I)
// passes 0.11), but only the part of the bending that varies within an element locks, and with
// 8 elements under a uniform load that part is small: the error levels off at 0.52 %, a false
// alarm (a warning that knew the element count per member would be needed). At L/h = 1e4
// (A / I = 1.2e9) the direct solver accepts the quadratic beams on their backward error
// (docs/solver.md §5): B32 and B22 stay at 3.6e-6, the FULL ones at 0.52 %, still warned.
TEST_F(AtlasWarnings, QuadraticFullBeamsAreWarnedWhereTheyStayAccurate) {
  for (const char* family : {"B32-FULL", "B22-FULL"}) {
    const RunRecord r = run("thin-beam", family, 3000);
    EXPECT_NEAR(*r.error_of(kStabilityMeasure), 0.0052, 0.0001) << family;
    EXPECT_EQ(r.warnings, std::vector<std::string>{"locking"}) << family;
  }
  for (const char* family : {"B32", "B22", "B32-FULL", "B22-FULL"}) {
    const RunRecord r = run("thin-beam", family, 10000, false);
    ASSERT_TRUE(r.ok()) << family << ": " << r.failure;
    const bool full = std::string(family).find("FULL") != std::string::npos;
    EXPECT_NEAR(*r.error_of(kStabilityMeasure), full ? 0.0052 : 3.6e-6, full ? 1e-4 : 1e-7)
        << family;
    EXPECT_EQ(r.warnings.size(), full ? 1u : 0u) << family;
  }
}

// Sweep "thin-plate" (t/L, quarter of 4 x 4 elements, element size / thickness 0.125 / t;
// Navier series of the Mindlin plate, SPEC §7.3). The Mindlin families S4, S4R, S9 stay below 1 %
// at every thickness and no locking warning fires; S8 fails (89 %) at t/L = 1e-4 with its
// locking warning. Measured limits of the S8 warning (threshold element size / thickness 10):
// it fires from t/L = 0.01 (size / t 12.5) although S8 stays below 10 % down to t/L = 0.001
// (7.8 % at size / t 125), where SPEC Tab 7.1b's coarser 2 x 2 quarter fails at size / t 250
// (87 %): the onset depends on the mesh as well as on size / t, which a threshold cannot see.
// S8R fails at t/L = 1e-4 (32 %) unwarned; S9R's spurious-mode warning fires at every thickness
// where it stays within 0.012 %; STRI3 (Kirchhoff) lacks the shear deflection of the thick
// plate (17 % at t/L = 0.2) with no warning.
TEST_F(AtlasWarnings, PlateWarningsAgainstTheThinLimit) {
  for (const char* family : {"S4", "S4R", "S9"})
    for (double t : {0.2, 0.01, 1e-4}) {
      const RunRecord r = run("thin-plate", family, t);
      EXPECT_LT(*r.error_of(kStabilityMeasure), 0.01) << family << " " << t;
      EXPECT_TRUE(r.warnings.empty()) << family << " " << t;
    }
  expect_bracket("thin-plate", "S8", 0.02, 1e-4, "locking");
  EXPECT_NEAR(*run("thin-plate", "S8", 1e-4).error_of(kStabilityMeasure), 0.891, 0.001);
  const RunRecord s8 = run("thin-plate", "S8", 0.001);
  EXPECT_NEAR(*s8.error_of(kStabilityMeasure), 0.0776, 0.0005);
  EXPECT_EQ(s8.warnings, std::vector<std::string>{"locking"});
  const RunRecord s8r = run("thin-plate", "S8R", 1e-4);
  EXPECT_NEAR(*s8r.error_of(kStabilityMeasure), 0.317, 0.001);
  EXPECT_TRUE(s8r.warnings.empty());
  const RunRecord s9r = run("thin-plate", "S9R", 1e-4);
  EXPECT_LT(*s9r.error_of(kStabilityMeasure), 1.2e-4);
  EXPECT_EQ(s9r.warnings, std::vector<std::string>{"spurious modes"});
  const RunRecord stri3 = run("thin-plate", "STRI3", 0.2);
  EXPECT_NEAR(*stri3.error_of(kStabilityMeasure), 0.171, 0.001);
  EXPECT_TRUE(stri3.warnings.empty());
}

}  // namespace
}  // namespace styk::studies
