// make_extrapolation() (solver/src/stress_averaging.hpp): which fitting space every element type
// and rule gets, the classic 2x2x2 -> corner extrapolation of C3D8, and exact reproduction of
// linear (and, in the element's own space, quadratic) fields at the nodes and the centre.
#include <cmath>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "stress_averaging.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk::solver_detail {
namespace {

using Field = std::function<double(const Vec3&)>;

class ExtrapolationTest : public test::PluginRegistrySuite<> {
 protected:
  static void SetUpTestSuite() {
    PluginRegistrySuite::SetUpTestSuite();
    for (const PluginDiagnostic& d : plugin_diagnostics()) ADD_FAILURE() << d.message;
  }
  static const TElement& element(const std::string& type) {
    const TElement* e = registry().find(type);
    if (e == nullptr) throw std::invalid_argument(type + " is not registered");
    return *e;
  }

  // Samples `f` at the points of the rule, extrapolates, and compares with f at the nodes and at
  // the centre.
  static void expect_reproduced(const std::string& type, RuleKind kind, const Field& f) {
    const TElement& e = element(type);
    const IntegrationRule rule = e.rule(kind);
    const Extrapolation op = make_extrapolation(e, rule);
    Eigen::VectorXd at_points(rule.size());
    for (int p = 0; p < rule.size(); ++p) at_points(p) = f(rule.points[p]);
    const Eigen::VectorXd at_nodes = op.to_nodes * at_points;
    for (int i = 0; i < e.node_count(); ++i)
      EXPECT_NEAR(at_nodes(i), f(e.natural_nodes()[i]), 1e-11) << type << " node " << i + 1;
    EXPECT_NEAR(op.to_centroid.dot(at_points), f({0.0, 0.0, 0.0}), 1e-11) << type << " centre";
  }
};

const Field kLinear = [](const Vec3& x) { return 3.0 - 2.0 * x[0] + 0.5 * x[1] + 7.0 * x[2]; };

TEST_F(ExtrapolationTest, FullRulesUseTheElementSpace) {
  for (const char* type : {"C3D8", "C3D20", "C3D27", "C3D14", "C3D21", "C3D28"}) {
    const TElement& e = element(type);
    const Extrapolation op = make_extrapolation(e, e.rule(RuleKind::Full));
    EXPECT_EQ(op.space, "element") << type;
    EXPECT_EQ(op.to_nodes.rows(), e.node_count()) << type;
    EXPECT_EQ(op.to_nodes.cols(), e.rule(RuleKind::Full).size()) << type;
  }
}

// Fewer points than nodes: the largest smaller space that the points determine.
TEST_F(ExtrapolationTest, ReducedRulesFallBackToSmallerSpaces) {
  EXPECT_EQ(make_extrapolation(element("C3D8"), element("C3D8").rule(RuleKind::Reduced)).space,
            "constant");  // 1 point
  EXPECT_EQ(make_extrapolation(element("C3D20"), element("C3D20").rule(RuleKind::Reduced)).space,
            "trilinear");  // 2x2x2
  EXPECT_EQ(make_extrapolation(element("C3D28"), element("C3D28").rule(RuleKind::Reduced)).space,
            "trilinear");  // 3x3x3 < 28 nodes
  IntegrationRule tetrahedral_like;
  tetrahedral_like.points = {
      {-0.5, -0.5, -0.5}, {0.5, -0.5, -0.5}, {-0.5, 0.5, -0.5}, {-0.5, -0.5, 0.5}};
  tetrahedral_like.weights = {1, 1, 1, 1};
  EXPECT_EQ(make_extrapolation(element("C3D8"), tetrahedral_like).space, "linear");
  EXPECT_THROW(make_extrapolation(element("C3D8"), IntegrationRule{}), std::logic_error);
}

// C3D8 with 2x2x2 Gauss: the classic extrapolation, node i gets sum_p L_p(sqrt(3) xi_i) s_p, with
// L_p the trilinear Lagrange function of the point p's octant: prod (1 + sqrt(3) xi_i,d s_p,d)/2.
TEST_F(ExtrapolationTest, C3D8IsTheClassicTrilinearExtrapolation) {
  const TElement& e = element("C3D8");
  const IntegrationRule rule = e.rule(RuleKind::Full);
  const Extrapolation op = make_extrapolation(e, rule);
  for (int i = 0; i < 8; ++i)
    for (int p = 0; p < 8; ++p) {
      double expected = 1.0;
      for (int d = 0; d < 3; ++d) {
        const double sign = rule.points[p][d] > 0 ? 1.0 : -1.0;
        expected *= 0.5 * (1.0 + std::sqrt(3.0) * e.natural_nodes()[i][d] * sign);
      }
      EXPECT_NEAR(op.to_nodes(i, p), expected, 1e-13) << "node " << i + 1 << " point " << p + 1;
    }
  for (int p = 0; p < 8; ++p) EXPECT_NEAR(op.to_centroid(p), 0.125, 1e-14);
}

TEST_F(ExtrapolationTest, LinearFieldsAreReproducedByEveryTypeAndRule) {
  for (const char* type : {"C3D8", "C3D20", "C3D27", "C3D14", "C3D21", "C3D28"})
    for (RuleKind kind : {RuleKind::Full, RuleKind::Reduced}) {
      if (std::string(type) == "C3D8" && kind == RuleKind::Reduced) continue;  // constant only
      expect_reproduced(type, kind, kLinear);
    }
}

TEST_F(ExtrapolationTest, ConstantFieldsAreReproducedEvenByOnePoint) {
  expect_reproduced("C3D8", RuleKind::Reduced, [](const Vec3&) { return -4.5; });
}

// Fields inside the element's own space come back exactly: serendipity cubic terms for C3D20,
// the bottom-face bubble (1-xi^2)(1-eta^2) zeta (zeta-1) for C3D21, the bicubic bottom trace for
// C3D28.
TEST_F(ExtrapolationTest, FieldsOfTheElementSpaceAreReproduced) {
  expect_reproduced("C3D20", RuleKind::Full, [](const Vec3& x) {
    return x[0] * x[0] - 2.0 * x[1] * x[2] + x[0] * x[1] * x[2] + 0.3 * x[0] * x[0] * x[1] * x[2];
  });
  expect_reproduced("C3D21", RuleKind::Full, [](const Vec3& x) {
    return (1 - x[0] * x[0]) * (1 - x[1] * x[1]) * x[2] * (x[2] - 1) + x[2] * x[2];
  });
  expect_reproduced("C3D28", RuleKind::Full, [](const Vec3& x) {
    return (1 - x[2]) * x[0] * x[0] * x[0] * x[1] * x[1] + x[1] * x[2];
  });
}

// The fitted field is a weighted mean: every row of each operator sums to one.
TEST_F(ExtrapolationTest, RowsSumToOne) {
  for (const char* type : {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"}) {
    const Extrapolation op = make_extrapolation(element(type), element(type).rule(RuleKind::Full));
    for (int i = 0; i < op.to_nodes.rows(); ++i)
      EXPECT_NEAR(op.to_nodes.row(i).sum(), 1.0, 1e-12) << type << " node " << i + 1;
    EXPECT_NEAR(op.to_centroid.sum(), 1.0, 1e-12) << type;
  }
}

}  // namespace
}  // namespace styk::solver_detail
