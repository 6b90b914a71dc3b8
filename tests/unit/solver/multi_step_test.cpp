// Step accumulation (OP=MOD / OP=NEW) and factorisation reuse. Linear statics superpose exactly:
// step 2 = step 1 loads + an added load must equal the sum of the two separate solutions, to
// round-off (1e-10 relative).
#include <gtest/gtest.h>

#include <algorithm>

#include "solver_test_support.hpp"

namespace styk {
namespace {

// 3 x 1 x 1 bar of C3D8, length 3, clamped at x = 0.
Model clamped_bar(const ElementRegistry& registry) {
  Model model = test::block(registry, "C3D8", 3, 1, 1, 3.0, 1.0, 1.0);
  for (int n : test::nodes_at(model, 0, 0.0))
    for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, {}});
  return model;
}

void add_tip_load(const Model& model, Step& step, int dof, double total) {
  const std::vector<int> tip = test::nodes_at(model, 0, 3.0);
  for (int n : tip) step.cloads.push_back({n, dof, total / tip.size(), {}});
}

void expect_superposed(const IncrementResult& sum, const IncrementResult& a,
                       const IncrementResult& b) {
  const double scale = test::max_abs_displacement(sum);
  ASSERT_GT(scale, 0.0);
  for (std::size_t n = 0; n < sum.U.size(); ++n)
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(sum.U[n][d], a.U[n][d] + b.U[n][d], 1e-10 * scale);
      EXPECT_NEAR(sum.RF[n][d], a.RF[n][d] + b.RF[n][d], 1e-10 * 11.0);
    }
  for (std::size_t p = 0; p < sum.S.size(); ++p)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(sum.S[p][k], a.S[p][k] + b.S[p][k], 1e-9 * (1.0 + std::abs(sum.S[p][k])));
}

TEST(MultiStep, ModifiedLoadsSuperposeAndReuseTheFactor) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = clamped_bar(registry);
  Step axial = test::static_step(1.0);
  add_tip_load(model, axial, 1, 10.0);
  Step plus_shear = test::static_step(2.0);  // OP=MOD: keeps the axial load
  add_tip_load(model, plus_shear, 3, 1.0);
  Step shear_only = test::static_step(0.5);
  shear_only.cload_op_new = true;
  add_tip_load(model, shear_only, 3, 1.0);
  model.steps = {axial, plus_shear, shear_only};

  AnalysisReport report;
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, &report);
  ASSERT_EQ(results.increments.size(), 3u);
  const IncrementResult& r1 = results.increments[0];
  const IncrementResult& r2 = results.increments[1];
  const IncrementResult& r3 = results.increments[2];
  expect_superposed(r2, r1, r3);

  // Times: step time = the step's period, total time accumulated.
  EXPECT_EQ(r1.step, 1);
  EXPECT_EQ(r2.step, 2);
  EXPECT_DOUBLE_EQ(r2.step_time, 2.0);
  EXPECT_DOUBLE_EQ(r2.total_time, 3.0);
  EXPECT_DOUBLE_EQ(r3.total_time, 3.5);

  // The prescribed set never changes, so the matrix is factorised once.
  const auto factorisations =
      std::count_if(report.timings.begin(), report.timings.end(),
                    [](const PhaseTiming& t) { return t.phase == "factorise"; });
  EXPECT_EQ(factorisations, 1);

  // And the shear-only step equals a separate one-step analysis.
  Model separate = clamped_bar(registry);
  separate.steps = {shear_only};
  separate.steps[0].cload_op_new = false;
  const Results alone = run_static_analysis(separate, registry, SolveOptions{}, nullptr, nullptr);
  const double scale = test::max_abs_displacement(alone.increments[0]);
  for (std::size_t n = 0; n < r3.U.size(); ++n)
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(r3.U[n][d], alone.increments[0].U[n][d], 1e-12 * scale);
}

TEST(MultiStep, NewBoundaryConditionsRefactorise) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = clamped_bar(registry);
  Step pull = test::static_step();
  add_tip_load(model, pull, 1, 10.0);
  // Step 2 also fixes the tip in x (OP=MOD adds a boundary condition). A prescribed value is
  // absolute, so u_x(tip) = 0: the load now sits on supported dofs and goes straight into them.
  Step hold = test::static_step();
  for (int n : test::nodes_at(model, 0, 3.0)) hold.boundaries.push_back({n, 1, 0.0, {}});
  model.steps = {pull, hold};

  AnalysisReport report;
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, &report);
  ASSERT_EQ(results.increments.size(), 2u);
  const auto factorisations =
      std::count_if(report.timings.begin(), report.timings.end(),
                    [](const PhaseTiming& t) { return t.phase == "factorise"; });
  EXPECT_EQ(factorisations, 2);
  // With both ends held in x the load goes entirely into the supports: the x reactions sum to
  // minus the applied 10 (equilibrium, round-off tolerance), and every u_x vanishes.
  double rx = 0.0;
  for (const Vec3& rf : results.increments[1].RF) rx += rf[0];
  EXPECT_NEAR(rx, -10.0, 1e-10 * 10.0);
  for (const Vec3& u : results.increments[1].U) EXPECT_NEAR(u[0], 0.0, 1e-14);
}

}  // namespace
}  // namespace styk
