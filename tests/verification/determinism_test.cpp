// Determinism: the same deck gives the same answer bit for bit, whatever the number of worker
// threads (assembly colours and recovery run in parallel) and however often it is solved. Checked
// for a linear C3D20 model with the direct and the iterative solver, the same model heated
// non-uniformly (thermal load), a frictional contact model with the C3D21 plug-in, and a steady
// heat model with the C3D28 plug-in (the samples/ decks).
// Equality is exact (operator== on the doubles), not a tolerance.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hex_model_builder.hpp"
#include "styk/inp/reader.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

// Heats every node of the model to 20 + x (a gradient along the cantilever) with an expansion
// coefficient, so the step carries a thermal load assembled from every element.
void heat_along_x(Model& model) {
  for (Material& material : model.materials) material.expansion = 1.2e-5;
  for (int n = 0; n < model.node_count(); ++n)
    model.steps.front().temperatures.push_back({n, 20.0 + model.coords[n][0], {}});
}

Results solve(const std::string& sample, int threads, LinearSolverKind solver, bool heated) {
  const ElementRegistry& registry = test::shared_registry();
  Model model = read_inp(std::string(STYK_SOURCE_DIR) + "/samples/" + sample + ".inp", registry);
  if (heated) heat_along_x(model);
  SolveOptions options;
  options.threads = threads;
  options.force = solver;
  return run_static_analysis(model, registry, options, nullptr, nullptr);
}

// The first index where two vectors differ, or -1 when they are equal element for element.
template <class T>
long first_difference(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i])) return static_cast<long>(i);
  return -1;
}

void expect_identical(const Results& a, const Results& b, const std::string& what) {
  ASSERT_EQ(a.increments.size(), b.increments.size()) << what;
  for (std::size_t k = 0; k < a.increments.size(); ++k) {
    const IncrementResult& x = a.increments[k];
    const IncrementResult& y = b.increments[k];
    const std::string at = what + ", increment " + std::to_string(k + 1);
    EXPECT_EQ(first_difference(x.U, y.U), -1) << at << ": U";
    EXPECT_EQ(first_difference(x.RF, y.RF), -1) << at << ": RF";
    EXPECT_EQ(first_difference(x.S, y.S), -1) << at << ": S";
    EXPECT_EQ(first_difference(x.E, y.E), -1) << at << ": E";
    EXPECT_EQ(first_difference(x.S_nodal_I, y.S_nodal_I), -1) << at << ": S averaged at nodes";
    EXPECT_EQ(first_difference(x.scalar.value, y.scalar.value), -1) << at << ": NT";
    EXPECT_EQ(first_difference(x.scalar.reaction, y.scalar.reaction), -1) << at << ": RFL";
    EXPECT_EQ(first_difference(x.scalar.flux, y.scalar.flux), -1) << at << ": HFL";
    ASSERT_EQ(x.contact.size(), y.contact.size()) << at << ": contact nodes";
    for (std::size_t c = 0; c < x.contact.size(); ++c) {
      EXPECT_EQ(x.contact[c].status, y.contact[c].status) << at << ": contact node " << c;
      EXPECT_EQ(x.contact[c].pressure, y.contact[c].pressure) << at << ": contact node " << c;
      EXPECT_EQ(x.contact[c].shear, y.contact[c].shear) << at << ": contact node " << c;
      EXPECT_EQ(x.contact[c].slip, y.contact[c].slip) << at << ": contact node " << c;
    }
  }
}

struct Case {
  const char* sample;
  LinearSolverKind solver;
  const char* label;
  bool heated = false;
};

class Determinism : public ::testing::TestWithParam<Case> {};

TEST_P(Determinism, OneTwoAndFourThreadsAndARepeatGiveTheSameBits) {
  const Case& c = GetParam();
  const Results one = solve(c.sample, 1, c.solver, c.heated);
  ASSERT_FALSE(one.increments.empty());
  expect_identical(one, solve(c.sample, 1, c.solver, c.heated),
                   std::string(c.label) + ", repeated");
  for (int threads : {2, 4})
    expect_identical(one, solve(c.sample, threads, c.solver, c.heated),
                     std::string(c.label) + ", " + std::to_string(threads) + " threads");
}

INSTANTIATE_TEST_SUITE_P(
    Samples, Determinism,
    ::testing::Values(Case{"cantilever-c3d20", LinearSolverKind::Cholmod, "linear_direct"},
                      Case{"cantilever-c3d20", LinearSolverKind::Iterative, "linear_iterative"},
                      Case{"cantilever-c3d20", LinearSolverKind::Cholmod, "thermal_load", true},
                      Case{"spec-3.2.3-two-cantilevers-c3d21-mu0.2", LinearSolverKind::Automatic,
                           "contact_friction"},
                      Case{"spec-6.2-cylinder-wall-c3d28", LinearSolverKind::Automatic, "heat"}),
    [](const ::testing::TestParamInfo<Case>& param_info) {
      return std::string(param_info.param.label);
    });

}  // namespace
}  // namespace styk
