// Models that cannot be analysed are diagnosed in words, at the right deck line, never solved
// into garbage.
#include <gtest/gtest.h>

#include <algorithm>

#include "solver_test_support.hpp"

namespace styk {
namespace {

std::string error_of(const Model& model, const ElementRegistry& registry,
                     LinearSolverKind kind = LinearSolverKind::Automatic, int* line = nullptr) {
  SolveOptions options;
  options.force = kind;
  try {
    run_static_analysis(model, registry, options, nullptr, nullptr);
  } catch (const InputError& error) {
    if (line != nullptr) *line = error.where().line;
    return error.what();
  }
  return "no InputError";
}

Model loaded_cube(const ElementRegistry& registry) {
  Model model = test::block(registry, "C3D8", 1, 1, 1, 1.0, 1.0, 1.0);
  Step step = test::static_step();
  for (int n : test::nodes_at(model, 0, 1.0)) step.cloads.push_back({n, 1, 1.0, {}});
  model.steps.push_back(step);
  return model;
}

TEST(Diagnostics, UnconstrainedModelMovesFreely) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = loaded_cube(registry);
  // Held in y and z only: free in x.
  for (int n : test::nodes_at(model, 0, 0.0)) {
    model.boundaries.push_back({n, 2, 0.0, {}});
    model.boundaries.push_back({n, 3, 0.0, {}});
  }
  const std::string message = error_of(model, registry);
  EXPECT_NE(message.find("test.inp: the model can move freely in x"), std::string::npos) << message;
  EXPECT_NE(message.find("(8 nodes)"), std::string::npos) << message;
}

TEST(Diagnostics, SupportOnOneLineLetsTheModelRotate) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = test::block(registry, "C3D8", 3, 1, 1, 3.0, 1.0, 1.0);
  // Every dof fixed, but only on the edge y = z = 0: the bar can spin about it.
  for (int n = 0; n < model.node_count(); ++n)
    if (model.coords[n][1] == 0.0 && model.coords[n][2] == 0.0)
      for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, {}});
  Step step = test::static_step();
  step.cloads.push_back({test::nodes_at(model, 2, 1.0).front(), 2, 1.0, {}});
  model.steps.push_back(step);
  const std::string message = error_of(model, registry);
  EXPECT_NE(message.find("rotate freely"), std::string::npos) << message;
  EXPECT_NE(message.find("along (1, 0, 0)"), std::string::npos) << message;
}

TEST(Diagnostics, HingeIsCaughtByTheFactorisationAtANode) {
  // Two cubes sharing one corner node: the second can turn about it although the mesh is one
  // connected, well supported part. The factorisation must name a node of the second cube.
  const ElementRegistry registry = test::builtin_registry();
  Model model = test::block(registry, "C3D8", 1, 1, 1, 1.0, 1.0, 1.0);
  const TElement& hex = *registry.find("C3D8");
  std::vector<int> nodes;
  int shared = -1;
  for (int n = 0; n < model.node_count(); ++n)
    if (model.coords[n] == Vec3{1.0, 1.0, 1.0}) shared = n;
  for (const Vec3& xi : hex.natural_nodes()) {
    const Vec3 x{1.5 + 0.5 * xi[0], 1.5 + 0.5 * xi[1], 1.5 + 0.5 * xi[2]};
    if (x == Vec3{1.0, 1.0, 1.0}) {
      nodes.push_back(shared);
    } else {
      nodes.push_back(model.add_node(1000 + static_cast<Id>(nodes.size()), x, {}));
    }
  }
  model.elements[model.add_element(2, "C3D8", nodes, {"test.inp", 9})].section = 0;
  for (int n : test::nodes_at(model, 0, 0.0))
    for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, {}});
  Step step = test::static_step();
  step.cloads.push_back({nodes[6], 3, 1.0, {}});
  model.steps.push_back(step);

  const std::string message = error_of(model, registry, LinearSolverKind::Cholmod);
  const std::string lead = "test.inp: the stiffness matrix is singular at node ";
  ASSERT_EQ(message.rfind(lead, 0), 0u) << message;
  const long named = std::stol(message.substr(lead.size()));
  EXPECT_GE(named, 1001) << message;  // one of the second cube's own nodes 1001..1007
  EXPECT_LE(named, 1007) << message;
  EXPECT_NE(message.find("mechanism"), std::string::npos) << message;
}

TEST(Diagnostics, ElementWithoutSectionPointsAtItsLine) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = loaded_cube(registry);
  test::add_symmetry_supports(model);
  model.elements[0].section = -1;
  model.elements[0].where = {"test.inp", 42};
  int line = 0;
  const std::string message = error_of(model, registry, LinearSolverKind::Automatic, &line);
  EXPECT_EQ(line, 42);
  EXPECT_NE(message.find("test.inp:42: element 1 has no section"), std::string::npos) << message;
}

TEST(Diagnostics, UnknownElementTypeIsNamed) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = loaded_cube(registry);
  test::add_symmetry_supports(model);
  model.elements[0].type = "C3D99";
  model.elements[0].where = {"test.inp", 5};
  EXPECT_NE(error_of(model, registry).find("test.inp:5: element 1 has type C3D99"),
            std::string::npos);
}

TEST(Diagnostics, LoadOnAnUnusedNodeIsRejectedAtTheLoadLine) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = loaded_cube(registry);
  test::add_symmetry_supports(model);
  const int lonely = model.add_node(99, Vec3{5.0, 5.0, 5.0}, {});
  model.steps[0].cloads.push_back({lonely, 2, 1.0, {"test.inp", 17}});
  int line = 0;
  const std::string message = error_of(model, registry, LinearSolverKind::Automatic, &line);
  EXPECT_EQ(line, 17);
  EXPECT_NE(message.find("node 99, which belongs to no element"), std::string::npos) << message;
}

TEST(Diagnostics, MaterialWithoutElasticConstants) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = loaded_cube(registry);
  test::add_symmetry_supports(model);
  model.materials[0].poisson.reset();
  model.materials[0].where = {"test.inp", 3};
  int line = 0;
  const std::string message = error_of(model, registry, LinearSolverKind::Automatic, &line);
  EXPECT_EQ(line, 3);
  EXPECT_NE(message.find("no *ELASTIC"), std::string::npos) << message;
}

TEST(Diagnostics, ModelWithoutStep) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = loaded_cube(registry);
  model.steps.clear();
  EXPECT_NE(error_of(model, registry).find("no *STEP"), std::string::npos);
}

}  // namespace
}  // namespace styk
