// SPEC §7.3 "where methods fail" for beams, and the beam column of SPEC §3.1.1 1b, solved from
// CalculiX decks (*BEAM SECTION) through the reader and the solver.
//
// Tab 7.1a is the cantilever of n linear Timoshenko elements: B21 (2 nodes, in the plane),
// E = 1000, G = 375 (so nu = 1/3: the printed nu = 0.3 does not go with G = 375, and G decides
// every column), L = 4, RECT b = h = 1, shear factor 5/6, a unit transverse force at the free end.
// "Normalised tip deflection" is w / w_T with the Timoshenko value w_T = P L^3 / (3 E I) +
// P L / (k G A) = 0.2688: with k = 5/6 every printed digit of the thick columns follows (k = 1 or
// Cowper's nu-dependent k, or normalising by P L^3 / (3 E I), miss 0.762 or 0.167). The thin beam
// is the one whose shear-to-bending ratio k G A L^2 / (E I) is 10^5 times the thick beam's 60:
// h = sqrt(1e-5) with b = 1 (every printed thin digit follows from that ratio alone; h = 0.01
// would give 0.20E-4). Reduced = 1 point (Styk's and Abaqus' default for B21), full = 2 points
// (INTEGRATION=FULL). The thesis divided tip deflections printed to 4 decimals: 2 full elements
// give w = 0.119467, printed 0.1195, and 0.1195 / 0.2688 = 0.445 as in the table, while the
// unrounded ratio 0.4444 would print 0.444 (likewise 8 elements: 0.2493 / 0.2688 = 0.927 against
// 0.9275 unrounded). Read that way, all 20 cells are asserted to the printed digits:
// |round(w, 4) / round(w_T, 4) - printed| <= half a unit of the last printed digit; unrounded,
// 18 cells match and those two differ by one unit in the third decimal.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "beam_decks.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kThin = 3.1622776601683794e-3;  // sqrt(1e-5)

// |actual - printed| <= half a unit in the printed value's last digit; `printed` as the thesis
// prints it, e.g. "0.762" or "0.128E-3".
void expect_printed(double actual, const std::string& printed, const std::string& what) {
  const std::size_t e = printed.find('E');
  const std::string mantissa = printed.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(printed.substr(e + 1));
  const std::size_t dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  const double value = std::stod(mantissa) * std::pow(10.0, exponent);
  const double half_unit = 0.5 * std::pow(10.0, exponent - decimals);
  EXPECT_NEAR(actual, value, half_unit * (1.0 + 1e-9)) << what << ": printed " << printed;
}

struct Column {
  double h;
  const char* integration;
  std::vector<std::string> printed;  // the thesis, n = 1, 2, 4, 8, 16
  std::vector<std::string> styk;     // Styk's unrounded w / w_T, as docs/verification.md prints it
};

double timoshenko_tip(double h) {
  const double E = 1000.0, G = 375.0, L = 4.0, A = h, I = h * h * h / 12.0;
  return L * L * L / (3.0 * E * I) + L / (5.0 / 6.0 * G * A);
}

