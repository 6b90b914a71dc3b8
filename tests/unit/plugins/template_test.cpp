// The template plug-in (plugins/template, docs/plugins.md): it loads through the loader and its
// TMPL8 is the trilinear brick, i.e. it reproduces the built-in C3D8 exactly.
#include <gtest/gtest.h>

#include "plugin_fixtures.hpp"
#include "styk/elements/c3d8.hpp"

namespace styk {
namespace {

std::unique_ptr<test::LoadedPlugins> load_template() {
  return test::load_build_plugins({std::string(STYK_PLUGIN_BUILD_DIR) + "/examples"});
}

TEST(TemplatePlugin, LoadsAndRegistersTmpl8) {
  auto plugins = load_template();
  EXPECT_TRUE(plugins->diagnostics.empty());
  EXPECT_EQ(plugins->registry.names(), std::vector<std::string>{"TMPL8"});
  const TElement* e = plugins->registry.find("TMPL8");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->node_count(), 8);
  EXPECT_EQ(e->faces().size(), 6u);
}

// Same stiffness as the built-in C3D8 on a distorted element (both full and reduced rules; the
// same code computes both, so agreement to round-off, 1e-14 relative), and 6 zero eigenvalues
// with the full rule (elements-ref section 7, C3D8 2x2x2).
TEST(TemplatePlugin, StiffnessEqualsBuiltInC3D8) {
  auto plugins = load_template();
  const TElement& tmpl = *plugins->registry.find("TMPL8");
  const C3D8 builtin;
  const ElementGeometry g = test::distorted_geometry(builtin, 9);
  for (RuleKind kind : {RuleKind::Full, RuleKind::Reduced}) {
    Eigen::MatrixXd Kt, Kb;
    tmpl.stiffness(g, test::unit_material(), kind, Kt);
    builtin.stiffness(g, test::unit_material(), kind, Kb);
    EXPECT_LT((Kt - Kb).cwiseAbs().maxCoeff(), 1e-14 * Kb.cwiseAbs().maxCoeff());
  }
  Eigen::MatrixXd K;
  tmpl.stiffness(test::reference_geometry(tmpl), test::unit_material(), RuleKind::Full, K);
  EXPECT_EQ(test::zero_eigenvalue_count(K), 6);
}

// Single-element constant-strain check through TElement::strains_stresses (the solver patch test
// comes with the solver): uniaxial stress sigma_33 = 1 in a unit-E, nu = 0.25 material from the
// exact displacement field u = (-nu x, -nu y, z) / E on a distorted element; tolerance 1e-12.
TEST(TemplatePlugin, UniaxialStressStateIsExact) {
  auto plugins = load_template();
  const TElement& tmpl = *plugins->registry.find("TMPL8");
  const ElementGeometry g = test::distorted_geometry(tmpl, 4);
  const double nu = 0.25;
  Eigen::VectorXd u(24);
  for (int i = 0; i < 8; ++i) u.segment<3>(3 * i) << -nu * g.X(i, 0), -nu * g.X(i, 1), g.X(i, 2);
  Eigen::MatrixXd strain, stress;
  tmpl.strains_stresses(g, test::material(1.0, nu), RuleKind::Full, u, strain, stress);
  ASSERT_EQ(stress.rows(), 8);
  for (int k = 0; k < 8; ++k) {
    for (int m = 0; m < 6; ++m) EXPECT_NEAR(stress(k, m), m == 2 ? 1.0 : 0.0, 1e-12);
    EXPECT_NEAR(strain(k, 0), -nu, 1e-12);
    EXPECT_NEAR(strain(k, 2), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace styk
