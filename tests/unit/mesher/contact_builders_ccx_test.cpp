// The contact builders' decks with standard elements (C3D8, C3D20) load in CalculiX: `ccx -i job`
// (coarse meshes, to keep the test short: about 10 s) reads every keyword — no "*ERROR reading" and
// no fatal input error — and starts the analysis. CalculiX turns PRESSURE-OVERCLOSURE=HARD into a
// penalty and does not converge on every deck (the cylinders and the punch on the foundation stop
// with "increment size smaller than minimum"); that is accepted here: Styk's exact contact is what
// solves them, and a step that stops early leaves the later steps unread, so the decks that do
// converge are listed and must finish.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
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

struct CcxCase {
  std::string builder;
  std::map<std::string, std::string> args;
  std::set<std::string> must_finish;  // families CalculiX converges with (measured, ccx 2.20)
};

TEST(ContactBuildersInCalculix, StandardElementDecksLoad) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const test::Elements elements;
  const std::map<std::string, std::string> tiny_fit = {{"around", "2"},
                                                       {"shaft-rings", "1"},
                                                       {"sleeve-rings", "1"},
                                                       {"fit-rows", "2"},
                                                       {"end-rows", "1"}};
  auto with = [](std::map<std::string, std::string> a, const std::string& k, const std::string& v) {
    a[k] = v;
    return a;
  };
  const std::vector<CcxCase> cases = {
      {"punch-foundation",
       {{"n", "4"}, {"punch-rows", "2"}, {"outer", "4"}, {"depth-rows", "4"}},
       {}},
      {"cylinders", {{"nr", "1"}, {"ntheta", "4"}}, {}},
      {"two-cantilevers", {{"n", "10"}}, {"C3D8", "C3D20"}},
      {"punch-halfspace", {{"n", "2"}, {"outer", "2"}, {"depth-rows", "3"}}, {"C3D8", "C3D20"}},
      // C3D20 stops in the third step (the second push): all three steps have been read.
      {"shrink-fit", tiny_fit, {"C3D8"}},
      {"shrink-fit", with(with(tiny_fit, "model", "B"), "torques", "100"), {"C3D8", "C3D20"}},
      {"conical-fit",
       {{"around", "4"}, {"fit-rows", "4"}, {"top-rows", "1"}, {"sleeve-rings", "1"}},
       {"C3D8", "C3D20"}},
  };
  // A directory of this process: several builds may run the suite at the same time.
  const auto scratch = std::filesystem::path(::testing::TempDir()) /
                       ("styk_contact_ccx_" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  int index = 0;
  for (const CcxCase& c : cases) {
    for (const char* fam : {"C3D8", "C3D20"}) {
      SCOPED_TRACE(c.builder + " " + fam);
      auto args = c.args;
      args["element"] = fam;
      const mesher::BuildResult r = mesher::run_builder(c.builder, args, elements.registry);
      const std::string job = "job" + std::to_string(index++);
      {
        std::ofstream out(scratch / (job + ".inp"));
        write_inp(r.model, out);
      }
      const test::CcxRun run = test::run_ccx(scratch, job, 300);
      const int status = run.exit_code;
      const std::string& s = run.log;
      EXPECT_EQ(s.find("*ERROR reading"), std::string::npos) << s.substr(0, 3000);
      EXPECT_EQ(s.find("*ERROR in calinput"), std::string::npos) << s.substr(0, 3000);
      EXPECT_NE(s.find("increment 1 attempt 1"), std::string::npos) << s.substr(0, 3000);
      if (c.must_finish.count(fam)) {
        EXPECT_EQ(status, 0);
        EXPECT_NE(s.find("Job finished"), std::string::npos)
            << s.substr(s.size() > 3000 ? s.size() - 3000 : 0);
      }
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
}

}  // namespace
}  // namespace styk
