// The linear coarse space of the serial iterative solver's p-multigrid (solver/src/
// linear_coarse_space.hpp, docs/solver.md §4): it must interpolate every linear field exactly from
// the corner nodes (the coarse level then represents the rigid motions and the constant strains),
// exist only where there is something to coarsen, and the p-multigrid solve must agree with the
// direct solver.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cantilever_model.hpp"
#include "linear_coarse_space.hpp"
#include "prepared_model.hpp"
#include "solver_test_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/split.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

// A linear field u(x) = a + B x, component c.
double linear_field(const Vec3& x, int c) {
  const double a[3] = {0.3, -1.2, 0.7};
  const double B[3][3] = {{1.0, 0.4, -0.3}, {0.25, -2.0, 0.5}, {-0.6, 0.1, 1.5}};
  return a[c] + B[c][0] * x[0] + B[c][1] * x[1] + B[c][2] * x[2];
}

// max |P u_corners - u| over every node and component, relative to max |u|.
double interpolation_error(const Model& model, const ElementRegistry& registry) {
  const solver_detail::PreparedModel prepared = solver_detail::prepare_model(model, registry);
  const auto space = solver_detail::linear_coarse_space(model, prepared);
  if (!space) {
    ADD_FAILURE() << "no coarse space";
    return 1.0;
  }
  double worst = 0.0, scale = 0.0;
  for (int a = 0; a < prepared.active_nodes(); ++a)
    for (int c = 0; c < 3; ++c) {
      double interpolated = 0.0;
      for (int p = space->ptr[a]; p < space->ptr[a + 1]; ++p) {
        const int corner = prepared.node_of_active[space->corner_node[space->node[p]]];
        interpolated += space->weight[p] * linear_field(model.coords[corner], c);
      }
      const double exact = linear_field(model.coords[prepared.node_of_active[a]], c);
      worst = std::max(worst, std::abs(interpolated - exact));
      scale = std::max(scale, std::abs(exact));
    }
  return worst / scale;
}

TEST(LinearCoarseSpace, InterpolatesLinearFieldsExactlyOnQuadraticBricks) {
  const ElementRegistry registry = test::builtin_registry();
  for (const char* type : {"C3D20", "C3D20R", "C3D27"}) {
    const Model model = test::block(registry, type, 3, 2, 2, 3.0, 1.0, 1.5);
    EXPECT_LT(interpolation_error(model, registry), 1e-13) << type;
    const solver_detail::PreparedModel prepared = solver_detail::prepare_model(model, registry);
    // 4 x 3 x 3 corner nodes.
    EXPECT_EQ(solver_detail::linear_coarse_space(model, prepared)->coarse_nodes, 36) << type;
  }
}

TEST(LinearCoarseSpace, InterpolatesLinearFieldsExactlyOnQuadraticTetrahedra) {
  const ElementRegistry registry = test::builtin_registry();
  mesher::Mesh mesh;
  mesher::mesh_block(mesh,
                     [](const Vec3& xi) {
                       return Vec3{2.0 * (xi[0] + 1), 0.5 * (xi[1] + 1), xi[2] + 1};
                     },
                     {"C3D20", {3, 2, 2}, {1, 1, 1}, "EALL"});
  mesher::split_to_tetrahedra(mesh, registry, "C3D10");
  const Model model = mesher::finish_model(mesh, "tetrahedra", 210000.0, 0.3);
  EXPECT_LT(interpolation_error(model, registry), 1e-13);
}

TEST(LinearCoarseSpace, NoneWhereThereIsNothingToCoarsen) {
  const ElementRegistry registry = test::builtin_registry();
  const Model model = test::block(registry, "C3D8", 3, 2, 2, 3.0, 1.0, 1.5);
  const solver_detail::PreparedModel prepared = solver_detail::prepare_model(model, registry);
  EXPECT_FALSE(solver_detail::linear_coarse_space(model, prepared).has_value());
}

TEST(LinearCoarseSpace, PMultigridAgreesWithTheDirectSolver) {
  // C3D20 cantilever 24 x 4 x 4 (clamped, unit tip shear): the iterative solve (CG with the
  // p-multigrid: Chebyshev-Jacobi on C3D20, GAMG on the linear level) against CHOLMOD.
  const ElementRegistry registry = test::builtin_registry();
  testkit::CantileverSpec spec;
  spec.nx = 24;
  spec.ny = 4;
  spec.nz = 4;
  const testkit::Cantilever cantilever = testkit::make_cantilever(spec, registry);
  SolveOptions direct;
  direct.force = LinearSolverKind::Cholmod;
  const Results a = run_static_analysis(cantilever.model, registry, direct, nullptr, nullptr);
  SolveOptions iterative;
  iterative.force = LinearSolverKind::Iterative;
  AnalysisReport report;
  const Results b = run_static_analysis(cantilever.model, registry, iterative, nullptr, &report);
  EXPECT_NE(report.linear_solver.find("p-multigrid"), std::string::npos) << report.linear_solver;
  // Measured 35 iterations to the default tolerance (bench/README.md compares with plain GAMG
  // on large models); a bound against a silent loss of the coarse level's effect.
  EXPECT_LE(report.iterations, 40);
  const IncrementResult& ra = a.increments[0];
  const IncrementResult& rb = b.increments[0];
  const double scale = test::max_abs_displacement(ra);
  double worst = 0.0;
  for (std::size_t n = 0; n < ra.U.size(); ++n)
    for (int d = 0; d < 3; ++d) worst = std::max(worst, std::abs(ra.U[n][d] - rb.U[n][d]));
  EXPECT_LT(worst, 1e-8 * scale);
}

TEST(LinearCoarseSpace, StepsReuseTheLevelAndScaleWithTheLoad) {
  // Two steps of one C3D20 cantilever with the iterative solver, the second with twice the tip
  // load (OP=MOD replaces the values). The solver prepared for step 1 (its p-multigrid level
  // included) is kept for step 2, whose stiffness and supports are the same; CG from a zero start
  // on twice the load must give twice the answer (measured: exactly).
  const ElementRegistry registry = test::builtin_registry();
  testkit::CantileverSpec spec;
  spec.nx = 12;
  spec.ny = 2;
  spec.nz = 2;
  Model model = testkit::make_cantilever(spec, registry).model;
  ASSERT_EQ(model.steps.size(), 1u);
  Step doubled = model.steps[0];
  for (auto& load : doubled.cloads) load.value *= 2.0;
  model.steps.push_back(doubled);
  SolveOptions iterative;
  iterative.force = LinearSolverKind::Iterative;
  AnalysisReport report;
  const Results results = run_static_analysis(model, registry, iterative, nullptr, &report);
  ASSERT_EQ(results.increments.size(), 2u);
  EXPECT_NE(report.linear_solver.find("p-multigrid"), std::string::npos);
  const IncrementResult& one = results.increments[0];
  const IncrementResult& two = results.increments[1];
  const double scale = test::max_abs_displacement(two);
  ASSERT_GT(scale, 0.0);
  for (std::size_t n = 0; n < one.U.size(); ++n)
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(two.U[n][d], 2.0 * one.U[n][d], 1e-12 * scale);
}

}  // namespace
}  // namespace styk
