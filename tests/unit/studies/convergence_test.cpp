// What the atlas reads from runs: log-log slopes, the Pareto front, the cheapest run below a
// target, and the charts built from them (series per family, slopes in the legend, the front).
#include <gtest/gtest.h>

#include <cmath>

#include "styk/studies/results/atlas_charts.hpp"
#include "styk/studies/results/convergence.hpp"

namespace styk::studies {
namespace {

// A series with error = c h^p exactly, DOF ~ h^-2, time ~ DOF.
std::vector<RunRecord> series(const std::string& family, double c, double p, int levels) {
  std::vector<RunRecord> out;
  for (int k = 0; k < levels; ++k) {
    RunRecord r;
    r.study = "accuracy";
    r.problem = "lame";
    r.family = family;
    r.level = k;
    r.h = 1.0 / (1 << k);
    r.dof = 100LL << (2 * k);
    r.time_s = 1e-4 * r.dof;
    r.error[static_cast<int>(Measure::Energy)] = c * std::pow(r.h, p);
    out.push_back(r);
  }
  return out;
}

TEST(Convergence, SlopesOfExactPowerLaws) {
  const auto fit = fit_log_log({1, 10, 100}, {2, 0.2, 0.02});
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->slope, -1.0, 1e-12);
  EXPECT_NEAR(fit->intercept, std::log10(2.0), 1e-12);
  EXPECT_FALSE(fit_log_log({1}, {1}));
  EXPECT_FALSE(fit_log_log({1, 1}, {1, 2}));  // no spread
  std::vector<RunRecord> runs = series("C3D20", 0.5, 2.0, 5);
  runs[0].error[static_cast<int>(Measure::Energy)] = 0.9;  // pre-asymptotic: outside the last 3
  const auto s = series_of(runs, "lame", "C3D20", Measure::Energy);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_NEAR(convergence_fit(s, Measure::Energy, Cost::Size)->slope, 2.0, 1e-12);
  EXPECT_NEAR(convergence_fit(s, Measure::Energy, Cost::Dof)->slope, -1.0, 1e-12);
  EXPECT_GT(std::abs(convergence_fit(s, Measure::Energy, Cost::Size, 0)->slope - 2.0), 0.05);
}

TEST(Convergence, ParetoFrontAndCheapestRun) {
  std::vector<RunRecord> runs = series("C3D8", 1.0, 1.0, 4);         // errors 1, .5, .25, .125
  const std::vector<RunRecord> quad = series("C3D20", 0.2, 2.0, 3);  // .2, .05, .0125
  runs.insert(runs.end(), quad.begin(), quad.end());
  for (RunRecord& r : runs)
    if (r.family == "C3D20") r.time_s *= 3;  // slower per DOF
  std::vector<const RunRecord*> all;
  for (const RunRecord& r : runs) all.push_back(&r);
  const auto front = pareto_front(all, Measure::Energy, Cost::Time);
  // Times: C3D8 .01 .04 .16 .64; C3D20 .03 .12 .48. Front: C3D8 .01 (1), C3D20 .03 (.2),
  // C3D20 .12 (.05), C3D20 .48 (.0125); C3D8 .04 (.5) and .16 (.25) are beaten by C3D20 .03.
  ASSERT_EQ(front.size(), 4u);
  EXPECT_EQ(front[0]->family, "C3D8");
  EXPECT_EQ(front[1]->family, "C3D20");
  EXPECT_EQ(front[3]->level, 2);
  const RunRecord* best = cheapest_reaching(all, Measure::Energy, Cost::Time, 0.3);
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->family, "C3D20");
  EXPECT_EQ(best->level, 0);
  EXPECT_EQ(cheapest_reaching(all, Measure::Energy, Cost::Time, 1e-4), nullptr);
}

TEST(AtlasCharts, OneSeriesPerFamilyWithSlopeAndTheFront) {
  std::vector<RunRecord> runs = series("C3D8", 1.0, 1.0, 4);
  const std::vector<RunRecord> quad = series("C3D20", 0.2, 2.0, 3);
  runs.insert(runs.end(), quad.begin(), quad.end());
  const charts::Chart c =
      convergence_chart(runs, "lame", Measure::Energy, Cost::Dof, {"C3D8", "C3D20"});
  ASSERT_EQ(c.series.size(), 3u);
  EXPECT_EQ(c.series[0].name, "Pareto front");
  EXPECT_TRUE(c.series[0].highlight);
  EXPECT_EQ(c.series[1].name, "C3D8  slope -0.50");
  EXPECT_EQ(c.series[2].name, "C3D20  slope -1.00");
  EXPECT_EQ(c.series[2].colour, 1);
  EXPECT_TRUE(c.x.log && c.y.log);
  EXPECT_EQ(c.series[1].points.size(), 4u);
  EXPECT_NE(c.series[1].points[3].tip.find("C3D8, level 3: 6 400 DOF"), std::string::npos)
      << c.series[1].points[3].tip;
  const charts::Chart h =
      convergence_chart(runs, "lame", Measure::Energy, Cost::Size, {"C3D8", "C3D20"});
  EXPECT_EQ(h.series.size(), 2u);  // no front against h
  EXPECT_EQ(h.series[1].name, "C3D20  order 2.00");
}

}  // namespace
}  // namespace styk::studies
