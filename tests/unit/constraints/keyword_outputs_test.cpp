// Output requests of issue 15 item 5 against hand values: ENER, ELSE, EVOL and CENT of *EL PRINT,
// *SECTION PRINT, the stress error estimate ERR, print requests carried over to later steps,
// FREQUENCY=, TOTALS=ONLY and GLOBAL=, read back from the .dat report Styk writes.
#include <gtest/gtest.h>

#include <sstream>

#include <Eigen/Dense>

#include "keyword_test_support.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/io/dat_writer.hpp"

namespace styk {
namespace {

using test::kSymmetricSupports;
using test::solve_text;
using test::unit_cube;

const char* const kPullLoad = "*DLOAD\n2, P4, -100.\n4, P4, -100.\n6, P4, -100.\n8, P4, -100.\n";

std::vector<DatBlock> dat_of(const test::Solved& s) {
  std::ostringstream out;
  write_dat(out, s.model, s.results);
  std::istringstream in(out.str());
  return parse_dat_blocks(in);
}

// Uniaxial sigma = 100 in steel: ENER = sigma^2 / (2 E) at every point, ELSE = ENER / 8 per
// element (volume 1/8), EVOL = 1/8, their totals 8 times that; CENT is the omega^2 of the
// elements' CENTRIF load (0 for those without). 1e-12 relative (the .dat's 7 digits: 1e-6).
TEST(KeywordOutputs, EnergyVolumeAndCentrifugalSpeed) {
  const std::string deck =
      unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*DENSITY\n1E-30\n") +
      kSymmetricSupports + "*ELSET, ELSET=SPUN\n1\n*STEP\n*STATIC\n" + kPullLoad +
      "*DLOAD\nSPUN, CENTRIF, 25., 0., 0., 0., 0., 0., 1.\n*EL PRINT, ELSET=EALL\nENER\n"
      "*EL PRINT, ELSET=EALL, TOTALS=YES\nELSE, EVOL, CENT\n*EL PRINT, ELSET=EALL, "
      "TOTALS=ONLY\nELSE\n*END STEP\n";
  const test::Solved s = solve_text("energy.inp", deck);
  const IncrementResult& inc = s.results.increments[0];
  const double ener = 100.0 * 100.0 / (2.0 * 210000.0);
  for (double e : inc.ENER) EXPECT_NEAR(e, ener, 1e-9 * ener);
  for (double v : inc.element_volume) EXPECT_NEAR(v, 0.125, 1e-12);
  for (double w : inc.element_energy) EXPECT_NEAR(w, ener * 0.125, 1e-9 * ener);
  const std::vector<DatBlock> blocks = dat_of(s);
  ASSERT_EQ(blocks.size(), 7u);
  EXPECT_EQ(blocks[0].what, "internal energy density (elem, integ.pnt.,energy)");
  EXPECT_EQ(blocks[0].rows.size(), 64u);
  EXPECT_EQ(blocks[1].what, "internal energy (element, energy)");
  EXPECT_EQ(blocks[2].what, "total internal energy");
  EXPECT_NEAR(blocks[2].rows[0].values[0], ener, 1e-6 * ener);
  EXPECT_EQ(blocks[3].what, "volume (element, volume)");
  EXPECT_EQ(blocks[4].what, "total volume");
  EXPECT_NEAR(blocks[4].rows[0].values[0], 1.0, 1e-6);
  EXPECT_EQ(blocks[5].what, "centrifugal force(element,omega square)");
  EXPECT_EQ(blocks[5].rows[0].values[0], 25.0);
  EXPECT_EQ(blocks[5].rows[1].values[0], 0.0);
  EXPECT_EQ(blocks[6].what, "total internal energy");  // TOTALS=ONLY: the sum alone
}

// *SECTION PRINT across the cube's mid plane x = 0.5 under the uniaxial sigma = 100: normal
// force 100 (tension), area 1, centre (0.5, 0.5, 0.5), normal +x, no shear, torque or bending.
TEST(KeywordOutputs, SectionForcesOfAUniaxialState) {
  const std::string deck = unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
                           kSymmetricSupports +
                           "*SURFACE, NAME=MID\n1, S4\n3, S4\n5, S4\n7, S4\n*STEP\n*STATIC\n" +
                           kPullLoad + "*SECTION PRINT, SURFACE=MID, NAME=SP\nSOF\n*END STEP\n";
  const test::Solved s = solve_text("section.inp", deck);
  ASSERT_EQ(s.results.increments[0].sections.size(), 1u);
  const SectionForces& f = s.results.increments[0].sections[0];
  EXPECT_NEAR(f.normal_force, 100.0, 1e-10);
  EXPECT_NEAR(f.area, 1.0, 1e-12);
  EXPECT_NEAR(f.shear_force, 0.0, 1e-10);
  EXPECT_NEAR(f.bending_moment, 0.0, 1e-10);
  EXPECT_NEAR(f.centre[0], 0.5, 1e-12);
  EXPECT_NEAR(f.normal[0], 1.0, 1e-12);
  EXPECT_NEAR(f.moment[1], 50.0, 1e-10);  // force 100 along x at z = 0.5: moment +50 about y
  const std::vector<DatBlock> blocks = dat_of(s);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].what, "statistics");
  ASSERT_EQ(blocks[0].rows.size(), 4u);
  EXPECT_NEAR(blocks[0].rows[3].values[1], 100.0, 1e-4);
}