// SPEC §7.3 Tab 7.1a, all 20 cells.
TEST(Spec73Tab71a, LinearTimoshenkoCantileverMatchesEveryPrintedDigit) {
  const ElementRegistry registry = test::builtin_registry();
  const std::vector<Column> columns = {
      {1.0,
       "REDUCED",
       {"0.762", "0.940", "0.985", "0.996", "0.999"},
       {"0.761905", "0.940476", "0.985119", "0.996280", "0.999070"}},
      {1.0,
       "FULL",
       {"0.167", "0.445", "0.762", "0.927", "0.981"},
       {"0.166667", "0.444444", "0.761905", "0.927536", "0.980843"}},
      {kThin,
       "REDUCED",
       {"0.750", "0.938", "0.984", "0.996", "0.999"},
       {"0.750000", "0.937500", "0.984375", "0.996094", "0.999023"}},
      {kThin,
       "FULL",
       {"0.20E-5", "0.80E-5", "0.32E-4", "0.128E-3", "0.512E-3"},
       {"2.00000E-6", "7.99994E-6", "3.19990E-5", "1.27984E-4", "5.11738E-4"}},
  };
  for (const Column& column : columns) {
    const std::vector<int> counts = {1, 2, 4, 8, 16};
    for (std::size_t k = 0; k < counts.size(); ++k) {
      test::Cantilever c;
      c.type = "B21";
      c.elements = counts[k];
      std::ostringstream dimensions;
      dimensions.precision(17);
      dimensions << "1., " << column.h;
      c.dimensions = dimensions.str();
      c.integration = column.integration;
      const auto four_decimals = [](double v) { return std::round(v * 1e4) / 1e4; };
      const double w = test::tip_uy(test::solve_cantilever(c, registry));
      const double ratio = four_decimals(w) / four_decimals(timoshenko_tip(column.h));
      const std::string cell = std::string(column.h == 1.0 ? "thick " : "thin ") +
                               column.integration + " n = " + std::to_string(counts[k]);
      expect_printed(ratio, column.printed[k], cell);
      expect_printed(w / timoshenko_tip(column.h), column.styk[k], cell + " (unrounded)");
    }
  }
}

// The closed forms behind the columns (SPEC §7.3, "Structural benchmarks"), to round-off: with
// w_b = P L^3 / (3 E I), l = L / n,
//   reduced: w = w_b (1 - 1 / (4 n^2)) + P L / (k G A),
//   full:    w = w_b (1 - 1 / (4 n^2)) / (1 + k G A l^2 / (12 E I)) + P L / (k G A),
// i.e. full integration stiffens the bending by exactly the factor the locking warning quotes.
TEST(Spec73Tab71a, ReducedAndFullElementsFollowTheirClosedForms) {
  const ElementRegistry registry = test::builtin_registry();
  const double E = 1000.0, G = 375.0, L = 4.0, I = 1.0 / 12.0, kGA = 5.0 / 6.0 * G;
  const double w_b = L * L * L / (3.0 * E * I);
  for (const int n : {1, 3, 8}) {
    test::Cantilever c;
    c.type = "B21";
    c.elements = n;
    const double reduced = test::tip_uy(test::solve_cantilever(c, registry));
    EXPECT_NEAR(reduced, w_b * (1.0 - 1.0 / (4.0 * n * n)) + L / kGA, 1e-10 * reduced);
    c.integration = "FULL";
    const double full = test::tip_uy(test::solve_cantilever(c, registry));
    const double l = L / n, stiffening = 1.0 + kGA * l * l / (12.0 * E * I);
    EXPECT_NEAR(full, w_b * (1.0 - 1.0 / (4.0 * n * n)) / stiffening + L / kGA, 1e-10 * full)
        << "n = " << n;
  }
}

