// *DLOAD GRAV and CENTRIF, *DSLOAD, *INITIAL CONDITIONS TYPE=STRESS, *CHANGE SOLID SECTION and
// *BOUNDARY, FIXED (issue 15 item 2) against hand values.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "keyword_test_support.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

using test::kSymmetricSupports;
using test::max_deviation;
using test::solve_text;
using test::unit_cube;

Vec3 total_reaction(const test::Solved& s, std::size_t increment = 0) {
  Vec3 sum{0.0, 0.0, 0.0};
  for (const Vec3& rf : s.results.increments.at(increment).RF)
    for (int d = 0; d < 3; ++d) sum[d] += rf[d];
  return sum;
}

// A column 1 x 1 x 4 of C3D20 (1 x 1 x 4 elements) along z under its own weight, standing on
// its base (z held), Poisson's ratio 0 so that the held flat base is the exact solution (with
// contraction the free base would bulge): sigma_zz(z) = -rho g (4 - z), linear, which C3D20
// represents exactly; the base reacts rho g A L = 7.85e-9 * 9810 * 4. 1e-10 relative.
TEST(KeywordLoads, GravityOnAColumn) {
  std::string deck = "*NODE, NSET=NALL\n";
  // 3 x 3 grid per level at z = 0, 0.5, ..., 4; C3D20 uses corners and mid-edges only.
  auto id = [](int i, int j, int k) { return 1 + i + 3 * j + 9 * k; };
  for (int k = 0; k <= 8; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        if ((i % 2) + (j % 2) + (k % 2) <= 1)
          deck += std::to_string(id(i, j, k)) + ", " + std::to_string(0.5 * i) + ", " +
                  std::to_string(0.5 * j) + ", " + std::to_string(0.5 * k) + "\n";
  deck += "*ELEMENT, TYPE=C3D20, ELSET=EALL\n";
  for (int e = 0; e < 4; ++e) {
    const int c = 2 * e;
    const int n[20] = {id(0, 0, c),     id(2, 0, c),     id(2, 2, c),     id(0, 2, c),
                       id(0, 0, c + 2), id(2, 0, c + 2), id(2, 2, c + 2), id(0, 2, c + 2),
                       id(1, 0, c),     id(2, 1, c),     id(1, 2, c),     id(0, 1, c),
                       id(1, 0, c + 2), id(2, 1, c + 2), id(1, 2, c + 2), id(0, 1, c + 2),
                       id(0, 0, c + 1), id(2, 0, c + 1), id(2, 2, c + 1), id(0, 2, c + 1)};
    deck += std::to_string(e + 1);
    for (int k = 0; k < 20; ++k) deck += (k == 15 ? ",\n" : ", ") + std::to_string(n[k]);
    deck += "\n";
  }
  deck += "*NSET, NSET=BASE\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if ((i % 2) + (j % 2) <= 1) deck += std::to_string(id(i, j, 0)) + "\n";
  deck +=
      "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.\n*DENSITY\n7.85E-9\n"
      "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n*BOUNDARY\nBASE, 3\n1, 1, 2\n3, 2\n"
      "*STEP\n*STATIC\n*DLOAD\nEALL, GRAV, 9810., 0., 0., -1.\n*END STEP\n";
  const test::Solved s = solve_text("gravity_column.inp", deck);
  const IncrementResult& inc = s.results.increments[0];
  const double rho_g = 7.85e-9 * 9810.0;
  ElementRegistry registry = test::builtin_registry();
  double worst = 0.0;
  for (int e = 0; e < s.model.element_count(); ++e) {
    // Integration point heights from the rule (3 x 3 x 3 Gauss on an element of height 1).
    const IntegrationRule rule = registry.find("C3D20")->rule(RuleKind::Full);
    for (int p = 0; p < rule.size(); ++p) {
      const double z = e + 0.5 * (1.0 + rule.points[p][2]);
      worst = std::max(worst, std::abs(inc.S[inc.ip_offset[e] + p][2] + rho_g * (4.0 - z)));
    }
  }
  EXPECT_LT(worst, 1e-10 * rho_g * 4.0);
  EXPECT_NEAR(total_reaction(s)[2], rho_g * 4.0, 1e-12 * rho_g * 4.0);
}

// A bar from r = 1 to r = 4 along x, spinning about z (omega^2 = 1e6), held at r = 1: the hub
// reacts rho omega^2 A integral r dr = 7.85e-9 * 1e6 * 0.5 * 7.5 along -x. 1e-12 relative.
TEST(KeywordLoads, CentrifugalReaction) {
  std::string deck = "*NODE, NSET=NALL\n";
  auto id = [](int i, int j, int k) { return 1 + i + 7 * j + 14 * k; };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 7; ++i)
        deck += std::to_string(id(i, j, k)) + ", " + std::to_string(1.0 + 0.5 * i) + ", " +
                std::to_string(j * 1.0 - 0.5) + ", " + std::to_string(0.5 * k) + "\n";
  deck += "*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
  for (int i = 0; i < 6; ++i)
    deck += std::to_string(i + 1) + ", " + std::to_string(id(i, 0, 0)) + ", " +
            std::to_string(id(i + 1, 0, 0)) + ", " + std::to_string(id(i + 1, 1, 0)) + ", " +
            std::to_string(id(i, 1, 0)) + ", " + std::to_string(id(i, 0, 1)) + ", " +
            std::to_string(id(i + 1, 0, 1)) + ", " + std::to_string(id(i + 1, 1, 1)) + ", " +
            std::to_string(id(i, 1, 1)) + "\n";
  deck +=
      "*NSET, NSET=HUB\n1, 8, 15, 22\n*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*DENSITY\n"
      "7.85E-9\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n*BOUNDARY\nHUB, 1, 3\n"
      "*STEP\n*STATIC\n*DLOAD\nEALL, CENTRIF, 1.0E6, 0., 0., 0., 0., 0., 1.\n*END STEP\n";
  const test::Solved s = solve_text("centrifugal_bar.inp", deck);
  const double expected = 7.85e-9 * 1e6 * 0.5 * 7.5;
  EXPECT_NEAR(total_reaction(s)[0], -expected, 1e-12 * expected);
  EXPECT_NEAR(total_reaction(s)[1], 0.0, 1e-12 * expected);
}

