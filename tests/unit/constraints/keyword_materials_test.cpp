// *ELASTIC types and temperature tables, *EXPANSION types and tables with ZERO=, and material
// axes from *ORIENTATION on *SOLID SECTION (issue 15 item 3), against hand values: a unit cube of
// eight C3D8 in a homogeneous state (uniaxial stress, or free thermal expansion), which the
// element reproduces exactly, so every integration point must match to round-off.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "keyword_test_support.hpp"

namespace styk {
namespace {

using test::kSymmetricSupports;
using test::max_deviation;
using test::solve_text;
using test::unit_cube;

// Uniaxial stress sigma_xx = 100 from a tension of 100 on the faces at x = 1 (elements 2, 4, 6,
// 8, face S4).
const char* const kPull =
    "*STEP\n*STATIC\n*DLOAD\n2, P4, -100.\n4, P4, -100.\n6, P4, -100.\n"
    "8, P4, -100.\n*END STEP\n";

// The same pull on both x faces (P6 is the face at x = 0): a balanced load, for the 3-2-1
// supports below, which react nothing.
const char* const kPullBoth =
    "*STEP\n*STATIC\n*DLOAD\n1, P6, -100.\n2, P4, -100.\n3, P6, -100.\n4, P4, -100.\n5, P6, "
    "-100.\n6, P4, -100.\n7, P6, -100.\n8, P4, -100.\n*END STEP\n";

// Statically determinate supports (3-2-1): free expansion leaves no stress whatever the strain.
const char* const kThreeTwoOne = "*BOUNDARY\n1, 1, 3\n3, 2, 3\n7, 3\n";

constexpr double kTight = 1e-12;

// SPEC-free hand value: with engineering constants E1 = 1e5, nu12 = 0.3, nu13 = 0.2, a stress
// sigma11 = 100 gives eps11 = 1e-3, eps22 = -3e-4, eps33 = -2e-4 (compliance), to 1e-12 rel.
TEST(KeywordMaterials, EngineeringConstantsUniaxial) {
  const test::Solved s = solve_text(
      "eng_uniaxial.inp",
      unit_cube("*MATERIAL, NAME=M\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n100000., 50000., 20000., "
                "0.3, 0.2, 0.25, 30000., 20000.\n10000.\n") +
          kSymmetricSupports + kPull);
  const IncrementResult& inc = s.results.increments.at(0);
  EXPECT_LT(max_deviation(inc.S, 0, 100.0), 100.0 * kTight);
  EXPECT_LT(max_deviation(inc.S, 1, 0.0), 100.0 * kTight);
  EXPECT_LT(max_deviation(inc.E, 0, 1e-3), 1e-3 * 1e-11);
  EXPECT_LT(max_deviation(inc.E, 1, -3e-4), 1e-3 * 1e-11);
  EXPECT_LT(max_deviation(inc.E, 2, -2e-4), 1e-3 * 1e-11);
}

// Material axis 1 along global y (*ORIENTATION a = (0, 1, 0), b = (-1, 0, 0)): the pull along x
// acts along material axis 2: eps_xx = 100 / E2 = 2e-3, eps_yy = -nu12 100 / E1 = -3e-4,
// eps_zz = -nu23 100 / E2 = -5e-4; the global stress stays uniaxial.
TEST(KeywordMaterials, EngineeringConstantsInRotatedAxes) {
  const test::Solved s = solve_text(
      "eng_rotated.inp",
      unit_cube("*ORIENTATION, NAME=Q\n0., 1., 0., -1., 0., 0.\n*MATERIAL, NAME=M\n*ELASTIC, "
                "TYPE=ENGINEERING CONSTANTS\n100000., 50000., 20000., 0.3, 0.2, 0.25, 30000., "
                "20000.\n10000.\n",
                ", ORIENTATION=Q") +
          kSymmetricSupports + kPull);
  const IncrementResult& inc = s.results.increments.at(0);
  EXPECT_LT(max_deviation(inc.S, 0, 100.0), 100.0 * kTight);
  EXPECT_LT(max_deviation(inc.E, 0, 2e-3), 2e-3 * 1e-11);
  EXPECT_LT(max_deviation(inc.E, 1, -3e-4), 2e-3 * 1e-11);
  EXPECT_LT(max_deviation(inc.E, 2, -5e-4), 2e-3 * 1e-11);
  EXPECT_LT(max_deviation(inc.E, 3, 0.0), 2e-3 * 1e-11);
}

// Orthotropic and anisotropic constants: the strain of sigma11 = 100 is the first column of the
// compliance D^-1 of the deck's constants (hand: Eigen's inverse of the 6 x 6 matrix written from
// the data line), to 1e-10 relative.
TEST(KeywordMaterials, OrthotropicAndAnisotropicUniaxial) {
  Matrix6d D = Matrix6d::Zero();
  D(0, 0) = 150000.;
  D(0, 1) = D(1, 0) = 40000.;
  D(1, 1) = 90000.;
  D(0, 2) = D(2, 0) = 30000.;
  D(1, 2) = D(2, 1) = 35000.;
  D(2, 2) = 60000.;
  D(3, 3) = 25000.;
  D(4, 4) = 20000.;
  D(5, 5) = 15000.;
  const test::Solved ortho = solve_text(
      "ortho_uniaxial.inp",
      unit_cube("*MATERIAL, NAME=M\n*ELASTIC, TYPE=ORTHO\n150000., 40000., 90000., 30000., 35000., "
                "60000., 25000., 20000.\n15000.\n") +
          kSymmetricSupports + kPull);
  Vector6d eps = D.inverse().col(0) * 100.0;
  for (int c = 0; c < 3; ++c)
    EXPECT_LT(max_deviation(ortho.results.increments[0].E, c, eps[c]), 1e-10 * eps[0]) << c;

  // Anisotropic: the orthotropic matrix with couplings 11-12 and 22-23, the 21 constants in
  // CalculiX's order. Symmetric supports would resist the coupled shear: use 3-2-1 ones and
  // pull on both faces.
  D(0, 3) = D(3, 0) = 9000.;
  D(1, 5) = D(5, 1) = -4000.;
  const test::Solved aniso = solve_text(
      "aniso_uniaxial.inp",
      unit_cube("*MATERIAL, NAME=M\n*ELASTIC, TYPE=ANISO\n150000., 40000., 90000., 30000., 35000., "
                "60000., 9000., 0.,\n0., 25000., 0., 0., 0., 0., 20000., 0.,\n-4000., 0., 0., 0., "
                "15000.\n") +
          kThreeTwoOne + kPullBoth);
  eps = D.inverse().col(0) * 100.0;
  const IncrementResult& inc = aniso.results.increments[0];
  EXPECT_LT(max_deviation(inc.S, 0, 100.0), 100.0 * 1e-10);
  for (int c = 0; c < 6; ++c)
    EXPECT_LT(max_deviation(inc.E, c, c < 3 ? eps[c] : 0.5 * eps[c]), 1e-10 * eps[0]) << c;
}

// E and nu over temperature: rows (0: 200000, 0.30), (100: 150000, 0.32), (300: 100000, 0.35).
// At a uniform 150 degrees E = 137500, nu = 0.3275 (linear between the rows); at 400, beyond the
// table, the last row holds: E = 100000, nu = 0.35. Strains of sigma11 = 100 to 1e-12 relative.
TEST(KeywordMaterials, ElasticTableInterpolatedAtTheTemperature) {
  const std::string material =
      "*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.30, 0.\n150000., 0.32, 100.\n100000., 0.35, "
      "300.\n*EXPANSION\n0.\n";
  for (const auto& [T, E, nu] :
       {std::tuple{150.0, 137500.0, 0.3275}, std::tuple{400.0, 100000.0, 0.35}}) {
    const std::string deck =
        unit_cube(material) + kSymmetricSupports + "*STEP\n*STATIC\n*TEMPERATURE\nNALL, " +
        std::to_string(T) +
        "\n*DLOAD\n2, P4, -100.\n4, P4, -100.\n6, P4, -100.\n8, P4, -100.\n*END STEP\n";
    const test::Solved s = solve_text("elastic_table.inp", deck);
    const IncrementResult& inc = s.results.increments[0];
    EXPECT_LT(max_deviation(inc.E, 0, 100.0 / E), 1e-12 * 100.0 / E) << T;
    EXPECT_LT(max_deviation(inc.E, 1, -nu * 100.0 / E), 1e-12 * 100.0 / E) << T;
  }
}

// The secant expansion referred to ZERO = 20: alpha rows (0: 1.1e-5), (100: 1.3e-5), (200:
// 1.6e-5). Heated from T0 to 180 (alpha(180) = 1.54e-5) a free cube strains
// alpha(180) (180 - 20) - alpha(T0) (T0 - 20): 2.464e-3 from T0 = 20, 2.104e-3 from T0 = 50
// (alpha(50) = 1.2e-5); no stress. 1e-12 relative.
TEST(KeywordMaterials, ExpansionTableWithZero) {
  for (const auto& [T0, strain] : {std::pair{20.0, 2.464e-3}, std::pair{50.0, 2.104e-3}}) {
    const std::string deck =
        unit_cube(
            "*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n*EXPANSION, ZERO=20.\n1.1E-5, 0.\n"
            "1.3E-5, 100.\n1.6E-5, 200.\n") +
        kThreeTwoOne + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, " + std::to_string(T0) +
        "\n*STEP\n*STATIC\n*TEMPERATURE\nNALL, 180.\n*END STEP\n";
    const test::Solved s = solve_text("expansion_table.inp", deck);
    const IncrementResult& inc = s.results.increments[0];
    for (int c = 0; c < 3; ++c) EXPECT_LT(max_deviation(inc.E, c, strain), 1e-12 * strain) << T0;
    EXPECT_LT(max_deviation(inc.S, 0, 0.0), 1e-9);
  }
}

// Orthotropic expansion in axes turned 30 degrees about z, heated by 100: the material strain
// diag(1e-3, 2.5e-3, 0.5e-3) seen globally is eps_xx = c^2 1e-3 + s^2 2.5e-3, eps_yy = s^2 1e-3 +
// c^2 2.5e-3, eps_xy = c s (1e-3 - 2.5e-3) (tensor), eps_zz = 0.5e-3; no stress. Anisotropic
// coefficients with shear terms (a12 = 0.4e-5, a23 = -0.3e-5) give eps_12 = 0.4e-3 and
// eps_23 = -0.3e-3 directly. 1e-12 relative.
TEST(KeywordMaterials, OrthotropicAndAnisotropicExpansion) {
  const double c = std::cos(M_PI / 6.0), s = std::sin(M_PI / 6.0);
  const std::string heat =
      "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n*STEP\n*STATIC\n*TEMPERATURE\nNALL, 100.\n"
      "*END STEP\n";
  const test::Solved ortho = solve_text(
      "expansion_ortho.inp",
      unit_cube("*ORIENTATION, NAME=Q\n" + std::to_string(c) + ", " + std::to_string(s) + ", 0., " +
                    std::to_string(-s) + ", " + std::to_string(c) +
                    ", 0.\n*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n*EXPANSION, TYPE=ORTHO\n"
                    "1.0E-5, 2.5E-5, 0.5E-5\n",
                ", ORIENTATION=Q") +
          kThreeTwoOne + heat);
  const IncrementResult& a = ortho.results.increments[0];
  // The orientation's a and b were written with 6 digits: compare to what they give.
  const double cc = c * c, ss = s * s;
  EXPECT_LT(max_deviation(a.E, 0, cc * 1e-3 + ss * 2.5e-3), 1e-6 * 1e-3);
  EXPECT_LT(max_deviation(a.E, 1, ss * 1e-3 + cc * 2.5e-3), 1e-6 * 1e-3);
  EXPECT_LT(max_deviation(a.E, 3, c * s * (1e-3 - 2.5e-3)), 1e-6 * 1e-3);
  EXPECT_LT(max_deviation(a.E, 2, 0.5e-3), 1e-12 * 1e-3);
  EXPECT_LT(max_deviation(a.S, 0, 0.0), 1e-6);

  const test::Solved aniso =
      solve_text("expansion_aniso.inp",
                 unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n*EXPANSION, TYPE=ANISO\n"
                           "1.0E-5, 2.0E-5, 1.5E-5, 0.4E-5, 0., -0.3E-5\n") +
                     kThreeTwoOne + heat);
  const IncrementResult& b = aniso.results.increments[0];
  const double expected[6] = {1e-3, 2e-3, 1.5e-3, 0.4e-3, 0.0, -0.3e-3};
  for (int k = 0; k < 6; ++k) EXPECT_LT(max_deviation(b.E, k, expected[k]), 1e-12 * 2e-3) << k;
  EXPECT_LT(max_deviation(b.S, 3, 0.0), 1e-9);
}

// Bars take an isotropic material only: an orthotropic one is refused at the section's line.
TEST(KeywordMaterials, TrussRefusesAnOrthotropicMaterial) {
  const std::string deck =
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n"
      "*MATERIAL, NAME=M\n*ELASTIC, TYPE=ORTHO\n1., 0.1, 2., 0.1, 0.1, 3., 0.5, 0.6,\n0.7\n"
      "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n1.\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n"
      "*STEP\n*STATIC\n*CLOAD\n2, 1, 1.\n*END STEP\n";
  try {
    solve_text("truss_ortho.inp", deck);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 10) << e.what();
    EXPECT_NE(std::string(e.what()).find("isotropic material only"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace styk
