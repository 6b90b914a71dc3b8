// SPEC §2.4, thesis Tab 2.9-2.11 (elements-ref §6 "two-element contact"): two elements of one
// type stacked on the reference cubes [-1,1]^2 x [-1,1] (lower) and [-1,1]^2 x [1,3] (upper),
// separated by a zero-thickness frictionless contact interface (matching nodes: node-to-node),
// nu = 0.3, lower bottom supported in z only, in-plane rigid motions removed on both elements
// (node at x = y = -1: ux, uy; node at x = 1, y = -1: uy), the thesis' point loads CF3 on the
// upper top face. The upper element is held in z only by the contact (a body held by contact).
// C3D21/C3D28: both contact faces are the elements' S1 (the lower element turned upside down).
// Expected pair forces (contact multiplier of each slave node):
//   C3D14 (top corners -1/3, centre -8/3): corners 0.5935, centre 1.6259 (4 digits: 5e-5)
//   C3D21 (top corners +1/3, mid-edges -4/3): 1/9, 4/9, 16/9 (1e-9: uniform stress is exact)
//   C3D28 (same top loads): 1/36, 5/36, 25/36 (1e-9)
// every pair force positive and the sum 4 (1e-9); the gaps of closed pairs at round-off (1e-12).
// C3D20 (top corners +1/3, mid-edges -4/3, its consistent loads): a uniform pressure needs the
// corner pairs to pull (equivalent nodal area -1/3 < 0, the violated "physical contact
// condition"); a unilateral interface cannot pull, so the corner pairs open.
#include <map>
#include <memory>

#include <gtest/gtest.h>

#include "contact_model_kit.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/interface.hpp"
#include "styk/mesher/merge.hpp"
#include "styk/solver/analysis.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk {
namespace {

struct Stack {
  Model model;
  IncrementResult result;
};

Stack solve_stack(const ElementRegistry& registry, const std::string& type) {
  mesher::Mesh mesh;
  const std::string base = type == "C3D14" || type == "C3D8" ? "C3D8" : "C3D20";
  test::add_box(mesh, {-1, -1, -1}, {1, 1, 1}, {1, 1, 1}, base, "LOWER");
  test::add_box(mesh, {-1, -1, 1}, {1, 1, 3}, {1, 1, 1}, base, "UPPER");
  mesher::merge_coincident_nodes(mesh);
  if (type == "C3D14") mesher::convert_elements(mesh, registry, "C3D14");
  mesher::split_interface(mesh, "LOWER", "IF");
  if (type == "C3D21") {
    mesher::convert_elements(mesh, registry, "C3D21", "IF_B");
    mesher::convert_elements(mesh, registry, "C3D21", "IF_A");
  } else if (type == "C3D28") {
    mesher::convert_elements(mesh, registry, "C3D28", "IF_B");
    mesher::convert_elements(mesh, registry, "C3D28", "IF_A");
  }
  Stack out;
  Model& model = out.model;
  model = test::contact_model(mesh, {{"LOWER", 210000.0, 0.3}, {"UPPER", 210000.0, 0.3}});
  test::add_contact_pair(model, "IF_B", "IF_A", "SMOOTH", std::nullopt);
  using test::near;
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return near(x[2], -1); }), {3});
  for (double z : {-1.0, 3.0}) {
    test::fix(model,
              test::nodes_where(
                  model,
                  [z](const Vec3& x) { return near(x[0], -1) && near(x[1], -1) && near(x[2], z); }),
              {1, 2});
    test::fix(
        model,
        test::nodes_where(
            model, [z](const Vec3& x) { return near(x[0], 1) && near(x[1], -1) && near(x[2], z); }),
        {2});
  }
  for (int n : test::nodes_where(model, [](const Vec3& x) { return near(x[2], 3); })) {
    const Vec3& x = model.coords[n];
    const bool corner = near(std::abs(x[0]), 1) && near(std::abs(x[1]), 1);
    const bool centre = near(x[0], 0) && near(x[1], 0);
    double cf3 = 0.0;
    if (type == "C3D14")
      cf3 = corner ? -1.0 / 3.0 : (centre ? -8.0 / 3.0 : 0.0);
    else
      cf3 = corner ? 1.0 / 3.0 : -4.0 / 3.0;
    model.steps[0].cloads.push_back({n, 3, cf3, {}});
  }
  Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  EXPECT_EQ(results.increments.size(), 1u);
  out.result = std::move(results.increments.back());
  return out;
}