// *DSLOAD P on the top surface of the cube (area 1) pushes down with 4.5: the supports react
// +4.5 along z, exactly as the same *DLOAD P2 on the four top elements. 1e-12 relative.
TEST(KeywordLoads, SurfacePressure) {
  const std::string deck = unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
                           kSymmetricSupports +
                           "*SURFACE, NAME=TOP\n5, S2\n6, S2\n7, S2\n8, S2\n*STEP\n*STATIC\n"
                           "*DSLOAD\nTOP, P, 4.5\n*END STEP\n";
  const test::Solved s = solve_text("dsload.inp", deck);
  EXPECT_NEAR(total_reaction(s)[2], 4.5, 1e-12 * 4.5);
  EXPECT_LT(max_deviation(s.results.increments[0].S, 2, -4.5), 1e-12 * 4.5);
}

// A uniform initial stress in a body free to deform (3-2-1 supports) relaxes completely: the
// stress becomes 0 and the strain -C sigma0 (C the isotropic compliance), as in CalculiX.
TEST(KeywordLoads, InitialStressRelaxesInAFreeBody) {
  std::string rows;
  for (int e = 1; e <= 8; ++e)
    for (int p = 1; p <= 8; ++p)
      rows += std::to_string(e) + ", " + std::to_string(p) + ", 100., -40., 25., 10., 0., 5.\n";
  const std::string deck = unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.25\n") +
                           "*INITIAL CONDITIONS, TYPE=STRESS\n" + rows +
                           "*BOUNDARY\n1, 1, 3\n3, 2, 3\n7, 3\n*STEP\n*STATIC\n*END STEP\n";
  const test::Solved s = solve_text("initial_stress.inp", deck);
  const IncrementResult& inc = s.results.increments[0];
  for (int c = 0; c < 6; ++c) EXPECT_LT(max_deviation(inc.S, c, 0.0), 1e-9) << c;
  const double E = 200000.0, nu = 0.25;
  const double eps11 = -(100.0 - nu * (-40.0 + 25.0)) / E;
  const double eps12 = -10.0 * (1.0 + nu) / E;  // tensor shear: sigma12 / (2 G)
  EXPECT_LT(max_deviation(inc.E, 0, eps11), 1e-12 * std::abs(eps11));
  EXPECT_LT(max_deviation(inc.E, 3, eps12), 1e-12 * std::abs(eps11));
}

// *CHANGE SOLID SECTION: the pull of step 1 carried into step 2 after the whole cube turns from
// steel (210000) to aluminium (70000): the same stress, three times the strain. 1e-12 relative.
TEST(KeywordLoads, ChangeSolidSectionBetweenSteps) {
  const std::string deck = unit_cube(
                               "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*MATERIAL, "
                               "NAME=ALU\n*ELASTIC\n70000., 0.3\n") +
                           kSymmetricSupports +
                           "*STEP\n*STATIC\n*DLOAD\n2, P4, -100.\n4, P4, -100.\n6, P4, -100.\n"
                           "8, P4, -100.\n*END STEP\n*STEP\n*CHANGE SOLID SECTION, ELSET=EALL, "
                           "MATERIAL=ALU\n*STATIC\n*END STEP\n";
  const test::Solved s = solve_text("change_section.inp", deck);
  EXPECT_LT(max_deviation(s.results.increments[0].E, 0, 100.0 / 210000.0), 1e-12);
  EXPECT_LT(max_deviation(s.results.increments[1].E, 0, 100.0 / 70000.0), 1e-12);
  EXPECT_LT(max_deviation(s.results.increments[1].S, 0, 100.0), 1e-9);
}

// *BOUNDARY, FIXED: the face x = 1 stretched by the pull of step 1 keeps that displacement in
// step 2, whose load is gone (OP=NEW): the cube stays strained at 100 / E. 1e-12 relative.
TEST(KeywordLoads, BoundaryFixedHoldsThePreviousDisplacement) {
  const std::string deck = unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
                           kSymmetricSupports +
                           "*STEP\n*STATIC\n*DLOAD\n2, P4, -100.\n4, P4, -100.\n6, P4, -100.\n"
                           "8, P4, -100.\n*END STEP\n*STEP\n*STATIC\n*BOUNDARY, FIXED\nX1, 1\n"
                           "*DLOAD, OP=NEW\n*END STEP\n";
  const test::Solved s = solve_text("boundary_fixed.inp", deck);
  const double u = 100.0 / 210000.0;
  EXPECT_NEAR(test::displacement(s, 3, 0)[0], u, 1e-12 * u);
  EXPECT_NEAR(test::displacement(s, 3, 1)[0], u, 1e-12 * u);
  EXPECT_LT(max_deviation(s.results.increments[1].S, 0, 100.0), 1e-8);
}

}  // namespace
}  // namespace styk
