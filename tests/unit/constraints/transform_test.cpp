// *TRANSFORM (contact issue, constraints part): boundary conditions and concentrated loads of the
// set's nodes act in its local system; results stay global. A cantilever whose clamp and tip
// nodes carry a rectangular system rotated by 30 degrees about z, loaded along local 1, must equal
// the global model loaded along (cos 30, sin 30, 0) to 1e-10 (displacements and reactions); a
// prescribed local displacement moves the nodes exactly along the local axis. Errors: a missing
// node set, a cylindrical axis through a node, the iterative solver.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "constraint_test_support.hpp"

namespace styk {
namespace {

constexpr double kAngle = 30.0 * M_PI / 180.0;

Model cantilever() {
  Model model = test::grid_model_shell(1000.0, 0.3);
  test::add_c3d8_grid(model, 0.0, {4, 2, 2}, 1.0);
  for (const auto& [name, x] : {std::pair<std::string, double>{"ROOT", 0.0}, {"TIP", 4.0}}) {
    NodeSet& set = model.nsets[name];
    set.name = name;
    set.nodes = test::nodes_at(model, 0, x);
  }
  for (int n : model.nsets["ROOT"].nodes)
    for (int d = 1; d <= 3; ++d) model.boundaries.push_back({n, d, 0.0, {}});
  return model;
}

Transform rotated(const std::string& nset) {
  Transform transform;
  transform.nset = nset;
  transform.axes.system = CoordinateSystem::Rectangular;
  transform.axes.a = {std::cos(kAngle), std::sin(kAngle), 0.0};
  transform.axes.b = {-std::sin(kAngle), std::cos(kAngle), 0.0};
  transform.where = {"cantilever.inp", 12};
  return transform;
}

double largest(const IncrementResult& r) {
  double m = 0.0;
  for (const Vec3& u : r.U)
    for (double c : u) m = std::max(m, std::abs(c));
  return m;
}

TEST(Transform, LocalLoadsAndSupportsEqualTheRotatedGlobalOnes) {
  Model global = cantilever();
  const std::vector<int> tip = global.nsets["TIP"].nodes;
  for (int n : tip) {
    global.steps[0].cloads.push_back({n, 1, std::cos(kAngle) / tip.size(), {}});
    global.steps[0].cloads.push_back({n, 2, std::sin(kAngle) / tip.size(), {}});
  }
  Model local = cantilever();
  local.transforms = {rotated("ROOT"), rotated("TIP")};
  for (int n : tip) local.steps[0].cloads.push_back({n, 1, 1.0 / tip.size(), {}});

  const IncrementResult a = test::solve_with_plugins(global).increments.at(0);
  const IncrementResult b = test::solve_with_plugins(local).increments.at(0);
  const double scale = largest(a);
  ASSERT_GT(scale, 0.0);
  for (int n = 0; n < global.node_count(); ++n)
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(b.U[n][d], a.U[n][d], 1e-10 * scale) << n;
      EXPECT_NEAR(b.RF[n][d], a.RF[n][d], 1e-10) << n;  // reactions are reported globally
    }
}

TEST(Transform, PrescribedLocalDisplacementMovesAlongTheLocalAxis) {
  Model model = cantilever();
  model.transforms = {rotated("TIP")};
  for (int n : model.nsets["TIP"].nodes) model.steps[0].boundaries.push_back({n, 1, 0.01, {}});
  const IncrementResult r = test::solve_with_plugins(model).increments.at(0);
  const Vec3 e1 = rotated("TIP").axes.a;
  const Vec3 e2 = rotated("TIP").axes.b;
  for (int n : model.nsets["TIP"].nodes) {
    const Vec3& u = r.U[n];
    EXPECT_NEAR(u[0] * e1[0] + u[1] * e1[1], 0.01, 1e-13);
    // The reaction acts along the constrained local axis only.
    EXPECT_NEAR(r.RF[n][0] * e2[0] + r.RF[n][1] * e2[1], 0.0, 1e-10);
    EXPECT_NEAR(r.RF[n][2], 0.0, 1e-10);
  }
}

TEST(Transform, MissingNodeSetIsAnErrorAtTheTransform) {
  Model model = cantilever();
  model.transforms = {rotated("NOPE")};
  try {
    test::solve_with_plugins(model);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 12);
    EXPECT_NE(error.message().find("NOPE"), std::string::npos) << error.message();
  }
}

TEST(Transform, MissingNodeSetInADeckIsAnErrorAtItsLine) {
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n6, 1, 0, 1\n"
      "7, 1, 1, 1\n8, 0, 1, 1\n*ELEMENT, TYPE=C3D8, ELSET=EALL\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
      "*TRANSFORM, NSET=NOPE, TYPE=C\n0., 0., 0., 0., 0., 1.\n";  // the transform: line 12
  try {
    test::parse_deck("transform_missing_nset.inp", deck);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 12);
  }
}

TEST(Transform, CylinderAxisThroughANodeIsAnError) {
  Model model = cantilever();
  Transform transform;
  transform.nset = "ROOT";  // contains the node at the origin, on the z axis
  transform.axes.system = CoordinateSystem::Cylindrical;
  transform.axes.a = {0.0, 0.0, 0.0};
  transform.axes.b = {0.0, 0.0, 1.0};
  transform.where = {"cantilever.inp", 21};
  model.transforms = {transform};
  try {
    test::solve_with_plugins(model);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 21);
    EXPECT_NE(error.message().find("axis"), std::string::npos) << error.message();
  }
}

TEST(Transform, IterativeSolverIsRefusedByName) {
  Model model = cantilever();
  model.transforms = {rotated("TIP")};
  for (int n : model.nsets["TIP"].nodes) model.steps[0].cloads.push_back({n, 1, 1.0, {}});
  SolveOptions options;
  options.force = LinearSolverKind::Iterative;
  try {
    test::solve_with_plugins(model, options);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("*TRANSFORM"), std::string::npos) << error.message();
  }
}

}  // namespace
}  // namespace styk
