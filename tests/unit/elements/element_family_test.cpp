// The solid element family beyond C3D8/C3D20: C3D8R (+ the uncontrolled C3D8R0), C3D8I, C3D20R,
// C3D27, and the mean-dilatation B-bar option on every element: stiffness rank, symmetry, rigid
// body modes, constant-strain patch test on distorted elements.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "element_fixtures.hpp"
#include "styk/elements/c3d20.hpp"
#include "styk/elements/c3d20r.hpp"
#include "styk/elements/c3d27.hpp"
#include "styk/elements/c3d8.hpp"
#include "styk/elements/c3d8i.hpp"
#include "styk/elements/c3d8r.hpp"

namespace styk {
namespace {

using test::distorted_geometry;
using test::linear_field;
using test::reference_geometry;
using test::unit_material;
using test::zero_eigenvalue_count;

std::vector<std::unique_ptr<TElement>> family() {
  std::vector<std::unique_ptr<TElement>> elements;
  elements.push_back(std::make_unique<C3D8>());
  elements.push_back(std::make_unique<C3D8R>());
  elements.push_back(std::make_unique<C3D8R>(0.0));
  elements.push_back(std::make_unique<C3D8I>());
  elements.push_back(std::make_unique<C3D20>());
  elements.push_back(std::make_unique<C3D20R>());
  elements.push_back(std::make_unique<C3D27>());
  return elements;
}

Eigen::MatrixXd stiffness_of(const TElement& e, const ElementGeometry& g, RuleKind kind,
                             bool b_bar = false) {
  Eigen::MatrixXd K;
  e.stiffness(g, unit_material(), kind, K, ElementOptions{b_bar});
  return K;
}

// Zero eigenvalues of the single-element stiffness (relative tolerance 1e-9), reference cube and
// three distorted elements (nodes moved by up to 0.15), element's own rule:
// C3D8R (hourglass control) 6; C3D8R0 (none) 18 = 6 + 12 hourglass modes (elements-ref section 7,
// C3D8 1x1x1); C3D8I 6; C3D20R 12 (elements-ref section 7, C3D20 2x2x2); C3D27 3x3x3 6.
TEST(ElementFamily, ZeroEigenvalueCounts) {
  const std::vector<std::pair<std::string, int>> expected = {
      {"C3D8", 6},  {"C3D8R", 6},   {"C3D8R0", 18}, {"C3D8I", 6},
      {"C3D20", 6}, {"C3D20R", 12}, {"C3D27", 6}};
  const auto elements = family();
  ASSERT_EQ(elements.size(), expected.size());
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const TElement& e = *elements[i];
    ASSERT_EQ(e.name(), expected[i].first);
    EXPECT_EQ(zero_eigenvalue_count(stiffness_of(e, reference_geometry(e), RuleKind::Full)),
              expected[i].second)
        << e.name();
    for (unsigned seed : {1u, 2u, 3u})
      EXPECT_EQ(zero_eigenvalue_count(stiffness_of(e, distorted_geometry(e, seed), RuleKind::Full)),
                expected[i].second)
          << e.name() << " seed " << seed;
  }
}

// With mean-dilatation B-bar a single element has the same zero eigenvalues as without, except:
// an undistorted element whose interpolation contains the quadratic "special conformal" fields
// u = 2 (b.x) x - |x|^2 b about its centre (C3D8I, C3D20, C3D20R, C3D27) gets those 3 as extra zero
// modes (their strain 2 (b.x) I has no deviator and zero element mean), and C3D20R loses 7 more
// (19), because all 8 of its points lose their volumetric constraint. None of them survives in a
// mesh: BBar.MeshesHaveOnlyRigidBodyModes.
TEST(ElementFamily, ZeroEigenvalueCountsWithBBar) {
  struct Row {
    std::string name;
    int reference, distorted;
  };
  const std::vector<Row> expected = {{"C3D8", 6, 6},  {"C3D8R", 6, 6}, {"C3D8R0", 18, 18},
                                     {"C3D8I", 9, 6}, {"C3D20", 9, 6}, {"C3D20R", 19, 19},
                                     {"C3D27", 9, 6}};
  const auto elements = family();
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const TElement& e = *elements[i];
    ASSERT_EQ(e.name(), expected[i].name);
    EXPECT_EQ(zero_eigenvalue_count(stiffness_of(e, reference_geometry(e), RuleKind::Full, true)),
              expected[i].reference)
        << e.name();
    for (unsigned seed : {1u, 2u, 3u})
      EXPECT_EQ(
          zero_eigenvalue_count(stiffness_of(e, distorted_geometry(e, seed), RuleKind::Full, true)),
          expected[i].distorted)
          << e.name() << " seed " << seed;
  }
}