// A thin cantilever in space (B31, B32; RECT 0.1 x 0.2, L = 10, so L / h = 50), tip force along y:
// against Euler-Bernoulli w_EB = P L^3 / (3 E I) and Timoshenko w_T = w_EB + P L / (k G A).
// B32 with reduced integration reproduces w_T to round-off with one element (its 2 points
// integrate the shear of the cubic field exactly); B31 follows the closed forms of Tab 7.1a in
// space too (reduced w_T - w_EB / (4 n^2), full with the locking factor); the fully integrated
// B32 locks mildly: its constant curvature is free, only the curvature's variation within an
// element is stiffened, so the error falls as 1 / n^2: 1.42 % at 4 elements, 0.038 % at 16.
TEST(Spec73ThinCantilever, EulerBernoulliAndTimoshenkoClosedForms) {
  const ElementRegistry registry = test::builtin_registry();
  const double E = 2.1e5, nu = 0.3, G = E / (2 * (1 + nu)), L = 10.0, a = 0.1, b = 0.2;
  const double I = a * b * b * b / 12.0, A = a * b, kGA = 5.0 / 6.0 * G * A;
  const double w_eb = L * L * L / (3.0 * E * I), w_t = w_eb + L / kGA;
  test::Cantilever c;
  c.length = L;
  c.young = E;
  c.poisson = nu;
  c.dimensions = "0.1, 0.2";

  c.type = "B32";
  c.elements = 1;
  EXPECT_NEAR(test::tip_uy(test::solve_cantilever(c, registry)), w_t, 1e-10 * w_t);
  EXPECT_NEAR(w_t / w_eb - 1.0, 3.1e-4, 0.05e-4);  // the shear part at L / h = 50
  const double b32_full[] = {0.98580, 0.99962};
  for (const int n : {4, 16}) {
    c.type = "B31";
    c.elements = n;
    c.integration = "";
    EXPECT_NEAR(test::tip_uy(test::solve_cantilever(c, registry)), w_t - w_eb / (4.0 * n * n),
                1e-10 * w_t);
    c.integration = "FULL";
    const double l = L / n, stiffening = 1.0 + kGA * l * l / (12.0 * E * I);
    EXPECT_NEAR(test::tip_uy(test::solve_cantilever(c, registry)),
                w_eb * (1.0 - 1.0 / (4.0 * n * n)) / stiffening + L / kGA, 1e-10 * w_t);
    c.type = "B32";
    EXPECT_NEAR(test::tip_uy(test::solve_cantilever(c, registry)) / w_t, b32_full[n == 4 ? 0 : 1],
                0.5e-5)
        << "B32 full, n = " << n;
  }
}

// A uniform line load q (P2) on a cantilever: w = q L^4 / (8 E I) + q L^2 / (2 k G A) at the tip,
// reproduced to round-off by 4 B31 and by 2 B32 elements with the default (reduced) rule and the
// consistent nodal loads; the support reacts with -q L and the moment -q L^2 / 2.
TEST(Spec73ThinCantilever, LineLoadIsExactAtTheTip) {
  const ElementRegistry registry = test::builtin_registry();
  const double E = 2.1e5, G = E / 2.6, L = 10.0, I = 0.1 * 0.008 / 12.0, A = 0.02, q = 0.5;
  const double exact = q * L * L * L * L / (8.0 * E * I) + q * L * L / (2.0 * 5.0 / 6.0 * G * A);
  for (const char* type : {"B31", "B32"}) {
    test::Cantilever c;
    c.type = type;
    c.elements = std::string(type) == "B31" ? 4 : 2;
    c.length = L;
    c.young = E;
    c.poisson = 0.3;
    c.dimensions = "0.1, 0.2";
    c.line_load = true;
    c.load = "P2, 0.5";
    const IncrementResult inc = test::solve_cantilever(c, registry);
    EXPECT_NEAR(test::tip_uy(inc), exact, 1e-9 * exact) << type;
    EXPECT_NEAR(inc.RF[0][1], -q * L, 1e-9) << type;
    EXPECT_NEAR(inc.RM[0][2], -q * L * L / 2.0, 1e-9) << type;
  }
}

