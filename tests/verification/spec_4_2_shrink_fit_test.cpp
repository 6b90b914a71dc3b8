// SPEC §4.2 shrink fit: the interference comes from heating the shaft (thermal load in the contact
// path), step 2 pushes the sleeve axially from the heated, fitted state (state carried over).
// Model: tests/verification/spec_4_2_shrink_fit_model.hpp (quarter, solid shaft Ø20 x 60, sleeve
// Ø20/Ø30 x 20 centred, node-to-node interface with C3D21 or C3D28 layers, mu = 0.2).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "spec_4_2_shrink_fit_model.hpp"
#include "styk/solver/analysis.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk {
namespace {

class ShrinkFitSpec42 : public test::PluginRegistrySuite<> {};

// Prints the solver's log when STYK_TEST_LOG is set (for looking at the iteration).
class LogSink : public ProgressSink {
 public:
  void begin(const std::string&) override {}
  void end(const std::string&, double) override {}
  void info(const std::string& message) override {
    if (std::getenv("STYK_TEST_LOG") != nullptr) std::fprintf(stderr, "%s\n", message.c_str());
  }
};

double radius(const Vec3& x) { return std::hypot(x[0], x[1]); }

// Contact pressure per interface ring z (rounded), averaged around the circumference.
std::map<double, double> pressure_by_height(const Model& model, const IncrementResult& r) {
  std::map<double, std::pair<double, int>> sums;
  for (const ContactNodeResult& c : r.contact) {
    const double z = std::round(model.coords[c.node][2] * 1e6) / 1e6;
    sums[z].first += c.pressure;
    sums[z].second += 1;
  }
  std::map<double, double> out;
  for (const auto& [z, s] : sums) out[z] = s.first / s.second;
  return out;
}

struct ShaftEnd {
  double elongation = 0.0;        // mean u_z of the end face z = 60
  double diametral_growth = 0.0;  // 2 u_r at r = 10, z = 60 (mean around)
};

ShaftEnd shaft_end(const Model& model, const IncrementResult& r) {
  ShaftEnd out;
  int n_end = 0, n_rim = 0;
  for (int n : test::nodes_of(model, "SHAFT")) {
    const Vec3& x = model.coords[n];
    if (std::abs(x[2] - 60.0) > 1e-9) continue;
    out.elongation += r.U[n][2];
    ++n_end;
    if (std::abs(radius(x) - 10.0) < 1e-9) {
      out.diametral_growth += 2.0 * (r.U[n][0] * x[0] + r.U[n][1] * x[1]) / radius(x);
      ++n_rim;
    }
  }
  out.elongation /= n_end;
  out.diametral_growth /= n_rim;
  return out;
}

// Step 1 (heating), frictionless (SPEC §4.2: step 1 with mu 0 ... 0.4; Tab 4.1 is the grip
// without axial friction, see the elongation note), the sleeve held axially at one node (its
// reaction is asserted to vanish). Expected:
// - pressure away from the sleeve ends (mean over the rings 25 <= z <= 35) inside the Lamé band
//   of SPEC §4.2 (radial interference alpha dT r = 0.02; plane stress p = E delta (c^2 - b^2) /
//   (2 b c^2) = 111.1, plane strain 122). Which one: plane stress. The sleeve is a short free
//   ring (sigma_z = 0) and the frictionless shaft is free to lengthen (its end z = 60 is free),
//   so nothing builds an axial stress; plane strain would need eps_z = 0. The edge peaks take a
//   share of the load, so the middle may sit a little below 111.1: asserted within 1 % of 111.1
//   (measured 110.8 with both layers);
// - peaks at both sleeve edges: the pressure of the edge rings z = 20 and z = 40 above the mid
//   pressure (the thesis' contour plot);
// - Tab 4.1, shaft end (z = 60, z = 0 held axially): elongation C3D21 0.1268 / C3D28 0.1258 and
//   diametral growth 0.040096 / 0.04018; asserted within 1 % (our mesh is not the thesis' 3072
//   elements). The free values are 0.12 and 0.04; the grip adds the Poisson elongation of the
//   squeezed length, nu 2 p / E x 20 = 0.0073, which the elongation check sees (5 %);
// - contact closed everywhere, gaps at round-off, global equilibrium < 1e-8.
struct Ring {
  double mid = 0.0, low_edge = 0.0, high_edge = 0.0;
};

Ring expect_heated_fit(const Model& model, const IncrementResult& r, const std::string& type,
                       double elongation, double growth) {
  Ring out;
  EXPECT_FALSE(r.contact.empty());
  for (const ContactNodeResult& c : r.contact) {
    EXPECT_NE(c.status, ContactStatus::Open) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.gap, 0.0, 1e-10);
  }
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-8);
  const std::map<double, double> rings = pressure_by_height(model, r);
  int count = 0;
  for (const auto& [z, p] : rings)
    if (z >= 25.0 - 1e-9 && z <= 35.0 + 1e-9) {
      out.mid += p;
      ++count;
    }
  out.mid /= count;
  out.low_edge = rings.begin()->second;
  out.high_edge = rings.rbegin()->second;
  for (const auto& [z, p] : rings) std::printf("%s z = %6.3f  p = %8.3f\n", type.c_str(), z, p);
  const ShaftEnd end = shaft_end(model, r);
  std::printf("%s mid pressure %.3f, edges %.3f / %.3f, elongation %.5f, diametral growth %.6f\n",
              type.c_str(), out.mid, out.low_edge, out.high_edge, end.elongation,
              end.diametral_growth);
  EXPECT_NEAR(out.mid, 111.1, 0.01 * 111.1);
  EXPECT_GT(out.low_edge, out.mid);   // z = 20
  EXPECT_GT(out.high_edge, out.mid);  // z = 40
  EXPECT_NEAR(end.elongation, elongation, 0.01 * elongation);
  EXPECT_NEAR(end.diametral_growth, growth, 0.01 * growth);
  // The sleeve's axial hold takes nothing (frictionless, determinate).
  double sleeve_rf = 0.0;
  for (int n : test::nodes_of(model, "SLEEVE")) sleeve_rf += r.RF[n][2];
  EXPECT_LT(std::abs(sleeve_rf), 1e-8 * out.mid * 100.0) << "sleeve axial reaction";
  ::testing::Test::RecordProperty(type + "_mid_pressure", std::to_string(out.mid));
  return out;
}

