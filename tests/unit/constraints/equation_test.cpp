// *EQUATION (contact issue, constraints part): exact elimination of linear multi-point
// constraints. Two C3D8 grids meeting at x = 2 with duplicated nodes, tied by equations
// (directly, or through a chain of equations whose terms are themselves eliminated), must give
// the displacements of the same mesh with merged nodes to 1e-10 relative; the tie forces are
// equal and opposite. Errors: an eliminated dof that is also prescribed, cyclic equations, the
// iterative solver.
#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "constraint_test_support.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kYoung = 1000.0;
constexpr double kPoisson = 0.3;

// Clamped at x = 0, loaded at x = 4 by (0.3, -1, 0.5) shared by the tip nodes.
void clamp_and_load(Model& model) {
  for (int n : test::nodes_at(model, 0, 0.0))
    for (int d = 1; d <= 3; ++d) model.boundaries.push_back({n, d, 0.0, {}});
  const std::vector<int> tip = test::nodes_at(model, 0, 4.0);
  const double force[3] = {0.3, -1.0, 0.5};
  for (int n : tip)
    for (int d = 0; d < 3; ++d)
      model.steps[0].cloads.push_back({n, d + 1, force[d] / tip.size(), {}});
}

Model merged_model() {
  Model model = test::grid_model_shell(kYoung, kPoisson);
  test::add_c3d8_grid(model, 0.0, {4, 2, 2}, 1.0);
  clamp_and_load(model);
  return model;
}

// The interface node pairs (grid A node, grid B node) of the tied model, sorted by position.
std::vector<std::pair<int, int>> interface_pairs(const Model& model, int first_b) {
  std::vector<std::pair<int, int>> pairs;
  for (int a : test::nodes_at(model, 0, 2.0)) {
    if (a >= first_b) continue;
    for (int b : test::nodes_at(model, 0, 2.0))
      if (b >= first_b && model.coords[a] == model.coords[b]) pairs.emplace_back(a, b);
  }
  return pairs;
}

// Grids [0, 2] and [2, 4] with their own nodes at x = 2, tied dof by dof. `chain`: only the
// first pair is tied directly; pair k ties u_bk - u_b(k-1) = u_ak - u_a(k-1), whose second term
// is eliminated by the previous equation (a chain as long as the interface).
Model tied_model(bool chain) {
  Model model = test::grid_model_shell(kYoung, kPoisson);
  test::add_c3d8_grid(model, 0.0, {2, 2, 2}, 1.0);
  const int first_b = model.node_count();
  test::add_c3d8_grid(model, 2.0, {2, 2, 2}, 1.0);
  const std::vector<std::pair<int, int>> pairs = interface_pairs(model, first_b);
  EXPECT_EQ(pairs.size(), 9u);
  for (std::size_t k = 0; k < pairs.size(); ++k)
    for (int d = 1; d <= 3; ++d) {
      Equation equation;
      equation.where = {"tied.inp", static_cast<int>(100 + 3 * k + d)};
      equation.terms.push_back({pairs[k].second, d, 1.0});
      if (chain && k > 0) {
        equation.terms.push_back({pairs[k - 1].second, d, -1.0});
        equation.terms.push_back({pairs[k].first, d, -1.0});
        equation.terms.push_back({pairs[k - 1].first, d, 1.0});
      } else {
        equation.terms.push_back({pairs[k].first, d, -1.0});
      }
      model.equations.push_back(equation);
    }
  clamp_and_load(model);
  return model;
}

void expect_same_as_merged(const Model& tied, const Results& tied_results) {
  const Model merged = merged_model();
  const Results merged_results = test::solve_with_plugins(merged);
  const IncrementResult& a = merged_results.increments.at(0);
  const IncrementResult& b = tied_results.increments.at(0);
  double largest = 0.0;
  for (const Vec3& u : a.U)
    for (double c : u) largest = std::max(largest, std::abs(c));
  ASSERT_GT(largest, 0.0);
  int compared = 0;
  for (int n = 0; n < merged.node_count(); ++n)
    for (int m = 0; m < tied.node_count(); ++m) {
      if (tied.coords[m] != merged.coords[n]) continue;
      ++compared;
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(b.U[m][d], a.U[n][d], 1e-10 * largest) << m;
    }
  EXPECT_EQ(compared, tied.node_count());
  // The support reactions agree too.
  for (int d = 0; d < 3; ++d) {
    double sum_a = 0.0, sum_b = 0.0;
    for (int n : test::nodes_at(merged, 0, 0.0)) sum_a += a.RF[n][d];
    for (int n : test::nodes_at(tied, 0, 0.0)) sum_b += b.RF[n][d];
    EXPECT_NEAR(sum_b, sum_a, 1e-10);
  }
}

