// The SPEC §4.6 bolted flange deck with standard elements (C3D8, C3D20; coarse, preload by the
// 1D estimate so no Styk solve is needed) and the §2.4 stacked C3D20 deck load in CalculiX:
// `ccx -i job` reads every keyword (*TRANSFORM TYPE=C, two contact pairs, a prescribed
// displacement in step 1, *STATIC, DIRECT) with no "*ERROR reading" and no fatal input error,
// and starts the analysis. Whether CalculiX's penalty contact converges is not asserted (as in
// contact_builders_ccx_test.cpp); the runs are cut at 300 s.
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

TEST(BoltedFlangeInCalculix, StandardElementDecksLoad) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const test::Elements elements;
  const std::map<std::string, std::string> coarse = {
      {"preload-by", "estimate"}, {"ring-layers", "2"},  {"neck-layers", "1"},
      {"gasket-layers", "1"},     {"shank-layers", "1"}, {"head-layers", "1"},
      {"gasket-rings", "4"},      {"neck-rings", "1"},   {"pressure", "2"}};
  struct Job {
    std::string builder;
    std::map<std::string, std::string> args;
  };
  std::vector<Job> jobs;
  for (const char* fam : {"C3D8", "C3D20"}) {
    auto args = coarse;
    args["element"] = fam;
    jobs.push_back({"bolted-flange", args});
  }
  jobs.push_back({"stacked-elements", {{"element", "C3D20"}}});
  const auto scratch = std::filesystem::path(::testing::TempDir()) /
                       ("styk_flange_ccx_" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  int index = 0;
  for (const Job& j : jobs) {
    SCOPED_TRACE(j.builder + " " + j.args.at("element"));
    const mesher::BuildResult r = mesher::run_builder(j.builder, j.args, elements.registry);
    const std::string job = "job" + std::to_string(index++);
    {
      std::ofstream out(scratch / (job + ".inp"));
      write_inp(r.model, out);
    }
    // Convergence of CalculiX's penalty contact is not asserted, only that it reads the deck.
    const std::string s = test::run_ccx(scratch, job, 300).log;
    EXPECT_EQ(s.find("*ERROR reading"), std::string::npos) << s.substr(0, 3000);
    EXPECT_EQ(s.find("*ERROR in"), std::string::npos) << s.substr(0, 3000);
    EXPECT_NE(s.find("increment 1 attempt 1"), std::string::npos) << s.substr(0, 3000);
  }
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
}

}  // namespace
}  // namespace styk
