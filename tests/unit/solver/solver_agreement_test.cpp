// The direct (CHOLMOD) and iterative (CG + GAMG) solvers must agree: same model, displacements
// within 1e-6 relative (the iterative tolerance is 1e-9 on the residual). Also checks prescribed
// non-zero displacements through both elimination schemes against the exact uniaxial solution.
#include <gtest/gtest.h>

#include "solver_test_support.hpp"

namespace styk {
namespace {

TEST(SolverAgreement, CholmodAndGamgAgreeOnTheCantilever) {
  // PERFORMANCE.md cantilever (C3D20, 10 x 1 x 1, clamped, unit tip shear), 20 x 4 x 4 elements:
  // 1865 nodes, 5595 dofs of which 195 on the clamped face.
  const ElementRegistry registry = test::builtin_registry();
  testkit::CantileverSpec spec;
  spec.nx = 20;
  spec.ny = 4;
  spec.nz = 4;
  const testkit::Cantilever cantilever = testkit::make_cantilever(spec, registry);

  SolveOptions direct;
  direct.force = LinearSolverKind::Cholmod;
  AnalysisReport direct_report;
  const Results a =
      run_static_analysis(cantilever.model, registry, direct, nullptr, &direct_report);
  SolveOptions iterative;
  iterative.force = LinearSolverKind::Iterative;
  AnalysisReport iterative_report;
  const Results b =
      run_static_analysis(cantilever.model, registry, iterative, nullptr, &iterative_report);

  EXPECT_EQ(direct_report.dofs, 5400);
  EXPECT_NE(direct_report.linear_solver.find("CHOLMOD"), std::string::npos);
  EXPECT_NE(iterative_report.linear_solver.find("GAMG"), std::string::npos);
  EXPECT_GT(iterative_report.iterations, 0);

  const IncrementResult& ra = a.increments[0];
  const IncrementResult& rb = b.increments[0];
  const double scale = test::max_abs_displacement(ra);
  for (std::size_t n = 0; n < ra.U.size(); ++n)
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(ra.U[n][d], rb.U[n][d], 1e-6 * scale);
  // Reactions: the clamped face carries the unit tip shear in both solutions.
  double rz_a = 0.0, rz_b = 0.0;
  for (std::size_t n = 0; n < ra.RF.size(); ++n) {
    rz_a += ra.RF[n][2];
    rz_b += rb.RF[n][2];
  }
  EXPECT_NEAR(rz_a, -1.0, 1e-10);
  EXPECT_NEAR(rz_b, -1.0, 1e-6);
}

TEST(SolverChoice, DeckSolverIsUsedUnlessTheOptionsForceOne) {
  // *STATIC, SOLVER=ITERATIVE selects CG + GAMG even for a tiny model; SolveOptions::force wins.
  const ElementRegistry registry = test::builtin_registry();
  Model model = test::block(registry, "C3D20", 2, 1, 1, 2.0, 1.0, 1.0);
  test::add_symmetry_supports(model);
  Step step = test::static_step();
  step.procedure.solver = LinearSolverKind::Iterative;
  for (int n : test::nodes_at(model, 0, 2.0)) step.boundaries.push_back({n, 1, 0.01, {}});
  model.steps.push_back(step);

  AnalysisReport deck;
  run_static_analysis(model, registry, SolveOptions{}, nullptr, &deck);
  EXPECT_NE(deck.linear_solver.find("GAMG"), std::string::npos) << deck.linear_solver;
  SolveOptions forced;
  forced.force = LinearSolverKind::Cholmod;
  AnalysisReport overridden;
  run_static_analysis(model, registry, forced, nullptr, &overridden);
  EXPECT_NE(overridden.linear_solver.find("CHOLMOD"), std::string::npos)
      << overridden.linear_solver;
}

class PrescribedDisplacement : public testing::TestWithParam<LinearSolverKind> {};

TEST_P(PrescribedDisplacement, StretchesTheBarUniformly) {
  // 4 x 2 x 2 C3D20 bar [0,4] x [0,1] x [0,1], symmetry supports, u_x = d on x = 4. Exact:
  // u_x = d x / L, u_y = -nu d y / L, u_z = -nu d z / L, end reaction E A d / L. Tolerance
  // 1e-10 relative for CHOLMOD (round-off), 1e-7 for CG stopped at a 1e-12 relative residual.
  const double d = 0.004, L = 4.0, E = 210000.0, nu = 0.3;
  const ElementRegistry registry = test::builtin_registry();
  Model model = test::block(registry, "C3D20", 4, 2, 2, L, 1.0, 1.0);
  test::add_symmetry_supports(model);
  Step stretch = test::static_step();
  for (int n : test::nodes_at(model, 0, L)) stretch.boundaries.push_back({n, 1, d, {}});
  model.steps.push_back(stretch);

  SolveOptions options;
  options.force = GetParam();
  options.iterative_tolerance = 1e-12;
  const double tolerance = GetParam() == LinearSolverKind::Cholmod ? 1e-10 : 1e-7;
  const Results results = run_static_analysis(model, registry, options, nullptr, nullptr);
  const IncrementResult& r = results.increments[0];
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    EXPECT_NEAR(r.U[n][0], d * x[0] / L, tolerance * d);
    EXPECT_NEAR(r.U[n][1], -nu * d * x[1] / L, tolerance * d);
    EXPECT_NEAR(r.U[n][2], -nu * d * x[2] / L, tolerance * d);
  }
  const double force = E * 1.0 * d / L;
  double end = 0.0, start = 0.0;
  for (int n : test::nodes_at(model, 0, L)) end += r.RF[n][0];
  for (int n : test::nodes_at(model, 0, 0.0)) start += r.RF[n][0];
  EXPECT_NEAR(end, force, tolerance * force);
  EXPECT_NEAR(start, -force, tolerance * force);
}

INSTANTIATE_TEST_SUITE_P(Solver, PrescribedDisplacement,
                         testing::Values(LinearSolverKind::Cholmod, LinearSolverKind::Iterative),
                         [](const testing::TestParamInfo<LinearSolverKind>& param) {
                           return param.param == LinearSolverKind::Cholmod ? std::string("Cholmod")
                                                                           : std::string("Gamg");
                         });

}  // namespace
}  // namespace styk