// SPEC §3.1.1 1b, the B21 column: L = 6, height W = 0.2 along the load, width D = 0.1,
// E = 1e7, nu = 0.3, unit tip force; 6, 12, 24 elements. Theory (Euler-Bernoulli) 0.108; the
// thesis prints 0.1062 / 0.1069 / 0.1073 (its Abaqus run). Styk's B21 (reduced, the default)
// gives the element's closed form 0.108 (1 - 1 / (4 n^2)) + P L / (k G A) = 0.10734, 0.10791,
// 0.10805: within 0.6 % of theory and converging to the Timoshenko value 0.108094 from below.
// The thesis' values sit 1.7 / 1.0 / 0.65 % below theory, below both Styk rules' neighbourhood:
// full integration gives 0.01199, 0.03599, 0.07202 (locking, asserted below), and an Abaqus-style
// slenderness compensation (softer shear) would land above 0.1079; no plain Timoshenko
// beam of the stated section reproduces them, so their run's settings are not recoverable.
TEST(Spec311StraightBeam, B21ColumnOfTest1b) {
  const ElementRegistry registry = test::builtin_registry();
  const double E = 1e7, G = E / 2.6, L = 6.0, I = 0.1 * 0.008 / 12.0, A = 0.02;
  const double bending = L * L * L / (3.0 * E * I), shear = L / (5.0 / 6.0 * G * A);
  EXPECT_NEAR(bending, 0.108, 1e-12);
  EXPECT_NEAR(bending + shear, 0.108094, 0.5e-6);  // the Timoshenko value
  const std::vector<int> counts = {6, 12, 24};
  const std::vector<double> thesis = {0.1062, 0.1069, 0.1073};
  const std::vector<double> styk = {0.10734, 0.10791, 0.10805};
  const std::vector<double> full = {0.01199, 0.03599, 0.07202};
  for (std::size_t k = 0; k < counts.size(); ++k) {
    test::Cantilever c;
    c.type = "B21";
    c.elements = counts[k];
    c.length = L;
    c.young = E;
    c.poisson = 0.3;
    c.dimensions = "0.1, 0.2";
    const double w = test::tip_uy(test::solve_cantilever(c, registry));
    const int n = counts[k];
    EXPECT_NEAR(w, bending * (1.0 - 1.0 / (4.0 * n * n)) + shear, 1e-10 * w);
    EXPECT_NEAR(w, styk[k], 0.5e-5) << "n = " << n;  // the value docs/verification.md prints
    EXPECT_LT(std::abs(w / 0.108 - 1.0), 0.0062);
    EXPECT_GT(w, thesis[k]);  // the thesis' run is stiffer
    const double thesis_below[] = {0.0167, 0.0102, 0.0065};
    EXPECT_NEAR(1.0 - thesis[k] / 0.108, thesis_below[k], 0.5e-4);
    // Abaqus' slenderness compensation softens the shear stiffness by f = 1 / (1 + 0.25 l^2 A /
    // (12 I)); the reduced element's closed form with it lies above 0.1079, far from the thesis.
    const double l = L / n, f = 1.0 / (1.0 + 0.25 * l * l * A / (12.0 * I));
    EXPECT_GT(bending * (1.0 - 1.0 / (4.0 * n * n)) + shear / f, 0.1079);
    c.integration = "FULL";
    EXPECT_NEAR(test::tip_uy(test::solve_cantilever(c, registry)), full[k], 0.5e-5) << "n = " << n;
  }
}

// samples/beam-frame.inp (samples/README.md): a BOX column, a RECT arm loaded -5000 along z at its
// tip (2500, 0, 3000) and a PIPE arm pulled +1000 along x at (0, 2000, 3000), clamped at the base.
// Statics: the base reacts with RF = (-1000, 0, 5000) and RM = (0, -1.55e7, 2e6); the arm carries
// the shear SF2 = -5000 at every station; 144 free dofs (24 nodes x 6).
TEST(BeamFrameSample, ReactionsBalanceTheLoads) {
  const ElementRegistry registry = test::builtin_registry();
  const Model model = read_inp(std::string(STYK_SOURCE_DIR) + "/samples/beam-frame.inp", registry);
  AnalysisReport report;
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, &report);
  const IncrementResult& inc = results.increments.back();
  EXPECT_EQ(report.dofs, 144);
  const int base = model.node_index(1);
  const Vec3 rf{-1000.0, 0.0, 5000.0}, rm{0.0, -1.55e7, 2e6};
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(inc.RF[base][d], rf[d], 1e-6);
    EXPECT_NEAR(inc.RM[base][d], rm[d], 1e-3);
  }
  const ElementSet* arm = model.find_elset("ARM");
  ASSERT_NE(arm, nullptr);
  for (int e : arm->elements)
    for (int k = inc.station_offset[e]; k < inc.station_offset[e + 1]; ++k)
      EXPECT_NEAR(inc.SF[k][1], -5000.0, 1e-6);
}

}  // namespace
}  // namespace styk
