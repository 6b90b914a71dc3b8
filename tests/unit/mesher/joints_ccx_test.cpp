// The SPEC §4.4 spline joint and §4.5 P3G joint decks with standard elements (C3D8, C3D20; coarse
// meshes) load in CalculiX: `ccx -i job` reads every keyword of the deck (node sets, element-face
// surfaces, *CONTACT PAIR with PRESSURE-OVERCLOSURE=HARD, the rim *CLOAD, *CONTACT PRINT, *NODE
// PRINT with TOTALS) with no "*ERROR reading" and no fatal input error, and starts the analysis.
// CalculiX's penalty contact solves the spline decks (measured, ccx 2.20: C3D8 0.6 s, C3D20 5 s),
// which must finish; on the P3G decks it stops with "increment size smaller than minimum" (C3D8,
// 10 s) or needs 134 s and 225 increments (C3D20), so those runs are cut at 15 s and only the
// reading is asserted. (The §4.6 bolted flange runs in bolted_flange_ccx_test.cpp.)
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <system_error>

#include <unistd.h>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "support/ccx_runner.hpp"

namespace styk {
namespace {

struct CcxJoint {
  std::string builder;
  std::string family;
  bool must_finish;
};

std::ostream& operator<<(std::ostream& os, const CcxJoint& j) {
  return os << j.builder << " " << j.family;
}

std::map<std::string, std::string> coarse(const std::string& builder) {
  if (builder == "spline-joint")
    return {{"tooth", "2"},       {"groove", "2"},     {"flank-rows", "1"}, {"arm-rows", "1"},
            {"flange-rows", "1"}, {"shaft-rows", "2"}, {"hub-rings", "1"},  {"flange-rings", "2"}};
  return {{"around", "24"},    {"arm-rows", "1"},  {"flange-rows", "1"},
          {"shaft-rows", "2"}, {"hub-rings", "2"}, {"flange-rings", "3"}};
}

class JointsInCalculix : public ::testing::TestWithParam<CcxJoint> {};

TEST_P(JointsInCalculix, StandardElementDeckLoads) {
  const CcxJoint& j = GetParam();
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const test::Elements elements;
  auto args = coarse(j.builder);
  args["element"] = j.family;
  const mesher::BuildResult r = mesher::run_builder(j.builder, args, elements.registry);
  // A directory of this process: several builds may run the suite at the same time.
  const auto scratch = std::filesystem::path(::testing::TempDir()) /
                       ("styk_joints_ccx_" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  const std::string job = j.builder + "-" + j.family;
  {
    std::ofstream out(scratch / (job + ".inp"));
    write_inp(r.model, out);
  }
  const test::CcxRun run = test::run_ccx(scratch, job, 15);
  const int status = run.exit_code;
  const std::string& s = run.log;
  EXPECT_EQ(s.find("*ERROR reading"), std::string::npos) << s.substr(0, 3000);
  EXPECT_EQ(s.find("*ERROR in"), std::string::npos) << s.substr(0, 3000);
  EXPECT_NE(s.find("increment 1 attempt 1"), std::string::npos) << s.substr(0, 3000);
  if (j.must_finish) {
    EXPECT_EQ(status, 0);
    EXPECT_NE(s.find("Job finished"), std::string::npos)
        << s.substr(s.size() > 3000 ? s.size() - 3000 : 0);
  }
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
}

INSTANTIATE_TEST_SUITE_P(Spec, JointsInCalculix,
                         ::testing::Values(CcxJoint{"spline-joint", "C3D8", true},
                                           CcxJoint{"spline-joint", "C3D20", true},
                                           CcxJoint{"p3g-joint", "C3D8", false},
                                           CcxJoint{"p3g-joint", "C3D20", false}));

}  // namespace
}  // namespace styk
