// The sparse contact solve (docs/contact.md, "Sparse contact solve": each Newton step one sparse
// LU of K with the closed contact rows, no dense compliance) against the dense path on the SPEC
// contact models: the converged answer of the active-set iteration is unique, so both paths must
// give the same statuses, and tractions and displacements equal to round-off. Asserted within
// 1e-8 of the largest value (measured: 5e-13 on the cantilevers, 1.4e-11 on the shrink fit).
#include <string>

#include <gtest/gtest.h>

#include "contact_path_agreement.hpp"
#include "contact_spec_models.hpp"
#include "spec_4_2_shrink_fit_model.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

constexpr double kAgreement = 1e-8;

struct Solved {
  Results results;
  AnalysisReport report;
};

Solved solve(const Model& model, ContactSolveKind kind, double memory_limit_gb = 0.0) {
  const auto registry = test::registry_with_plugins();
  SolveOptions options;
  options.contact_solve = kind;
  options.memory_limit_gb = memory_limit_gb;
  Solved out;
  out.results = run_static_analysis(model, registry->registry, options, nullptr, &out.report);
  return out;
}

bool sparse(const AnalysisReport& report) {
  return report.linear_solver.find("sparse contact solve") != std::string::npos;
}

void expect_paths_agree(const Model& model) {
  const Solved dense = solve(model, ContactSolveKind::Dense);
  const Solved sparse_solve = solve(model, ContactSolveKind::Sparse);
  EXPECT_FALSE(sparse(dense.report)) << dense.report.linear_solver;
  EXPECT_TRUE(sparse(sparse_solve.report)) << sparse_solve.report.linear_solver;
  test::expect_same_contact_answer(dense.results, sparse_solve.results, kAgreement);
}

// SPEC §3.2.3: the two cantilevers with mu = 0.2 (Zhong 1993): every closed node slips.
TEST(SparseContactSolve, CantileversGiveTheDenseAnswer) {
  expect_paths_agree(test::two_cantilevers_model(test::coulomb(0.2)));
}

// SPEC §3.2.4: the punch on the half-space, mu = 0.04: the punch is held only by contact (its
// rigid motions are unknowns of every Newton step beside the multipliers) and its edge nodes on
// the symmetry planes have dependent tangential rows.
TEST(SparseContactSolve, PunchHeldOnlyByContactGivesTheDenseAnswer) {
  expect_paths_agree(test::punch_model(test::coulomb(0.04)));
}

// SPEC §4.2 model A, coarse: thermal interference, then an axial push, friction 0.2, symmetry
// planes through the interface, the sleeve held axially by friction alone.
TEST(SparseContactSolve, ShrinkFitWithAPushGivesTheDenseAnswer) {
  test::ShrinkFitMesh mesh;
  mesh.core = 2;
  mesh.radial = 1;
  mesh.fit = 4;
  mesh.ends = 2;
  mesh.sleeve = 1;
  mesh.push = 52.5;
  expect_paths_agree(test::shrink_fit_thermal_model(mesh));
}

// The automatic choice holds the dense compliance while it takes at most a quarter of the memory
// limit: the cantilevers' 243 constraints need 8 (3 x 243)^2 = 4.25 MB.
TEST(SparseContactSolve, AutomaticChoiceFollowsTheMemoryLimit) {
  const Model model = test::two_cantilevers_model(test::coulomb(0.2));
  EXPECT_FALSE(sparse(solve(model, ContactSolveKind::Automatic, 0.018).report));  // 4.5 MB
  EXPECT_TRUE(sparse(solve(model, ContactSolveKind::Automatic, 0.016).report));   // 4.0 MB
}

}  // namespace
}  // namespace styk
