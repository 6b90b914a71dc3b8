// A linear stress field through the whole pipeline (solve -> recover -> extrapolate -> average):
// a C3D20 beam [0,4] x [0,1] x [-1,1] in pure bending. The exact 3D solution
//   u = k x z,  v = -nu k y z,  w = -k (x^2 + nu (z^2 - y^2)) / 2
// is quadratic, hence in the C3D20 space, so prescribing it on the two end faces (lateral faces
// traction-free, as in the exact solution) makes the FE solution exact: s11 = E k z, every other
// component 0. The extrapolated element-node values and the method-I averages must then equal
// E k z at the nodes (1e-9 of the peak stress); method II (mean of the neighbouring centroid
// values E k z_c) must equal that mean, i.e. smooth the field.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kYoung = 1000.0, kPoisson = 0.3, kCurvature = 1e-3;
constexpr double kTol = 1e-9 * kYoung * kCurvature;  // peak stress E k |z| = 1

Vec3 bending_displacement(const Vec3& x) {
  const double k = kCurvature, nu = kPoisson;
  return {k * x[0] * x[2], -nu * k * x[1] * x[2],
          -0.5 * k * (x[0] * x[0] + nu * (x[2] * x[2] - x[1] * x[1]))};
}

Model bending_beam(const ElementRegistry& registry) {
  test::HexModelBuilder builder(registry, kYoung, kPoisson);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) {
      const double x0 = i, x1 = i + 1.0, z0 = -1.0 + j, z1 = z0 + 1.0;
      builder.add("C3D20", {{{x0, 0, z0},
                             {x1, 0, z0},
                             {x1, 1, z0},
                             {x0, 1, z0},
                             {x0, 0, z1},
                             {x1, 0, z1},
                             {x1, 1, z1},
                             {x0, 1, z1}}});
    }
  Model model = builder.finish();
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    if (std::abs(x[0]) > 1e-12 && std::abs(x[0] - 4.0) > 1e-12) continue;
    const Vec3 u = bending_displacement(x);
    for (int d = 0; d < 3; ++d) model.boundaries.push_back({n, d + 1, u[d], {}});
  }
  return model;
}

void expect_bending_stress(const Tensor6& s, double z, const std::string& where) {
  EXPECT_NEAR(s[0], kYoung * kCurvature * z, kTol) << where;
  for (int k = 1; k < 6; ++k) EXPECT_NEAR(s[k], 0.0, kTol) << where << " comp " << k;
}

TEST(LinearStressField, PureBendingC3D20ExtrapolatesExactlyToTheNodes) {
  ElementRegistry registry = test::builtin_registry();
  const Model model = bending_beam(registry);
  SolveOptions options;
  options.threads = 2;
  const Results results = run_static_analysis(model, registry, options, nullptr, nullptr);
  const IncrementResult& inc = results.increments.at(0);

  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    const Element& element = model.elements[e];
    double zc = 0.0;
    for (int k = 0; k < element.node_count; ++k) {
      const double z = model.coords[nodes[k]][2];
      zc += z / element.node_count;
      expect_bending_stress(inc.S_element_nodes[element.first_node + k], z,
                            "element " + std::to_string(e) + " node " + std::to_string(k));
    }
    expect_bending_stress(inc.S_centroid[e], zc, "centroid " + std::to_string(e));
  }
  std::vector<double> centroid_sum(model.node_count(), 0.0);
  std::vector<int> count(model.node_count(), 0);
  for (int e = 0; e < model.element_count(); ++e)
    for (int k = 0; k < model.elements[e].node_count; ++k) {
      const int n = model.element_nodes(e)[k];
      centroid_sum[n] += inc.S_centroid[e][0];
      ++count[n];
    }
  int smoothed = 0;
  for (int n = 0; n < model.node_count(); ++n) {
    const double z = model.coords[n][2];
    expect_bending_stress(inc.S_nodal_I[n], z, "method I node " + std::to_string(n));
    EXPECT_NEAR(inc.S_nodal_II[n][0], centroid_sum[n] / count[n], kTol) << "node " << n;
    // Method II is a smoothing: on the top and bottom faces it gives E k z_c = +-0.5, not +-1.
    if (std::abs(std::abs(z) - 1.0) < 1e-12) {
      EXPECT_NEAR(std::abs(inc.S_nodal_II[n][0]), 0.5, kTol) << "node " << n;
      ++smoothed;
    }
  }
  EXPECT_GT(smoothed, 0);
}

}  // namespace
}  // namespace styk