TEST(Equation, TiedGridsMatchMergedMesh) {
  const Model tied = tied_model(false);
  const Results results = test::solve_with_plugins(tied);
  expect_same_as_merged(tied, results);
  // The constraint forces on the two nodes of a pair are equal and opposite (the interface
  // carries the load: the x forces over the interface add up to the applied 0.3).
  const IncrementResult& r = results.increments.at(0);
  double carried = 0.0;
  for (const auto& [a, b] : interface_pairs(tied, tied.node_count() / 2)) {
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(r.RF[a][d] + r.RF[b][d], 0.0, 1e-10);
    carried += r.RF[b][0];
  }
  EXPECT_NEAR(std::abs(carried), 0.3, 1e-10);
}

TEST(Equation, ChainedEquationsResolveToTheTie) {
  const Model tied = tied_model(true);
  expect_same_as_merged(tied, test::solve_with_plugins(tied));
}

TEST(Equation, PrescribedDependentDofIsAnErrorAtTheEquation) {
  Model model = tied_model(false);
  const Equation& equation = model.equations[4];
  model.steps[0].boundaries.push_back({equation.terms[0].node, equation.terms[0].dof, 0.0, {}});
  try {
    test::solve_with_plugins(model);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, equation.where.line);
    EXPECT_NE(error.message().find("also prescribed"), std::string::npos) << error.message();
  }
}

TEST(Equation, CyclicEquationsAreAnError) {
  Model model = tied_model(false);
  // u_a = u_b for the first pair's x: its a is now eliminated by b and b by a.
  Equation back = model.equations[0];
  std::swap(back.terms[0], back.terms[1]);
  back.where = {"tied.inp", 77};
  model.equations.push_back(back);
  try {
    test::solve_with_plugins(model);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_TRUE(error.where().line == 77 || error.where().line == model.equations[0].where.line);
    EXPECT_NE(error.message().find("cycle"), std::string::npos) << error.message();
  }
}

TEST(Equation, IterativeSolverIsRefusedByName) {
  SolveOptions options;
  options.force = LinearSolverKind::Iterative;
  try {
    test::solve_with_plugins(tied_model(false), options);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("*EQUATION"), std::string::npos) << error.message();
    EXPECT_NE(error.message().find("--solver cholmod"), std::string::npos) << error.message();
  }
}

// The same checks from a deck: the reader's line numbers reach the messages.
TEST(Equation, DeckErrorsCarryTheEquationLine) {
  const std::string head =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n6, 1, 0, 1\n"
      "7, 1, 1, 1\n8, 0, 1, 1\n*ELEMENT, TYPE=C3D8, ELSET=EALL\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"
      "*BOUNDARY\n1, 1, 3\n4, 1, 3\n5, 1, 3\n8, 1, 3\n";  // 20 lines
  const std::string step = "*STEP\n*STATIC\n*BOUNDARY\n2, 1, 1, 0.01\n*END STEP\n";
  ElementRegistry registry = test::builtin_registry();
  {
    const Model model =
        test::parse_deck("eq_prescribed.inp", head + "*EQUATION\n2\n2, 1, 1., 3, 1, -1.\n" + step);
    try {
      run_static_analysis(model, registry, {}, nullptr, nullptr);
      FAIL() << "expected an InputError";
    } catch (const InputError& error) {
      EXPECT_EQ(error.where().line, model.equations[0].where.line);
      EXPECT_GE(error.where().line, 21);
      EXPECT_LE(error.where().line, 23);
    }
  }
  {
    const Model model = test::parse_deck(
        "eq_cycle.inp", head + "*EQUATION\n2\n3, 2, 1., 6, 2, -1.\n2\n6, 2, 1., 3, 2, -2.\n" +
                            "*STEP\n*STATIC\n*CLOAD\n7, 2, 1.\n*END STEP\n");
    try {
      run_static_analysis(model, registry, {}, nullptr, nullptr);
      FAIL() << "expected an InputError";
    } catch (const InputError& error) {
      EXPECT_TRUE(error.where().line == model.equations[0].where.line ||
                  error.where().line == model.equations[1].where.line);
      EXPECT_GE(error.where().line, 21);
      EXPECT_NE(error.message().find("cycle"), std::string::npos) << error.message();
    }
  }
}

}  // namespace
}  // namespace styk