// ERR: a homogeneous stress leaves no difference between element and averaged stresses
// (ERR = 0); in a bent cantilever it is positive and the largest value falls when the mesh is
// refined (4 -> 16 elements along the beam: the linear stress varies less per element).
TEST(KeywordOutputs, StressErrorEstimate) {
  const std::string uniform = unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
                              kSymmetricSupports + "*STEP\n*STATIC\n" + kPullLoad +
                              "*EL FILE\nS\n*END STEP\n";
  const test::Solved flat = solve_text("err_uniform.inp", uniform);
  ASSERT_EQ(flat.results.increments[0].ERR.size(), 8u);
  for (double e : flat.results.increments[0].ERR) EXPECT_LT(e, 1e-6);

  auto cantilever = [](int n) {
    std::ostringstream d;
    d << "*NODE, NSET=NALL\n";
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i <= n; ++i)
          d << 1 + i + (n + 1) * (j + 2 * k) << ", " << 8.0 * i / n << ", " << j << ", " << k
            << "\n";
    d << "*ELEMENT, TYPE=C3D8I, ELSET=EALL\n";
    auto id = [n](int i, int j, int k) { return 1 + i + (n + 1) * (j + 2 * k); };
    for (int i = 0; i < n; ++i)
      d << i + 1 << ", " << id(i, 0, 0) << ", " << id(i + 1, 0, 0) << ", " << id(i + 1, 1, 0)
        << ", " << id(i, 1, 0) << ", " << id(i, 0, 1) << ", " << id(i + 1, 0, 1) << ", "
        << id(i + 1, 1, 1) << ", " << id(i, 1, 1) << "\n";
    d << "*NSET, NSET=FIX\n"
      << id(0, 0, 0) << ", " << id(0, 1, 0) << ", " << id(0, 0, 1) << ", " << id(0, 1, 1)
      << "\n*NSET, NSET=TIP\n"
      << id(n, 0, 0) << ", " << id(n, 1, 0) << ", " << id(n, 0, 1) << ", " << id(n, 1, 1)
      << "\n*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n"
      << "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n*BOUNDARY\nFIX, 1, 3\n*STEP\n*STATIC\n"
      << "*CLOAD\nTIP, 3, -1.\n*EL FILE\nS, ERR\n*END STEP\n";
    return d.str();
  };
  const test::Solved coarse = solve_text("err_coarse.inp", cantilever(4));
  const test::Solved fine = solve_text("err_fine.inp", cantilever(16));
  const auto largest = [](const test::Solved& s) {
    double m = 0.0;
    for (double e : s.results.increments[0].ERR) m = std::max(m, e);
    return m;
  };
  EXPECT_GT(largest(coarse), 1.0);
  EXPECT_LT(largest(fine), largest(coarse));
  // The figures docs/results.md quotes (measured; a change of the estimator shows here).
  EXPECT_NEAR(largest(coarse), 13.81, 0.005);
  EXPECT_NEAR(largest(fine), 8.05, 0.005);
  std::printf("ERR, bent cantilever: largest %.2f %% (4 elements) -> %.2f %% (16 elements)\n",
              largest(coarse), largest(fine));
}

// ERR is a continuum estimate: beams (section stations and fibres, not continuum points) get 0.
// The estimator used to read a beam's stresses and laws as if they were the full rule's points:
// CalculiX's b31 deck (a B31 cantilever with S on *EL FILE) then failed at random with "ERR:
// element 10 is NaN" (18 of 80 runs on 2 threads) or wrote garbage. Solved twice here.
TEST(KeywordOutputs, BeamsGetNoStressErrorEstimate) {
  std::ostringstream d;
  d << "*NODE, NSET=NALL\n";
  for (int i = 0; i <= 10; ++i) d << i + 1 << ", 0, 0, " << i << "\n";
  d << "*ELEMENT, TYPE=B31, ELSET=EALL\n";
  for (int i = 1; i <= 10; ++i) d << i << ", " << i << ", " << i + 1 << "\n";
  d << "*BOUNDARY\n1, 1, 6\n*MATERIAL, NAME=ALUM\n*ELASTIC\n1E7, .3\n"
    << "*BEAM SECTION, ELSET=EALL, MATERIAL=ALUM, SECTION=RECT\n.25, .25\n1., 0., 0.\n"
    << "*STEP\n*STATIC\n*CLOAD\n11, 1, 1.\n*EL FILE\nS\n*END STEP\n";
  for (int run = 0; run < 2; ++run) {
    const test::Solved s = solve_text("err_beam.inp", d.str());
    ASSERT_EQ(s.results.increments[0].ERR.size(), 10u);
    for (double e : s.results.increments[0].ERR) EXPECT_EQ(e, 0.0);
  }
}

