// Checks against CalculiX itself, run at test time on the unit-cube deck of io_test_support.cpp:
// the .dat reader on a fresh ccx report, and write_dat reproducing that report byte for byte.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io_test_support.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/io/dat_writer.hpp"
#include "support/ccx_runner.hpp"

namespace styk {
namespace {

// Runs ccx on the unit-cube deck in a fresh directory and returns the report's text.
std::string run_ccx_on_unit_cube(const std::string& dir_name) {
  const std::string dir = io_test::fresh_dir(dir_name);
  { std::ofstream(dir + "/cube.inp") << io_test::unit_cube_deck(); }
  if (test::run_ccx(dir, "cube").exit_code != 0 || !io_test::file_exists(dir + "/cube.dat")) {
    ADD_FAILURE() << "ccx failed, see " << dir << "/cube.log";
    return {};
  }
  return io_test::read_text(dir + "/cube.dat");
}

TEST(CcxDat, ReaderGetsCcxDisplacementsOfUniaxialTension) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  std::istringstream report(run_ccx_on_unit_cube("ccx_reader"));
  const std::vector<DatDisplacements> u = parse_dat_displacements(report);
  ASSERT_EQ(u.size(), 2u);
  EXPECT_EQ(u[0].time, 1.0);
  EXPECT_EQ(u[1].time, 1.5);
  ASSERT_EQ(u[0].u.size(), 8u);
  // Hand calculation, uniaxial stress in a unit cube (exact for C3D8): 4 x 100 N on 1 mm^2,
  // eps_z = 400 / 210000 = 1.9047619e-3, lateral eps = -0.3 eps_z = -5.7142857e-4.
  // ccx prints 7 significant digits: relative tolerance 1e-6.
  const double eps_z = 400.0 / 210000.0;
  for (Id top = 5; top <= 8; ++top) EXPECT_NEAR(u[0].u.at(top)[2], eps_z, 1e-6 * eps_z);
  EXPECT_NEAR(u[0].u.at(2)[0], -0.3 * eps_z, 1e-6 * 0.3 * eps_z);
  EXPECT_NEAR(u[0].u.at(8)[1], -0.3 * eps_z, 1e-6 * 0.3 * eps_z);
  EXPECT_EQ(u[0].u.at(1), (Vec3{0.0, 0.0, 0.0}));
  EXPECT_EQ(u[1].u.size(), 4u);  // step 2 prints set TOP only
}

OutputRequest request(OutputRequest::Kind kind, const std::string& set,
                      std::vector<std::string> vars) {
  OutputRequest r;
  r.kind = kind;
  r.set = set;
  r.vars = std::move(vars);
  return r;
}

// The cube model with the deck's output requests, and results holding exactly the numbers ccx
// printed: written back out, they must give ccx's report again, character for character.
TEST(CcxDat, WriteDatReproducesTheCcxReport) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const std::string ccx_report = run_ccx_on_unit_cube("ccx_writer");
  ASSERT_FALSE(ccx_report.empty());

  Model model = io_test::unit_cube();
  using Kind = OutputRequest::Kind;
  model.steps.resize(2);
  model.steps[0].outputs = {request(Kind::NodePrint, "NALL", {"U", "RF"}),
                            request(Kind::ElementPrint, "EALL", {"S", "E"})};
  model.steps[1].outputs = {request(Kind::NodePrint, "TOP", {"U"}),
                            request(Kind::ElementPrint, "EALL", {"S"})};

  Results results;
  for (int step = 1; step <= 2; ++step) {
    IncrementResult inc;
    inc.step = step;
    inc.total_time = step == 1 ? 1.0 : 1.5;
    inc.U.assign(8, Vec3{});
    inc.RF.assign(8, Vec3{});
    inc.ip_offset = {0, 8};
    inc.S.assign(8, Tensor6{});
    inc.E.assign(8, Tensor6{});
    results.increments.push_back(inc);
  }
  std::istringstream report(ccx_report);
  for (const DatBlock& block : parse_dat_blocks(report)) {
    IncrementResult& inc = results.increments[block.time == 1.0 ? 0 : 1];
    for (const DatRow& row : block.rows) {
      if (block.what.rfind("displacements", 0) == 0 || block.what.rfind("forces", 0) == 0) {
        Vec3& v = (block.what[0] == 'd' ? inc.U : inc.RF)[model.node_index(row.id)];
        for (int k = 0; k < 3; ++k) v[k] = row.values[k];
      } else {
        const bool stress = block.what.rfind("stresses", 0) == 0;
        Tensor6& t = (stress ? inc.S : inc.E)[row.integration_point - 1];
        for (int k = 0; k < 6; ++k) t[k] = row.values[k];
      }
    }
  }
  std::ostringstream ours;
  write_dat(ours, model, results);
  EXPECT_EQ(ours.str(), ccx_report);
}

}  // namespace
}  // namespace styk
