// Reading .dat reports: a committed CalculiX 2.20 report (data/ccx_two_steps.dat, produced by
// `ccx -i ccx_two_steps` from data/ccx_two_steps.inp), edge cases, and a round trip through
// write_dat.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "styk/io/dat_reader.hpp"
#include "styk/io/dat_writer.hpp"

namespace styk {
namespace {

const std::string kSample = std::string(STYK_SOURCE_DIR) + "/tests/unit/io/data/ccx_two_steps.dat";

TEST(DatReader, ReadsEveryBlockOfACcxReport) {
  std::ifstream in(kSample);
  ASSERT_TRUE(in) << kSample;
  const std::vector<DatBlock> blocks = parse_dat_blocks(in);
  ASSERT_EQ(blocks.size(), 7u);
  EXPECT_EQ(blocks[0].what, "displacements (vx,vy,vz)");
  EXPECT_EQ(blocks[0].set, "NALL");
  EXPECT_EQ(blocks[0].time, 1.0);
  EXPECT_EQ(blocks[0].rows.size(), 8u);
  EXPECT_EQ(blocks[2].what, "total force (fx,fy,fz)");
  EXPECT_EQ(blocks[2].set, "FIX");
  ASSERT_EQ(blocks[2].rows.size(), 1u);
  EXPECT_EQ(blocks[2].rows[0].id, 0);
  EXPECT_EQ(blocks[2].rows[0].values, (std::vector<double>{-1.169628E-14, -1.915598E-14, -400.0}));
  EXPECT_EQ(blocks[3].what, "stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)");
  ASSERT_EQ(blocks[3].rows.size(), 8u);
  EXPECT_EQ(blocks[3].rows[7].id, 1);
  EXPECT_EQ(blocks[3].rows[7].integration_point, 8);
  EXPECT_EQ(blocks[3].rows[7].values.size(), 6u);
  EXPECT_EQ(blocks[3].rows[7].values[2], 400.0);
  EXPECT_EQ(blocks[6].time, 1.5);
}

TEST(DatReader, DisplacementsPerTime) {
  std::ifstream in(kSample);
  const std::vector<DatDisplacements> u = parse_dat_displacements(in);
  ASSERT_EQ(u.size(), 2u);
  EXPECT_EQ(u[0].time, 1.0);
  EXPECT_EQ(u[0].u.size(), 8u);
  EXPECT_EQ(u[0].u.at(1234567), (Vec3{-5.714286E-04, -5.714286E-04, 1.904762E-03}));
  EXPECT_EQ(u[1].time, 1.5);
  EXPECT_EQ(u[1].u.size(), 4u);  // set TOP
  EXPECT_EQ(u[1].u.at(1234567), (Vec3{-1.693743E-03, -1.693743E-03, 2.250539E-03}));
  EXPECT_EQ(u[1].u.count(1), 0u);
}

TEST(DatReader, MergesSetsOfTheSameTimeAndReadsFortranExponents) {
  std::istringstream in(
      "\n displacements (vx,vy,vz) for set A and time  0.1000000E+01\n\n"
      "         1  1.000000-100  0.000000E+00  2.000000E+00\n"
      "\n displacements (vx,vy,vz) for set B and time  0.1000000E+01\n\n"
      "         5 -1.000000E+00  0.000000E+00  0.000000E+00\n");
  const std::vector<DatDisplacements> u = parse_dat_displacements(in);
  ASSERT_EQ(u.size(), 1u);
  ASSERT_EQ(u[0].u.size(), 2u);
  EXPECT_DOUBLE_EQ(u[0].u.at(1)[0], 1e-100);
  EXPECT_EQ(u[0].u.at(5)[0], -1.0);
}

TEST(DatReader, MalformedRowNamesTheLine) {
  std::istringstream in(
      "\n displacements (vx,vy,vz) for set A and time  0.1000000E+01\n\n"
      "         1  1.000000E+00  oops  2.000000E+00\n");
  try {
    parse_dat_blocks(in);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(".dat line 4"), std::string::npos) << e.what();
  }
}

TEST(DatReader, RoundTripsWriteDatToSevenDigits) {
  Model model;
  for (int n = 0; n < 5; ++n) model.add_node(10 * (n + 1), {1.0 * n, 0, 0}, {});
  Step step;
  OutputRequest request;
  request.vars = {"U"};
  step.outputs = {request};
  model.steps = {step, step};
  Results results;
  for (int k = 1; k <= 2; ++k) {
    IncrementResult inc;
    inc.step = k;
    inc.total_time = 0.75 * k;
    for (int n = 0; n < 5; ++n)
      inc.U.push_back({1.0 / (n + k + 2), -3.0e-7 * n * k, 12345.678901 * k});
    results.increments.push_back(inc);
  }
  std::stringstream text;
  write_dat(text, model, results);
  const std::vector<DatDisplacements> u = parse_dat_displacements(text);
  ASSERT_EQ(u.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(u[k].time, results.increments[k].total_time);
    ASSERT_EQ(u[k].u.size(), 5u);
    for (int n = 0; n < 5; ++n)
      for (int c = 0; c < 3; ++c) {
        const double expected = results.increments[k].U[n][c];
        // E13.6 keeps 7 significant digits: relative error below 5e-7.
        EXPECT_NEAR(u[k].u.at(10 * (n + 1))[c], expected, 5e-7 * std::abs(expected));
      }
  }
}

}  // namespace
}  // namespace styk
