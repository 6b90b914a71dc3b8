// Reading `styk solve --progress json` (docs/cli.md "Progress protocol"): the JSON lines the GUI
// turns into progress, log, warnings, errors and the results path; lines that are no event of
// this protocol version stay text. The lines below are the ones `styk solve` writes
// (cli/src/json_progress.cpp; SolveProtocol.TheSolverSpeaksTheProtocol runs it).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../cli/cli_runner.hpp"
#include "session/solve_protocol.hpp"

namespace styk::gui {
namespace {

TEST(SolveProtocol, PhasesInfoWarningsErrorsAndDone) {
  SolveLine l = parse_solve_line(R"({"event":"begin","phase":"assemble","styk_progress":1})"
                                 "\n");
  EXPECT_EQ(l.kind, SolveLine::Kind::PhaseBegin);
  EXPECT_EQ(l.phase, "assemble");
  l = parse_solve_line(R"({"event":"end","phase":"factorise","seconds":0.011,"styk_progress":1})");
  EXPECT_EQ(l.kind, SolveLine::Kind::PhaseEnd);
  EXPECT_EQ(l.phase, "factorise");
  EXPECT_DOUBLE_EQ(l.seconds, 0.011);
  l = parse_solve_line(
      R"({"event":"info","message":"pattern: 1863 dofs, 205749 nonzeros","styk_progress":1})");
  EXPECT_EQ(l.kind, SolveLine::Kind::Info);
  EXPECT_EQ(l.text, "pattern: 1863 dofs, 205749 nonzeros");
  l = parse_solve_line(R"({"event":"warning","message":"8 elements of type C3D8R0 have 27 )"
                       R"(zero-energy modes","styk_progress":1})");
  EXPECT_EQ(l.kind, SolveLine::Kind::Warning);
  EXPECT_EQ(l.text, "8 elements of type C3D8R0 have 27 zero-energy modes");
  l = parse_solve_line(R"({"event":"error","exit_code":1,"file":"/tmp/x/model.inp","kind":)"
                       R"("input","line":42,"message":"*CLOAD names node 999, which does not )"
                       R"(exist","styk_progress":1})");
  EXPECT_EQ(l.kind, SolveLine::Kind::Error);
  EXPECT_EQ(l.where.file, "/tmp/x/model.inp");
  EXPECT_EQ(l.where.line, 42);
  EXPECT_EQ(l.exit_code, 1);
  EXPECT_EQ(l.text, "*CLOAD names node 999, which does not exist");
  l = parse_solve_line(R"({"event":"error","exit_code":2,"kind":"not_converged","message":)"
                       R"("CG stopped","styk_progress":1})");
  EXPECT_EQ(l.kind, SolveLine::Kind::Error);
  EXPECT_EQ(l.where.file, "");
  EXPECT_EQ(l.exit_code, 2);
  l = parse_solve_line(
      R"({"dofs":4320,"event":"done","results":"/a/b.styk.h5","styk_progress":1})");
  EXPECT_EQ(l.kind, SolveLine::Kind::Done);
  EXPECT_EQ(l.results, "/a/b.styk.h5");
}

// Text, broken JSON, another version, an unknown event: Other, the line kept as its text.
TEST(SolveProtocol, LinesThatAreNoEventStayText) {
  for (const char* line :
       {"styk: assemble ...", "Segmentation fault", R"({"event":"begin","phase")",
        R"({"event":"begin","phase":"read","styk_progress":2})",
        R"({"event":"begin","phase":"read"})", R"({"event":"party","styk_progress":1})", "[1,2]"}) {
    const SolveLine l = parse_solve_line(line);
    EXPECT_EQ(l.kind, SolveLine::Kind::Other) << line;
    EXPECT_EQ(l.text, line);
  }
}

TEST(SolveProtocol, ProgressRisesThroughThePhases) {
  int last = -1;
  for (const char* phase : {"read", "check", "pattern", "assemble", "order", "factorise", "solve",
                            "recover", "write"}) {
    EXPECT_GT(phase_progress(phase), last) << phase;
    last = phase_progress(phase);
  }
  EXPECT_LT(last, 100);
  EXPECT_EQ(phase_progress("unknown"), -1);
  const std::vector<std::string> args = solve_arguments("m.inp", "/tmp/out");
  EXPECT_EQ(args,
            (std::vector<std::string>{"solve", "m.inp", "-o", "/tmp/out", "--progress", "json"}));
}

// The solver's side: `styk solve --progress json` on a deck with an error and on the sample
// cantilever writes only protocol lines on stderr; the first begins "read", the error names the
// deck line and exit code 1, the solve ends with the done event naming the results file.
TEST(SolveProtocol, TheSolverSpeaksTheProtocol) {
  const std::string dir = testing::scratch_dir("solve_protocol");
  const std::string styk = testing::styk_executable();
  { std::ofstream(dir + "/bad.inp") << "*NODE\n1, 0, 0, 0\n*CLOAD\n9, 1, 1.\n"; }
  const testing::CommandResult bad =
      testing::run_command(styk + " solve bad.inp --progress json", dir);
  EXPECT_EQ(bad.exit_code, 1);
  std::vector<SolveLine> lines;
  std::istringstream in(bad.err);
  for (std::string line; std::getline(in, line);) lines.push_back(parse_solve_line(line));
  ASSERT_EQ(lines.size(), 2u) << bad.err;
  EXPECT_EQ(lines[0].kind, SolveLine::Kind::PhaseBegin);
  EXPECT_EQ(lines[0].phase, "read");
  EXPECT_EQ(lines[1].kind, SolveLine::Kind::Error);
  EXPECT_EQ(lines[1].where.file, "bad.inp");
  EXPECT_EQ(lines[1].where.line, 3);
  EXPECT_EQ(lines[1].exit_code, 1);

  const std::string sample = std::string(STYK_SOURCE_DIR) + "/samples/cantilever-c3d20.inp";
  const testing::CommandResult good =
      testing::run_command(styk + " solve '" + sample + "' -o '" + dir + "' --progress json", dir);
  ASSERT_EQ(good.exit_code, 0) << good.err;
  std::istringstream out(good.err);
  SolveLine last;
  int phases = 0;
  for (std::string line; std::getline(out, line);) {
    last = parse_solve_line(line);
    EXPECT_NE(last.kind, SolveLine::Kind::Other) << line;
    phases += last.kind == SolveLine::Kind::PhaseBegin;
  }
  EXPECT_GE(phases, 8);
  EXPECT_EQ(last.kind, SolveLine::Kind::Done);
  EXPECT_EQ(last.results, dir + "/cantilever-c3d20.styk.h5");
}

}  // namespace
}  // namespace styk::gui
