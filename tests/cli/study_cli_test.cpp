// `styk study` from the command line (docs/cli.md, "Studies"): a small accuracy series run in
// child processes (each run's memory measured), its CSV, page and picture; the same redrawn from
// the CSV; one run printed as a CSV row; a stability sweep; and bad input refused with exit 1 and
// a message naming what is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_runner.hpp"

namespace styk::testing {
namespace {

std::string styk() { return "'" + styk_executable() + "'"; }

// Width and height from a PNG's IHDR chunk (0 if the file is no PNG).
std::pair<int, int> png_size(const std::string& path) {
  const std::string bytes = read_file(path);
  if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0) return {0, 0};
  auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(bytes[at]) << 24) |
           (static_cast<unsigned char>(bytes[at + 1]) << 16) |
           (static_cast<unsigned char>(bytes[at + 2]) << 8) |
           static_cast<unsigned char>(bytes[at + 3]);
  };
  return {static_cast<int>(be32(16)), static_cast<int>(be32(20))};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

TEST(StudyCli, AccuracySeriesInChildProcessesWritesCsvPageAndChart) {
  const std::string dir = scratch_dir("study_accuracy");
  const CommandResult r =
      run_command(styk() +
                      " study accuracy --problems lame --families C3D8,C3D20 --max-levels 2 "
                      "--repeats 1 -o out",
                  dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> rows = lines_of(read_file(dir + "/out/accuracy.csv"));
  ASSERT_EQ(rows.size(), 5u);  // header + 2 families x 2 levels
  EXPECT_EQ(rows[1].rfind("accuracy,lame,C3D8,0,", 0), 0u) << rows[1];
  for (std::size_t i = 1; i < rows.size(); ++i) {
    // Column 12 (memory_mb): the child's peak resident memory, a few tens of MB.
    std::istringstream fields(rows[i]);
    std::string field;
    for (int c = 0; c < 12; ++c) std::getline(fields, field, ',');
    EXPECT_GT(std::stod(field), 5.0) << rows[i];
  }
  const std::string page = read_file(dir + "/out/accuracy.md");
  EXPECT_NE(page.find("# Speed against accuracy"), std::string::npos);
  EXPECT_NE(page.find("![lame: energy-norm error against DOF and wall time](./accuracy-lame.png)"),
            std::string::npos);
  EXPECT_EQ(png_size(dir + "/out/accuracy-lame.png"), std::make_pair(2000, 760));

  const CommandResult redraw =
      run_command(styk() + " study accuracy --from-csv out/accuracy.csv -o again", dir);
  ASSERT_EQ(redraw.exit_code, 0) << redraw.err;
  EXPECT_EQ(redraw.err.find("level"), std::string::npos);  // nothing ran
  EXPECT_EQ(read_file(dir + "/again/accuracy.csv"), read_file(dir + "/out/accuracy.csv"));
  EXPECT_EQ(png_size(dir + "/again/accuracy-lame.png"), std::make_pair(2000, 760));
}

TEST(StudyCli, OneRunPrintsItsRow) {
  const CommandResult r =
      run_command(styk() + " study run --problem heat --family C3D20 --level 0 --repeats 1",
                  scratch_dir("study_run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("accuracy,heat,C3D20,0,,,0.5,", 0), 0u) << r.out;
  const CommandResult refused =
      run_command(styk() + " study run --problem heat --family C3D8R --level 0 --repeats 1",
                  scratch_dir("study_run"));
  ASSERT_EQ(refused.exit_code, 0) << refused.err;  // a row with its failure, for the series
  EXPECT_NE(refused.out.find("too few for a conductance"), std::string::npos) << refused.out;
}

TEST(StudyCli, StabilitySweepListsWhereTheWarningFired) {
  const std::string dir = scratch_dir("study_stability");
  const CommandResult r = run_command(
      styk() + " study stability --problems poisson --families C3D8 --in-process -o out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_file(dir + "/out/stability.md");
  // C3D8 fails from nu = 0.45 (0.5 - nu = 0.05) and is warned there, silent at 0.4 and 0.3.
  EXPECT_NE(page.find("| C3D8 | 1e-05, 0.0001, 0.001, 0.01, 0.05 | 1e-05, 0.0001, 0.001, 0.01, "
                      "0.05 | – | – | locking |"),
            std::string::npos)
      << page;
  EXPECT_GT(png_size(dir + "/out/stability-poisson.png").first, 0);
}

TEST(StudyCli, BadInputIsRefusedByName) {
  const std::string dir = scratch_dir("study_bad");
  struct Case {
    std::string args, message;
  };
  std::ofstream(dir + "/bad.csv") << "not,a,study\n";
  const Case cases[] = {
      {"study accuracy --problems nope", "styk study accuracy: unknown problem 'nope'"},
      {"study accuracy --families C3D99", "unknown element family 'C3D99'"},
      {"study accuracy -o a --docs b", "give either -o DIR or --docs DIR, not both"},
      {"study stability --from-csv bad.csv", "bad.csv:1: not a study CSV"},
      {"study accuracy --from-csv missing.csv", "missing.csv: cannot read the study CSV"},
      {"study run --problem nope --family C3D8", "unknown problem 'nope'"},
  };
  for (const Case& c : cases) {
    const CommandResult r = run_command(styk() + " " + c.args, dir);
    EXPECT_EQ(r.exit_code, 1) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/a"));  // nothing half-written
}

// A joint report (docs/joints.md) on the coarse mesh: the page, its CSV and its chart in -o DIR;
// -o with --docs refused before anything is solved or written.
TEST(StudyCli, JointReportWritesPageCsvAndChart) {
  const std::string dir = scratch_dir("study_joint");
  const CommandResult r = run_command(styk() + " study spline --coarse -o out", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_file(dir + "/out/spline.md");
  EXPECT_NE(page.find("Generated by `styk study spline --coarse`"), std::string::npos);
  EXPECT_NE(page.find("| Torque carried by the flanks (3 x the sector's) | 1000.0 N m |"),
            std::string::npos)
      << page;
  EXPECT_NE(read_file(dir + "/out/spline-flank-pressure.csv").find("z_mm,max_pressure_MPa"),
            std::string::npos);
  EXPECT_EQ(png_size(dir + "/out/spline-flank-pressure.png"), std::make_pair(1200, 700));
  const CommandResult both = run_command(styk() + " study p3g -o a --docs b", dir);
  EXPECT_EQ(both.exit_code, 1);
  EXPECT_NE(both.err.find("give either -o DIR or --docs DIR, not both"), std::string::npos)
      << both.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/a"));
}

TEST(StudyCli, ListsNameProblemsAndFamilies) {
  const CommandResult r =
      run_command(styk() + " study model-size --list", scratch_dir("study_list"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"shrink-fit-full", "shrink-fit-quarter", "shrink-fit-sector",
                           "families: C3D8 C3D8R C3D8I C3D14 C3D20 C3D20R C3D27 C3D21 C3D28"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name;
}

}  // namespace
}  // namespace styk::testing
