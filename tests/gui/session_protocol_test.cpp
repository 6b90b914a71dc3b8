// Reading `styk solve`'s output: the lines the GUI turns into progress, log and error messages.
#include <gtest/gtest.h>

#include "session/solve_protocol.hpp"

namespace styk::gui {
namespace {

TEST(SolveProtocol, PhasesInfoAndErrors) {
  SolveLine l = parse_solve_line("styk: assemble ...\n");
  EXPECT_EQ(l.kind, SolveLine::Kind::PhaseBegin);
  EXPECT_EQ(l.phase, "assemble");
  l = parse_solve_line("styk: factorise done in 0.011 s");
  EXPECT_EQ(l.kind, SolveLine::Kind::PhaseEnd);
  EXPECT_EQ(l.phase, "factorise");
  EXPECT_DOUBLE_EQ(l.seconds, 0.011);
  l = parse_solve_line("styk:   pattern: 1863 dofs, 205749 nonzeros");
  EXPECT_EQ(l.kind, SolveLine::Kind::Info);
  EXPECT_EQ(l.text, "pattern: 1863 dofs, 205749 nonzeros");
  l = parse_solve_line("styk:   warning: 8 elements of type C3D8R0 have 27 zero-energy modes");
  EXPECT_EQ(l.kind, SolveLine::Kind::Warning);
  EXPECT_EQ(l.text, "8 elements of type C3D8R0 have 27 zero-energy modes");
  l = parse_solve_line("/tmp/x/model.inp:42: *CLOAD names node 999, which does not exist");
  EXPECT_EQ(l.kind, SolveLine::Kind::Error);
  EXPECT_EQ(l.where.file, "/tmp/x/model.inp");
  EXPECT_EQ(l.where.line, 42);
  EXPECT_EQ(l.text, "*CLOAD names node 999, which does not exist");
  l = parse_solve_line("/tmp/x/model.inp: no *STEP in the deck");
  EXPECT_EQ(l.kind, SolveLine::Kind::Error);
  EXPECT_EQ(l.where.file, "/tmp/x/model.inp");
  EXPECT_EQ(l.where.line, 0);
  EXPECT_EQ(parse_solve_line("not converged: CG stopped").kind, SolveLine::Kind::Error);
  EXPECT_EQ(parse_solve_line("results: a.styk.h5").kind, SolveLine::Kind::Other);
}

TEST(SolveProtocol, ProgressRisesThroughThePhasesAndTheSummaryNamesTheResults) {
  int last = -1;
  for (const char* phase :
       {"read", "check", "pattern", "assemble", "order", "factorise", "solve", "recover", "write"}) {
    EXPECT_GT(phase_progress(phase), last) << phase;
    last = phase_progress(phase);
  }
  EXPECT_LT(last, 100);
  EXPECT_EQ(phase_progress("unknown"), -1);
  EXPECT_EQ(results_path_from_summary("results: /a/b.styk.h5\nreport:  /a/b.dat\n"),
            "/a/b.styk.h5");
  EXPECT_EQ(results_path_from_summary("nothing"), "");
  const std::vector<std::string> args = solve_arguments("m.inp", "/tmp/out");
  EXPECT_EQ(args, (std::vector<std::string>{"solve", "m.inp", "-o", "/tmp/out"}));
}

}  // namespace
}  // namespace styk::gui