// Pair force (= contact pressure x nodal area) by the slave node's in-plane class.
enum class Where { Corner, Edge, Interior };
Where classify(const Vec3& x) {
  const int on_edge = (std::abs(std::abs(x[0]) - 1) < 1e-9) + (std::abs(std::abs(x[1]) - 1) < 1e-9);
  return on_edge == 2 ? Where::Corner : (on_edge == 1 ? Where::Edge : Where::Interior);
}

void expect_pair_forces(const Stack& s, const std::map<Where, double>& expected, double tol) {
  ASSERT_FALSE(s.result.contact.empty());
  double sum = 0.0;
  for (const ContactNodeResult& c : s.result.contact) {
    const double force = c.pressure * c.area;
    const Vec3& x = s.model.coords[c.node];
    EXPECT_GT(force, 0.0) << "slave node " << s.model.node_ids[c.node];
    EXPECT_EQ(c.status, ContactStatus::Slip);  // closed and frictionless
    EXPECT_NEAR(force, expected.at(classify(x)), tol) << "slave node at " << x[0] << ", " << x[1];
    EXPECT_NEAR(c.gap, 0.0, 1e-12);  // exact enforcement: penetration at round-off
    sum += force;
  }
  EXPECT_NEAR(sum, 4.0, 1e-9);
  EXPECT_TRUE(s.result.contact_equilibrium.valid);
  EXPECT_LT(s.result.contact_equilibrium.relative_residual, 1e-8);
}

class StackedContact : public test::PluginRegistrySuite<> {};

TEST_F(StackedContact, C3D14PairForcesTab29) {
  const Stack s = solve_stack(registry(), "C3D14");
  EXPECT_EQ(s.result.contact.size(), 5u);
  expect_pair_forces(s, {{Where::Corner, 0.5935}, {Where::Interior, 1.6259}}, 5e-5);
}

TEST_F(StackedContact, C3D21PairForcesTab210) {
  const Stack s = solve_stack(registry(), "C3D21");
  EXPECT_EQ(s.result.contact.size(), 9u);
  expect_pair_forces(
      s, {{Where::Corner, 1.0 / 9}, {Where::Edge, 4.0 / 9}, {Where::Interior, 16.0 / 9}}, 1e-9);
}

TEST_F(StackedContact, C3D28PairForcesTab211) {
  const Stack s = solve_stack(registry(), "C3D28");
  EXPECT_EQ(s.result.contact.size(), 16u);
  expect_pair_forces(
      s, {{Where::Corner, 1.0 / 36}, {Where::Edge, 5.0 / 36}, {Where::Interior, 25.0 / 36}}, 1e-9);
}

TEST_F(StackedContact, C3D20CornerPairsWouldHaveToPull) {
  // The consistent pressure load of the C3D20 contact face puts -1/3 on each corner (nodal area
  // A_i < 0): a uniform pressure across the interface needs a tensile corner pair force.
  const Stack s = solve_stack(registry(), "C3D20");
  ASSERT_EQ(s.result.contact.size(), 8u);
  double sum = 0.0;
  for (const ContactNodeResult& c : s.result.contact) {
    if (classify(s.model.coords[c.node]) == Where::Corner) {
      EXPECT_NEAR(c.area, -1.0 / 3.0, 1e-12);    // the negative equivalent nodal area
      EXPECT_EQ(c.status, ContactStatus::Open);  // a contact pair cannot pull: it opens
      EXPECT_GT(c.gap, 0.0);
    } else {
      EXPECT_GT(c.pressure * c.area, 0.0);
    }
    sum += c.pressure * c.area;
  }
  EXPECT_NEAR(sum, 4.0, 1e-9);
}

}  // namespace
}  // namespace styk