// CalculiX's rules for requests over steps: step 2 has none and repeats step 1's; step 3's
// FREQUENCY=0 prints nothing (and wipes the earlier *NODE PRINT); TOTALS=ONLY prints the sum
// alone; GLOBAL=YES prints a *TRANSFORM node without its local system.
TEST(KeywordOutputs, CarryOverFrequencyTotalsOnlyAndGlobal) {
  const std::string deck =
      unit_cube("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n") +
      "*NSET, NSET=N27\n27\n*TRANSFORM, NSET=N27, TYPE=R\n0., 1., 0., -1., 0., 0.\n" +
      "*BOUNDARY\nX0, 1, 3\n*STEP\n*STATIC\n*CLOAD\n27, 2, 1.\n*NODE PRINT, NSET=N27\nU\n"
      "*NODE PRINT, NSET=N27, GLOBAL=YES\nU\n*NODE PRINT, NSET=X0, TOTALS=ONLY\nRF\n*END STEP\n"
      "*STEP\n*STATIC\n*END STEP\n*STEP\n*STATIC\n*NODE PRINT, NSET=N27, FREQUENCY=0\nU\n"
      "*END STEP\n";
  const test::Solved s = solve_text("carry_over.inp", deck);
  const std::vector<DatBlock> blocks = dat_of(s);
  ASSERT_EQ(blocks.size(), 6u);  // 3 in step 1, the same 3 in step 2, none in step 3
  EXPECT_TRUE(blocks[0].rows[0].local);
  EXPECT_FALSE(blocks[1].rows[0].local);
  // Local x is global y: the local first component is the global second one.
  EXPECT_NEAR(blocks[0].rows[0].values[0], blocks[1].rows[0].values[1],
              1e-6 * std::abs(blocks[1].rows[0].values[1]));
  EXPECT_EQ(blocks[2].what, "total force (fx,fy,fz)");
  // The *CLOAD on the transformed node acts along its local y, which is global -x: the held
  // face reacts +1 along x and nothing along y.
  EXPECT_NEAR(blocks[2].rows[0].values[0], 1.0, 1e-6);
  EXPECT_NEAR(blocks[2].rows[0].values[1], 0.0, 1e-6);
  EXPECT_EQ(blocks[3].time, 2.0);
  EXPECT_EQ(blocks[5].what, "total force (fx,fy,fz)");
}

// *EL PRINT of an element with an *ORIENTATION: by default its stresses print in the material
// axes (the orientation's name ending the row), with GLOBAL=YES in global ones. Axes turned 90
// degrees about z: local s11 is global s22 and local s12 is -global s12.
TEST(KeywordOutputs, ElementResultsInMaterialAxes) {
  const std::string deck = unit_cube(
                               "*ORIENTATION, NAME=TURNED\n0., 1., 0., -1., 0., 0.\n"
                               "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n",
                               ", ORIENTATION=TURNED") +
                           "*BOUNDARY\nX0, 1, 3\n*STEP\n*STATIC\n*CLOAD\n27, 2, 1.\n27, 1, 2.\n"
                           "*EL PRINT, ELSET=EALL\nS\n*EL PRINT, ELSET=EALL, GLOBAL=YES\nS\n"
                           "*END STEP\n";
  const test::Solved s = solve_text("orientation_print.inp", deck);
  const std::vector<DatBlock> blocks = dat_of(s);
  ASSERT_EQ(blocks.size(), 2u);
  double largest = 0.0;
  for (const DatRow& row : blocks[1].rows)
    for (double v : row.values) largest = std::max(largest, std::abs(v));
  for (std::size_t r = 0; r < blocks[0].rows.size(); ++r) {
    const DatRow& local = blocks[0].rows[r];
    const DatRow& global = blocks[1].rows[r];
    EXPECT_EQ(local.label, "TURNED");
    EXPECT_EQ(global.label, "");
    EXPECT_NEAR(local.values[0], global.values[1], 1e-6 * largest);
    EXPECT_NEAR(local.values[1], global.values[0], 1e-6 * largest);
    EXPECT_NEAR(local.values[3], -global.values[3], 1e-6 * largest);
  }
}

}  // namespace
}  // namespace styk