void heated_fit(const ElementRegistry& registry, const std::string& type, double elongation,
                double growth) {
  test::ShrinkFitMesh spec;
  spec.contact_type = type;
  spec.mu = 0.0;
  spec.hold_sleeve = true;
  const Model model = test::shrink_fit_thermal_model(spec);
  LogSink log;
  const Results results = run_static_analysis(model, registry, SolveOptions{}, &log, nullptr);
  ASSERT_EQ(results.increments.size(), 1u);
  expect_heated_fit(model, results.increments.back(), type, elongation, growth);
}

TEST_F(ShrinkFitSpec42, HeatedShaftC3D21) { heated_fit(registry(), "C3D21", 0.1268, 0.040096); }
TEST_F(ShrinkFitSpec42, HeatedShaftC3D28) { heated_fit(registry(), "C3D28", 0.1258, 0.04018); }

// Two steps with friction mu = 0.2 (SPEC §4.2 step 2A): the sleeve is held axially by friction
// only (a body held by contact). Step 1 heats the shaft; step 2 puts 52.5 MPa on the sleeve's top
// annulus in automatic increments from the heated, fitted state. Expected:
// - step 1: the fit closed, pressure in the band of the frictionless fit +- 10 % (axial friction
//   against the shaft's thermal elongation redistributes it);
// - step 2: the contact forces on the sleeve balance the push to 1e-8 (the applied load as the
//   solver integrated it: the quadratic faces' area differs from pi (15^2 - 10^2) / 4 by ~3e-6);
//   the fit stays closed and the mid pressure within 10 % of step 1's; the push (5154 N on the
//   quarter) is below the axial capacity mu p A of the fit; the state is carried: the shaft end
//   keeps its thermal elongation less the shortening of the shaft between the support and the
//   sleeve by the transmitted force F: F/(E A) x L, L between 20 (force transferred at the
//   sleeve's near end) and 40 (at its far end), A = pi 10^2 / 4.
TEST_F(ShrinkFitSpec42, HeatedShaftThenAxialPushWithFriction) {
  test::ShrinkFitMesh spec;
  spec.contact_type = "C3D21";
  spec.mu = 0.2;
  spec.push = 52.5;
  const Model model = test::shrink_fit_thermal_model(spec);
  LogSink log;
  const Results results = run_static_analysis(model, registry(), SolveOptions{}, &log, nullptr);
  const IncrementResult* heated = nullptr;
  for (const IncrementResult& r : results.increments)
    if (r.step == 1) heated = &r;
  ASSERT_NE(heated, nullptr);
  for (const ContactNodeResult& c : heated->contact) EXPECT_NE(c.status, ContactStatus::Open);
  const std::map<double, double> before = pressure_by_height(model, *heated);
  const double mid_before = before.at(30.0);
  EXPECT_GT(mid_before, 0.9 * 111.0);
  EXPECT_LT(mid_before, 1.1 * 122.0);

  const IncrementResult& pushed = results.increments.back();
  ASSERT_EQ(pushed.step, 2);
  EXPECT_GT(pushed.increment, 1);  // automatic increments (initial 0.25)
  EXPECT_LT(pushed.contact_equilibrium.relative_residual, 1e-8);
  constexpr double kPi = 3.14159265358979323846;
  const double push = 52.5 * kPi * (15.0 * 15.0 - 10.0 * 10.0) / 4.0;
  double axial = 0.0;
  int slipping = 0;
  for (const ContactNodeResult& c : pushed.contact) {
    EXPECT_NE(c.status, ContactStatus::Open);
    axial += c.force[2];
    slipping += c.status == ContactStatus::Slip;
  }
  // Contact forces on the sleeve (slave) hold it against the push (-z): they point +z.
  const double applied = -pushed.contact_equilibrium.applied[2];
  EXPECT_NEAR(applied, push, 1e-5 * push);
  EXPECT_NEAR(axial, applied, 1e-8 * applied);
  const double mid_after = pressure_by_height(model, pushed).at(30.0);
  EXPECT_NEAR(mid_after, mid_before, 0.1 * mid_before);
  const double capacity = 0.2 * mid_before * 2.0 * kPi * 10.0 * 20.0 / 4.0;
  EXPECT_LT(push, capacity);
  const double shortening =
      shaft_end(model, *heated).elongation - shaft_end(model, pushed).elongation;
  const double per_length = push / (2e5 * kPi * 100.0 / 4.0);
  EXPECT_GT(shortening, 20.0 * per_length);
  EXPECT_LT(shortening, 40.0 * per_length);
  std::printf(
      "push %.1f N (capacity ~%.0f N): %d of %zu nodes slip, mid pressure %.2f -> %.2f, "
      "shortening %.5f (%.1f x F/EA), %d increments in step 2\n",
      push, capacity, slipping, pushed.contact.size(), mid_before, mid_after, shortening,
      shortening / per_length, pushed.increment);
}

}  // namespace
}  // namespace styk