// Exactly symmetric; rigid translation and rotation give no force (|K u| < 1e-12 |K| |u|).
TEST(ElementFamily, SymmetricAndRigidBodyFree) {
  for (const auto& element : family()) {
    const TElement& e = *element;
    for (bool b_bar : {false, true}) {
      const ElementGeometry g = distorted_geometry(e, 5);
      const Eigen::MatrixXd K = stiffness_of(e, g, RuleKind::Full, b_bar);
      ASSERT_EQ(K.rows(), 3 * e.node_count());
      EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0) << e.name();
      Eigen::Matrix3d spin;
      spin << 0.0, -0.3, 0.2, 0.3, 0.0, -0.1, -0.2, 0.1, 0.0;
      const Eigen::VectorXd translation =
          linear_field(g, Eigen::Matrix3d::Zero(), {0.3, -0.2, 0.7});
      const Eigen::VectorXd rotation = linear_field(g, spin, Eigen::Vector3d::Zero());
      const double scale = K.cwiseAbs().maxCoeff();
      EXPECT_LT((K * translation).norm(), 1e-12 * scale * translation.norm()) << e.name();
      EXPECT_LT((K * rotation).norm(), 1e-12 * scale * rotation.norm()) << e.name();
    }
  }
}

// Constant-strain patch test on single distorted elements (seeds 17, 18; nodes moved by up to
// 0.15): a linear field u = c + G x gives strain sym(G) and stress D sym(G) at every point, to
// 1e-10, for every element, both rules, with and without B-bar. For C3D8I this checks the Taylor
// correction (the recovered incompatible modes vanish); for B-bar that the averaged dilatation of
// a linear field is the pointwise one.
TEST(ElementFamily, PatchTestOnDistortedElements) {
  Eigen::Matrix3d G;
  G << 0.3, -0.2, 0.5, 0.1, -0.4, 0.25, -0.15, 0.35, 0.2;
  const Eigen::Vector3d c(0.01, -0.02, 0.03);
  const double E = 1.0, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const Eigen::Matrix3d sigma = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
  const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (const auto& element : family())
    for (unsigned seed : {17u, 18u})
      for (RuleKind kind : {RuleKind::Full, RuleKind::Reduced})
        for (bool b_bar : {false, true}) {
          const TElement& e = *element;
          const ElementGeometry g = distorted_geometry(e, seed);
          const Eigen::VectorXd u = linear_field(g, G, c);
          Eigen::MatrixXd strain, stress;
          e.strains_stresses(g, unit_material(), kind, u, strain, stress, ElementOptions{b_bar});
          ASSERT_EQ(strain.rows(), e.rule(kind).size());
          double worst = 0.0;
          for (int k = 0; k < strain.rows(); ++k)
            for (int m = 0; m < 6; ++m) {
              worst = std::max(worst, std::abs(strain(k, m) - eps(pairs[m][0], pairs[m][1])));
              worst = std::max(worst, std::abs(stress(k, m) - sigma(pairs[m][0], pairs[m][1])));
            }
          EXPECT_LT(worst, 1e-10) << e.name() << " seed " << seed << (b_bar ? " B-bar" : "");
        }
}

// The hourglass stiffness of C3D8R vanishes on affine fields: K(C3D8R) u = K(C3D8R0) u for a
// linear u on a distorted element (relative 1e-12), while it stiffens every hourglass mode.
TEST(ElementFamily, HourglassControlIgnoresAffineFields) {
  const C3D8R controlled;
  const C3D8R uncontrolled(0.0);
  const ElementGeometry g = distorted_geometry(controlled, 23);
  const Eigen::MatrixXd Kc = stiffness_of(controlled, g, RuleKind::Full);
  const Eigen::MatrixXd Ku = stiffness_of(uncontrolled, g, RuleKind::Full);
  Eigen::Matrix3d G;
  G << 0.2, 0.1, -0.3, 0.4, 0.1, 0.2, -0.5, 0.3, -0.1;
  const Eigen::VectorXd u = linear_field(g, G, {0.1, 0.2, 0.3});
  EXPECT_LT((Kc * u - Ku * u).norm(), 1e-12 * (Ku * u).norm());
  EXPECT_GT((Kc - Ku).norm(), 1e-4 * Ku.norm());  // the control is there
}

// The reduced-integration types integrate with their own rule whatever kind is asked.
TEST(ElementFamily, RulesAndNames) {
  EXPECT_EQ(C3D8R().rule(RuleKind::Full).size(), 1);
  EXPECT_EQ(C3D8R().rule(RuleKind::Reduced).size(), 1);
  EXPECT_EQ(C3D20R().rule(RuleKind::Full).size(), 8);
  EXPECT_EQ(C3D8I().rule(RuleKind::Full).size(), 8);
  EXPECT_EQ(C3D27().rule(RuleKind::Full).size(), 27);
  EXPECT_EQ(C3D27().rule(RuleKind::Reduced).size(), 8);
  EXPECT_EQ(C3D8R().name(), "C3D8R");
  EXPECT_EQ(C3D8R(0.0).name(), "C3D8R0");
  EXPECT_EQ(C3D8I().incompatible_mode_count(), 9);
  EXPECT_EQ(C3D8().incompatible_mode_count(), 0);
}

}  // namespace
}  // namespace styk
