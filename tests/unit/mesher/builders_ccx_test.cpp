// Decks of the builders that use only standard elements (C3D8, C3D20) load and run in CalculiX:
// `ccx -i job` in a scratch directory must exit 0 without an *ERROR line.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "support/ccx_runner.hpp"

namespace styk {
namespace {

TEST(BuildersInCalculix, StandardElementDecksRun) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const test::Elements elements;
  const auto scratch = std::filesystem::path(::testing::TempDir()) / "styk_mesher_ccx";
  std::filesystem::create_directories(scratch);
  for (const mesher::BuilderInfo& b : mesher::builder_catalogue()) {
    // The contact builders (SPEC §3.2, §4) run in contact_builders_ccx_test.cpp on coarse meshes.
    // §6.1 is an electric-conduction deck (*COUPLED THERMAL-ELECTRICAL), which ccx does not read.
    if (b.section.rfind("§3.2", 0) == 0 || b.section.rfind("§4", 0) == 0 || b.section == "§6.1")
      continue;
    for (const char* fam : {"C3D8", "C3D20"}) {
      SCOPED_TRACE(b.name + " " + fam);
      const mesher::BuildResult r =
          mesher::run_builder(b.name, {{"element", fam}}, elements.registry);
      const std::string job = b.name + "-" + fam;
      {
        std::ofstream out(scratch / (job + ".inp"));
        write_inp(r.model, out);
      }
      const test::CcxRun run = test::run_ccx(scratch, job);
      EXPECT_EQ(run.exit_code, 0);
      EXPECT_EQ(run.log.find("*ERROR"), std::string::npos) << run.log.substr(0, 2000);
      EXPECT_NE(run.log.find("Job finished"), std::string::npos) << run.log.substr(0, 2000);
    }
  }
  std::filesystem::remove_all(scratch);
}

}  // namespace
}  // namespace styk
