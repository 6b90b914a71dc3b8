// StressAveraging (solver/src/stress_averaging.hpp) on two C3D8 cubes side by side, with
// hand-made integration-point values: element-node values, centroids, nodal methods I and II
// (SPEC §5), a node no element uses, threading, and mismatched input.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "stress_averaging.hpp"
#include "styk/elements/builtin.hpp"

namespace styk::solver_detail {
namespace {

class AveragingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    register_builtin_elements(registry_);
    test::HexModelBuilder builder(registry_, 1000.0, 0.3);
    builder.add(
        "C3D8",
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}});
    builder.add(
        "C3D8",
        {{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}}});
    model_ = builder.finish();
    unused_ = model_.add_node(99, {5.0, 5.0, 5.0}, {});
    formulation_.assign(2, registry_.find("C3D8"));
    rule_ = registry_.find("C3D8")->rule(RuleKind::Full);

    // Component 0: 2x - 1 in the left element (= xi there), 0 in the right one.
    // Component 3: 7 in both. Component 5: 10 * element index. Strains left empty.
    inc_.ip_offset = {0, 8, 16};
    inc_.S.assign(16, Tensor6{});
    for (int p = 0; p < 8; ++p) {
      inc_.S[p][0] = rule_.points[p][0];
      inc_.S[p][3] = inc_.S[8 + p][3] = 7.0;
      inc_.S[8 + p][5] = 10.0;
    }
  }

  double x_of(int node) const { return model_.coords[node][0]; }

  ElementRegistry registry_;
  Model model_;
  int unused_ = -1;
  std::vector<const TElement*> formulation_;
  IntegrationRule rule_;
  IncrementResult inc_;
};

TEST_F(AveragingTest, ElementNodesAndCentroids) {
  const StressAveraging averaging(model_, formulation_, RuleKind::Full);
  averaging.apply(1, inc_);
  ASSERT_EQ(inc_.S_element_nodes.size(), model_.connectivity.size());
  ASSERT_EQ(inc_.S_centroid.size(), 2u);
  for (int e = 0; e < 2; ++e)
    for (int k = 0; k < 8; ++k) {
      const Tensor6& s = inc_.S_element_nodes[model_.elements[e].first_node + k];
      const double x = x_of(model_.element_nodes(e)[k]);
      EXPECT_NEAR(s[0], e == 0 ? 2 * x - 1 : 0.0, 1e-13) << "element " << e << " node " << k;
      EXPECT_NEAR(s[3], 7.0, 1e-13);
      EXPECT_NEAR(s[5], 10.0 * e, 1e-13);
    }
  EXPECT_NEAR(inc_.S_centroid[0][0], 0.0, 1e-14);
  EXPECT_NEAR(inc_.S_centroid[0][3], 7.0, 1e-13);
  EXPECT_NEAR(inc_.S_centroid[1][5], 10.0, 1e-13);
  EXPECT_TRUE(inc_.E_element_nodes.empty());  // no strains given, none made up
  EXPECT_TRUE(inc_.E_nodal_I.empty());
}

// At x = 1 the nodes are shared: method I averages the element-node values (1 and 0 -> 0.5),
// method II the centroid values (0 and 0 -> 0; 0 and 10 -> 5 for component 5).
TEST_F(AveragingTest, MethodsIAndII) {
  const StressAveraging averaging(model_, formulation_, RuleKind::Full);
  averaging.apply(1, inc_);
  ASSERT_EQ(inc_.S_nodal_I.size(), static_cast<std::size_t>(model_.node_count()));
  ASSERT_EQ(inc_.S_nodal_II.size(), static_cast<std::size_t>(model_.node_count()));
  int shared = 0;
  for (int n = 0; n < model_.node_count(); ++n) {
    if (n == unused_) continue;
    const double x = x_of(n);
    const Tensor6& I = inc_.S_nodal_I[n];
    const Tensor6& II = inc_.S_nodal_II[n];
    const double expected_I0 = x == 0.0 ? -1.0 : x == 1.0 ? 0.5 : 0.0;
    const double expected_5 = x == 0.0 ? 0.0 : x == 1.0 ? 5.0 : 10.0;
    EXPECT_NEAR(I[0], expected_I0, 1e-13) << "node at x = " << x;
    EXPECT_NEAR(II[0], 0.0, 1e-13) << "node at x = " << x;
    EXPECT_NEAR(I[3], 7.0, 1e-13);
    EXPECT_NEAR(II[3], 7.0, 1e-13);
    EXPECT_NEAR(I[5], expected_5, 1e-13);
    EXPECT_NEAR(II[5], expected_5, 1e-13);
    shared += x == 1.0 ? 1 : 0;
  }
  EXPECT_EQ(shared, 4);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(inc_.S_nodal_I[unused_][k], 0.0);
    EXPECT_EQ(inc_.S_nodal_II[unused_][k], 0.0);
  }
}

TEST_F(AveragingTest, StrainsAreAveragedLikeStresses) {
  inc_.E = inc_.S;
  const StressAveraging averaging(model_, formulation_, RuleKind::Full);
  averaging.apply(1, inc_);
  EXPECT_EQ(inc_.E_element_nodes, inc_.S_element_nodes);
  EXPECT_EQ(inc_.E_centroid, inc_.S_centroid);
  EXPECT_EQ(inc_.E_nodal_I, inc_.S_nodal_I);
  EXPECT_EQ(inc_.E_nodal_II, inc_.S_nodal_II);
}

TEST_F(AveragingTest, ThreadCountDoesNotChangeTheResult) {
  const StressAveraging averaging(model_, formulation_, RuleKind::Full);
  IncrementResult serial = inc_, threaded = inc_;
  averaging.apply(1, serial);
  averaging.apply(3, threaded);
  EXPECT_EQ(serial.S_element_nodes, threaded.S_element_nodes);
  EXPECT_EQ(serial.S_centroid, threaded.S_centroid);
  EXPECT_EQ(serial.S_nodal_I, threaded.S_nodal_I);
  EXPECT_EQ(serial.S_nodal_II, threaded.S_nodal_II);
}

// One operator per element type, shared by its elements.
TEST_F(AveragingTest, OperatorIsBuiltOncePerType) {
  const StressAveraging averaging(model_, formulation_, RuleKind::Full);
  EXPECT_EQ(&averaging.extrapolation(0), &averaging.extrapolation(1));
  EXPECT_EQ(averaging.extrapolation(0).space, "element");
}

TEST_F(AveragingTest, MismatchedIntegrationPointsAreAProgrammingError) {
  const StressAveraging averaging(model_, formulation_, RuleKind::Full);
  IncrementResult wrong = inc_;
  wrong.ip_offset = {0, 8, 15};
  wrong.S.resize(15);
  EXPECT_THROW(averaging.apply(1, wrong), std::logic_error);
  IncrementResult short_offsets = inc_;
  short_offsets.ip_offset = {0, 8};
  EXPECT_THROW(averaging.apply(1, short_offsets), std::logic_error);
  EXPECT_THROW(StressAveraging(model_, {formulation_[0]}, RuleKind::Full), std::logic_error);
}

}  // namespace
}  // namespace styk::solver_detail
