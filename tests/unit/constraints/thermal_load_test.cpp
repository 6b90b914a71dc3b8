// Thermal loads in the linear static solver (contact issue, "Thermal"; SPEC §2.1 element
// family): a free bar heated by dT takes the strain alpha dT exactly with zero stress, a bar held
// axially at both ends takes sigma_xx = -E alpha dT, and cooling back returns to zero, for the
// built-in C3D8, C3D20, C3D20R, C3D8I and the C3D21 plug-in. A linear temperature field bends a
// free C3D20 bar without stress. All exact up to round-off: tolerances 1e-9 relative.
#include <cmath>

#include <gtest/gtest.h>

#include "constraint_test_support.hpp"

namespace styk {
namespace {

constexpr double kYoung = 2.0e5;
constexpr double kPoisson = 0.3;
constexpr double kAlpha = 1.2e-5;
constexpr double kInitial = 20.0;  // *INITIAL CONDITIONS
constexpr double kHot = 120.0;     // *TEMPERATURE of the heating step
constexpr double kLength = 4.0;    // bar [0, 4] x [0, 1] x [0, 1]

// 4 x 2 x 2 elements (two across, so that C3D20R has no hourglass mode) with skewed interior
// x planes, so the elements are not parallelepipeds.
Model bar(const ElementRegistry& registry, const std::string& type) {
  test::HexModelBuilder builder(registry, kYoung, kPoisson);
  const double planes[5] = {0.0, 0.9, 2.1, 2.9, kLength};
  auto x_at = [&](int i, double y, double z) {
    const bool interior = i > 0 && i < 4;
    return planes[i] + (interior ? 0.15 * (y - 0.5) + 0.1 * (z - 0.5) : 0.0);
  };
  // Corners 1-4 counter-clockwise seen from +z, 5-8 above them.
  const int dx[4] = {0, 1, 1, 0};
  const int dy[4] = {0, 0, 1, 1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        test::HexCorners c;
        for (int top = 0; top < 2; ++top)
          for (int m = 0; m < 4; ++m) {
            const double y = 0.5 * (j + dy[m]), z = 0.5 * (k + top);
            c[4 * top + m] = {x_at(i + dx[m], y, z), y, z};
          }
        builder.add(type, c);
      }
  Model model = builder.finish();
  model.materials[0].expansion = kAlpha;
  model.materials[0].expansion_reference = 50.0;  // ZERO=: cancels out (thermal_load.hpp)
  for (int n = 0; n < model.node_count(); ++n)
    model.initial_temperatures.push_back({n, kInitial, {}});
  return model;
}

void set_temperature(Step& step, const Model& model, double t) {
  for (int n = 0; n < model.node_count(); ++n) step.temperatures.push_back({n, t, {}});
}

// ux = 0 at x = 0 (and at x = L when clamped); uy, uz just enough against rigid motion, all on
// planes y = 0 / z = 0 so that free expansion from the origin satisfies them.
void support(Model& model, bool clamp_far_end) {
  for (int n : test::nodes_at(model, 0, 0.0)) model.boundaries.push_back({n, 1, 0.0, {}});
  if (clamp_far_end)
    for (int n : test::nodes_at(model, 0, kLength)) model.boundaries.push_back({n, 1, 0.0, {}});
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    if (x[0] != 0.0) continue;
    if (x[1] == 0.0 && (x[2] == 0.0 || x[2] == 1.0)) model.boundaries.push_back({n, 2, 0.0, {}});
    if (x[2] == 0.0 && (x[1] == 0.0 || x[1] == 1.0)) model.boundaries.push_back({n, 3, 0.0, {}});
  }
}

class HeatedBar : public ::testing::TestWithParam<const char*> {
 protected:
  std::unique_ptr<test::FullRegistry> registry_ = test::registry_with_plugins();
};

TEST_P(HeatedBar, FreeBarStrainsAlphaDtWithoutStress) {
  ASSERT_TRUE(registry_->diagnostics.empty());
  Model model = bar(registry_->registry, GetParam());
  support(model, false);
  set_temperature(model.steps[0], model, kHot);
  const Results results = run_static_analysis(model, registry_->registry, {}, nullptr, nullptr);
  const IncrementResult& r = results.increments.at(0);
  const double strain = kAlpha * (kHot - kInitial);
  for (int n = 0; n < model.node_count(); ++n)
    for (int d = 0; d < 3; ++d)
      ASSERT_NEAR(r.U[n][d], strain * model.coords[n][d], 1e-9 * strain * kLength) << n;
  for (const Tensor6& e : r.E)
    for (int c = 0; c < 6; ++c) ASSERT_NEAR(e[c], c < 3 ? strain : 0.0, 1e-9 * strain);
  for (const Tensor6& s : r.S)
    for (int c = 0; c < 6; ++c) ASSERT_NEAR(s[c], 0.0, 1e-9 * kYoung * strain);
  for (const Vec3& rf : r.RF)
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(rf[d], 0.0, 1e-9 * kYoung * strain);
}

TEST_P(HeatedBar, ClampedBarStressIsMinusEAlphaDt) {
  Model model = bar(registry_->registry, GetParam());
  support(model, true);
  set_temperature(model.steps[0], model, kHot);
  const Results results = run_static_analysis(model, registry_->registry, {}, nullptr, nullptr);
  const IncrementResult& r = results.increments.at(0);
  const double strain = kAlpha * (kHot - kInitial);
  const double sigma = -kYoung * strain;
  for (const Tensor6& s : r.S)
    for (int c = 0; c < 6; ++c) ASSERT_NEAR(s[c], c == 0 ? sigma : 0.0, 1e-9 * std::abs(sigma));
  // The wall at x = L pushes back with sigma * A (A = 1).
  double wall = 0.0;
  for (int n : test::nodes_at(model, 0, kLength)) wall += r.RF[n][0];
  EXPECT_NEAR(wall, sigma, 1e-9 * std::abs(sigma));
}

TEST_P(HeatedBar, HeatingThenCoolingBackReturnsToZero) {
  Model model = bar(registry_->registry, GetParam());
  support(model, true);
  set_temperature(model.steps[0], model, kHot);
  Step cool = model.steps[0];
  cool.temperatures.clear();
  set_temperature(cool, model, kInitial);  // OP=MOD back to the initial temperature
  Step reset = model.steps[0];
  reset.temperatures.clear();
  reset.temperature_op_new = true;  // OP=NEW without data: initial temperatures
  Step again = model.steps[0];      // heats again (the values carry over from here on)
  model.steps.push_back(cool);
  model.steps.push_back(reset);
  model.steps.push_back(again);
  const Results results = run_static_analysis(model, registry_->registry, {}, nullptr, nullptr);
  ASSERT_EQ(results.increments.size(), 4u);
  const double sigma = -kYoung * kAlpha * (kHot - kInitial);
  for (int k : {1, 2})
    for (const Tensor6& s : results.increments[k].S)
      for (int c = 0; c < 6; ++c) ASSERT_EQ(s[c], 0.0) << "step " << k + 1;
  EXPECT_NEAR(results.increments[0].S[0][0], sigma, 1e-9 * std::abs(sigma));
  EXPECT_NEAR(results.increments[3].S[0][0], sigma, 1e-9 * std::abs(sigma));
}

INSTANTIATE_TEST_SUITE_P(Elements, HeatedBar,
                         ::testing::Values("C3D8", "C3D20", "C3D20R", "C3D8I", "C3D21"));

// T = T0 + g y in a free straight C3D20 bar: the thermal strain alpha g y (all three normal
// components) is compatible (pure bending, quadratic displacements), so the stress vanishes.
TEST(ThermalLoad, LinearTemperatureBendsFreeBarWithoutStress) {
  const auto registry = test::registry_with_plugins();
  test::HexModelBuilder builder(registry->registry, kYoung, kPoisson);
  for (int i = 0; i < 4; ++i)
    builder.add("C3D20", {Vec3{1.0 * i, 0, 0}, Vec3{i + 1.0, 0, 0}, Vec3{i + 1.0, 1, 0},
                          Vec3{1.0 * i, 1, 0}, Vec3{1.0 * i, 0, 1}, Vec3{i + 1.0, 0, 1},
                          Vec3{i + 1.0, 1, 1}, Vec3{1.0 * i, 1, 1}});
  Model model = builder.finish();
  model.materials[0].expansion = kAlpha;
  // ux = 0 on x = 0; uy at (0,0,0) and (0,0,1); uz at (0,0,0): statically determinate for the
  // lateral motions, so the bending (which also twists the section's corners) stays free.
  for (int n : test::nodes_at(model, 0, 0.0)) {
    model.boundaries.push_back({n, 1, 0.0, {}});
    const Vec3& x = model.coords[n];
    if (x[1] == 0.0 && (x[2] == 0.0 || x[2] == 1.0)) model.boundaries.push_back({n, 2, 0.0, {}});
    if (x[1] == 0.0 && x[2] == 0.0) model.boundaries.push_back({n, 3, 0.0, {}});
  }
  const double gradient = 50.0;
  for (int n = 0; n < model.node_count(); ++n)
    model.steps[0].temperatures.push_back({n, gradient * model.coords[n][1], {}});
  const Results results = run_static_analysis(model, registry->registry, {}, nullptr, nullptr);
  const IncrementResult& r = results.increments.at(0);
  const double scale = kYoung * kAlpha * gradient;
  for (const Tensor6& s : r.S)
    for (int c = 0; c < 6; ++c) ASSERT_NEAR(s[c], 0.0, 1e-9 * scale);
  // Exact field u = alpha g (x y, (y^2 - x^2 - z^2) / 2, y z) plus the rigid rotation the
  // supports impose: uy(L, 0, 0) = -alpha g L^2 / 2.
  const std::vector<int> end = test::nodes_at(model, 0, kLength);
  for (int n : end) {
    if (model.coords[n][1] != 0.0 || model.coords[n][2] != 0.0) continue;
    EXPECT_NEAR(r.U[n][1], -kAlpha * gradient * kLength * kLength / 2.0,
                1e-9 * kAlpha * gradient * kLength * kLength);
  }
}

TEST(ThermalLoad, TemperatureChangeWithoutExpansionIsAnError) {
  const auto registry = test::registry_with_plugins();
  Model model = bar(registry->registry, "C3D8");
  model.materials[0].expansion.reset();
  model.materials[0].where = {"bar.inp", 7};
  support(model, false);
  set_temperature(model.steps[0], model, kHot);
  try {
    run_static_analysis(model, registry->registry, {}, nullptr, nullptr);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("EXPANSION"), std::string::npos) << error.message();
  }
}

}  // namespace
}  // namespace styk
