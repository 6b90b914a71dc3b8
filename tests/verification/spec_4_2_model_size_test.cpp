// SPEC §4.2, "model no more than a scene needs" (docs/model-size.md): the shrink fit's heating is
// axisymmetric, so a quarter (model A, planes x = 0 and y = 0) and a thin sector (model C: the
// plane y = 0 and an oblique plane held tangentially through a cylindrical *TRANSFORM) give the
// same answer; the full joint (model B) is in the study. On a coarse mesh (4 elements around a
// quarter, the sector 2 of them = 45 deg, C3D21 layer) the shaft-end elongation and diametral
// growth of A and C agree to 1e-3 relative (measured 8.6e-5 and 3.4e-5) and the contact pressure
// at mid-sleeve to 2e-3 (measured 9.5e-4): the sector's core is a kite of 45 deg where the
// quarter's is a square, so the meshes differ near the axis (on this mesh the quarter matches the
// full joint to 2e-6). The elongation lies within 2 % of the thesis' Tab 4.1
// value 0.1268 (measured 1.6 % below; Abaqus is a peer, not the truth).
#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/solver/analysis.hpp"
#include "styk/studies/study/problems.hpp"
#include "styk/studies/study/run.hpp"

namespace styk::studies {
namespace {

std::map<std::string, double> fit_answer(const ElementRegistry& registry,
                                         const std::string& model) {
  ProblemSetup setup = find_problem("shrink-fit-full")->setup(0);
  setup.args = {{"model", model},       {"load-case", "fit"}, {"around", "4"},
                {"sector-around", "2"}, {"shaft-rings", "2"}, {"sleeve-rings", "2"},
                {"fit-rows", "4"},      {"end-rows", "2"}};
  const Model m = build_problem_model(setup, "C3D21", registry);
  const Results results = run_static_analysis(m, registry, SolveOptions{}, nullptr, nullptr);
  return setup.quantities(m, results);
}

TEST(Spec42ModelSize, QuarterAndSectorGiveTheSameAnswer) {
  const auto full = test::registry_with_plugins();
  const auto quarter = fit_answer(full->registry, "A");
  const auto sector = fit_answer(full->registry, "C");
  EXPECT_NEAR(quarter.at("elongation"), 0.1268, 0.02 * 0.1268);
  for (const char* q : {"elongation", "diametral_growth"})
    EXPECT_NEAR(sector.at(q), quarter.at(q), 1e-3 * std::abs(quarter.at(q))) << q;
  EXPECT_NEAR(sector.at("pressure_mid"), quarter.at("pressure_mid"),
              2e-3 * quarter.at("pressure_mid"));
}

}  // namespace
}  // namespace styk::studies
