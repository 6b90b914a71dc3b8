// SPEC §3.2 contact tests, models built with the mesher (blocks, revolve, C3D21/C3D28 layer
// conversion) and solved through run_static_analysis with exact (Lagrange multiplier) contact.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include <gtest/gtest.h>

#include "contact_model_kit.hpp"
#include "contact_spec_models.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/merge.hpp"
#include "styk/solver/analysis.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

class ContactSpec32 : public test::PluginRegistrySuite<> {};

void convert_layer(mesher::Mesh& mesh, const std::string& type, const std::string& surface) {
  if (type == "C3D21") mesher::convert_elements(mesh, test::shared_registry(), "C3D21", surface);
  if (type == "C3D28") mesher::convert_elements(mesh, test::shared_registry(), "C3D28", surface);
}

// ---------------------------------------------------------------------------------------------
// §3.2.2 Two concentric cylinders (Lamé), plane strain, length 1: inner r 1-2 (E = 10, nu = 0.3),
// outer r 2-3 (E = 20, nu = 0.2), internal pressure 5, external 3. Quarter model, 3 radial x 16
// around x 1 axial elements per cylinder = 96 elements, 16 + 16 element faces in contact
// (C3D21/C3D28 layers on both sides, matching nodes); symmetry ux = 0 on x = 0, uy = 0 on y = 0,
// plane strain by uz = 0 everywhere. SPEC: analytic contact pressure 3.294 (uniform); thesis 3.3
// with C3D21 and C3D28 (Lamé to more digits: 3.29396). Asserted: every slave node's pressure
// within 0.05 % of 3.294 (measured C3D21 3.2938 ... 3.2941, C3D28 3.2939 ... 3.2941; with the
// nodal area A_i instead of its projection on the normal, docs/contact.md "Nodal area", the
// corner nodes were 0.048 % high and the mid-edge nodes 0.024 % low by the formula there,
// alpha = 5.6 deg).
Model concentric_cylinders(const std::string& type) {
  mesher::Mesh mesh;
  auto ring = [&](double r0, double r1, const std::string& elset) {
    // Profile (u = axial, v = radial) in the xz-plane, revolved about z: right-handed.
    const mesher::PatchMap profile =
        mesher::quad_map({{r0, 0, 0}, {r0, 0, 1}, {r1, 0, 1}, {r1, 0, 0}});
    mesher::BlockSpec spec;
    spec.type = "C3D20";
    spec.divisions = {1, 3, 16};
    spec.elset = elset;
    return mesher::mesh_block(mesh, mesher::revolve(profile, {0, 0, 0}, {0, 0, 1}, 0.0, kPi / 2),
                              spec);
  };
  const mesher::Block inner = ring(1.0, 2.0, "INNER");
  const mesher::Block outer = ring(2.0, 3.0, "OUTER");
  mesh.add_to_surface("INNER_OUT", inner.side_faces(1, 1));
  mesh.add_to_surface("OUTER_IN", outer.side_faces(1, -1));
  mesh.add_to_surface("P_IN", inner.side_faces(1, -1));
  mesh.add_to_surface("P_OUT", outer.side_faces(1, 1));
  convert_layer(mesh, type, "INNER_OUT");
  convert_layer(mesh, type, "OUTER_IN");
  Model model = test::contact_model(mesh, {{"INNER", 10.0, 0.3}, {"OUTER", 20.0, 0.2}});
  test::add_contact_pair(model, "OUTER_IN", "INNER_OUT", "SMOOTH", std::nullopt);
  test::add_pressure(model, "P_IN", 5.0);
  test::add_pressure(model, "P_OUT", 3.0);
  test::fix(model, test::nodes_where(model, [](const Vec3&) { return true; }), {3});
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return std::abs(x[0]) < 1e-9; }),
            {1});
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return std::abs(x[1]) < 1e-9; }),
            {2});
  return model;
}

void expect_lame_pressure(const ElementRegistry& registry, const std::string& type) {
  const Model model = concentric_cylinders(type);
  ASSERT_EQ(model.element_count(), 96);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  ASSERT_FALSE(r.contact.empty());
  double mean = 0.0, low = INFINITY, high = -INFINITY;
  for (const ContactNodeResult& c : r.contact) {
    EXPECT_NE(c.status, ContactStatus::Open);
    EXPECT_NEAR(c.pressure, 3.294, 5e-4 * 3.294) << type << " node " << model.node_ids[c.node];
    EXPECT_NEAR(c.gap, 0.0, 1e-12);
    mean += c.pressure / static_cast<double>(r.contact.size());
    low = std::min(low, c.pressure);
    high = std::max(high, c.pressure);
  }
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-8);
  ::testing::Test::RecordProperty(type + "_mean_pressure", std::to_string(mean));
  ::testing::Test::RecordProperty(type + "_low", std::to_string(low));
  ::testing::Test::RecordProperty(type + "_high", std::to_string(high));
}

TEST_F(ContactSpec32, ConcentricCylindersC3D21) { expect_lame_pressure(registry(), "C3D21"); }
TEST_F(ContactSpec32, ConcentricCylindersC3D28) { expect_lame_pressure(registry(), "C3D28"); }

// ---------------------------------------------------------------------------------------------
// §3.2.3 Two cantilevers in contact with friction (Zhong 1993): each beam L = 1, h = 0.1 (stacked,
// total 0.2), width 0.1, 40 x 2 elements each (one across), E = 2e11, nu = 0, pressure 2e6 on the
// top of the upper beam, left ends clamped. The facing element rows are C3D21 (contact face S1),
// the others C3D20; matching nodes (node-to-node), one load increment. SPEC table, C3D21 tip
// deflection of the upper beam: mu = 0: -7.7982e-3, 0.2: -7.5329e-3, 0.75: -6.8456e-3,
// 1: -6.5493e-3, 10: -1.9771e-3, 100: -1.9373e-3 — asserted within 5 %; tied (ROUGH) within 4 %
// of the tied-beam theory 1.875e-3; |deflection| decreasing as mu grows.
struct BeamResult {
  double tip = 0.0;
  int slipping = 0, sticking = 0;
};

BeamResult two_cantilevers(const ElementRegistry& registry, std::optional<Friction> friction) {
  const Model model = test::two_cantilevers_model(friction);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  BeamResult out;
  int count = 0;
  for (int n : test::nodes_of(model, "UPPER"))
    if (std::abs(model.coords[n][0] - 1.0) < 1e-9) {
      out.tip += r.U[n][2];
      ++count;
    }
  out.tip /= count;
  for (const ContactNodeResult& c : r.contact) {
    out.slipping += c.status == ContactStatus::Slip;
    out.sticking += c.status == ContactStatus::Stick;
  }
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-8);
  return out;
}

TEST_F(ContactSpec32, TwoCantileversWithFrictionC3D21) {
  const std::vector<std::pair<double, double>> table = {{0.0, -7.7982e-3},  {0.2, -7.5329e-3},
                                                        {0.75, -6.8456e-3}, {1.0, -6.5493e-3},
                                                        {10.0, -1.9771e-3}, {100.0, -1.9373e-3}};
  double previous = -INFINITY;
  for (const auto& [mu, thesis] : table) {
    const BeamResult r = two_cantilevers(registry(), test::coulomb(mu));
    std::printf("mu = %g: tip %.5e (thesis C3D21 %.5e), %d slip, %d stick\n", mu, r.tip, thesis,
                r.slipping, r.sticking);
    EXPECT_NEAR(r.tip, thesis, 0.05 * std::abs(thesis)) << "mu = " << mu;
    EXPECT_GT(r.tip, previous) << "mu = " << mu;  // less deflection with more friction
    previous = r.tip;
  }
  Friction rough;
  rough.kind = Friction::Kind::Rough;
  const BeamResult tied = two_cantilevers(registry(), rough);
  std::printf("tied: tip %.5e (beam theory -1.875e-3)\n", tied.tip);
  EXPECT_NEAR(tied.tip, -1.875e-3, 0.04 * 1.875e-3);
  EXPECT_GE(tied.tip, previous - 1e-12);
}

// ---------------------------------------------------------------------------------------------
// §3.2.4 Elastic punch on an elastic half-space with friction (Klarbring), quarter model: punch
// 10 x 10 x 10 (4 x 4 x 4 elements, the contact row C3D21), half-space 50 x 50 x 50 (4 x 4
// elements under the punch, C3D21 contact row, then 5 elements graded 4:1 outwards and 8 graded
// 6:1 in depth, C3D20), E = 2e5, nu = 0.3, bottom fixed, symmetry ux = 0 on x = 0 and uy = 0 on
// y = 0, P = 1000 downwards at the punch's top corner node on the axis. The punch is held in z
// only by the contact. 9 x 9 = 81 contact node pairs, one load increment.
struct PunchResult {
  Model model;
  IncrementResult result;
};

PunchResult punch(const ElementRegistry& registry, const Friction& friction) {
  PunchResult out;
  Model& model = out.model;
  model = test::punch_model(friction);
  EXPECT_EQ(model.steps[0].cloads.size(), 1u);
  Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  out.result = std::move(results.increments.back());
  EXPECT_EQ(out.result.contact.size(), 81u);
  EXPECT_LT(out.result.contact_equilibrium.relative_residual, 1e-8);
  return out;
}

Vec3 global_slip(const ContactNodeResult& c) {
  Vec3 s;
  for (int d = 0; d < 3; ++d) s[d] = c.slip[0] * c.t1[d] + c.slip[1] * c.t2[d];
  return s;
}

int slipping(const PunchResult& r) {
  int count = 0;
  for (const ContactNodeResult& c : r.result.contact) count += c.status == ContactStatus::Slip;
  return count;
}

// Isotropic mu = 0.04: every node slips except the one on the axis; slips symmetric about the
// diagonal x = y to 1e-6 relative; the slip at the outer contact corner within 10 % of the
// thesis' 4.03e-4 (C3D21) in both directions.
TEST_F(ContactSpec32, PunchOnHalfSpaceIsotropicFriction) {
  const PunchResult r = punch(registry(), test::coulomb(0.04));
  const Model& model = r.model;
  std::map<std::pair<long, long>, Vec3> slip_at;
  double largest = 0.0;
  for (const ContactNodeResult& c : r.result.contact) {
    const Vec3& x = model.coords[c.node];
    const bool on_axis = std::abs(x[0]) < 1e-9 && std::abs(x[1]) < 1e-9;
    EXPECT_EQ(c.status, on_axis ? ContactStatus::Stick : ContactStatus::Slip)
        << "node at " << x[0] << ", " << x[1];
    EXPECT_NEAR(c.gap, 0.0, 1e-12);
    slip_at[{std::lround(x[0] * 1000), std::lround(x[1] * 1000)}] = global_slip(c);
    largest = std::max(largest, std::hypot(global_slip(c)[0], global_slip(c)[1]));
  }
  for (const auto& [at, s] : slip_at) {
    const Vec3& mirror = slip_at.at({at.second, at.first});
    EXPECT_NEAR(s[0], mirror[1], 1e-6 * largest);
    EXPECT_NEAR(s[1], mirror[0], 1e-6 * largest);
  }
  const Vec3& corner = slip_at.at({10000, 10000});
  std::printf("mu = 0.04: corner slip %.4e, %.4e (thesis C3D21 4.03e-4), %d slipping\n", corner[0],
              corner[1], slipping(r));
  EXPECT_NEAR(std::abs(corner[0]), 4.03e-4, 0.1 * 4.03e-4);
  EXPECT_NEAR(std::abs(corner[1]), 4.03e-4, 0.1 * 4.03e-4);
}

// Anisotropic mu1 = 0.04 (x), mu2 = 0.4 (y): the slip is dominated by direction 1 — summed over
// the slipping nodes |slip_1| exceeds 3 x |slip_2| — and at every slipping node off the symmetry
// planes the slip direction turns towards direction 1 against the isotropic mu = 0.04 solution
// (|s1| / |s2| larger). Near x = 0 a node may still slip more along 2 (its slip_1 vanishes on the
// plane), which is why the comparison is made against the isotropic solution.
TEST_F(ContactSpec32, PunchOnHalfSpaceAnisotropicFriction) {
  Friction f;
  f.kind = Friction::Kind::Anisotropic;
  f.mu = 0.04;
  f.mu2 = 0.4;
  f.orientation = "XY";
  const PunchResult r = punch(registry(), f);
  const PunchResult iso = punch(registry(), test::coulomb(0.04));
  double sum1 = 0.0, sum2 = 0.0;
  int checked = 0;
  for (std::size_t i = 0; i < r.result.contact.size(); ++i) {
    const ContactNodeResult& c = r.result.contact[i];
    if (c.status != ContactStatus::Slip) continue;
    const Vec3 s = global_slip(c);
    sum1 += std::abs(s[0]);
    sum2 += std::abs(s[1]);
    const Vec3& x = r.model.coords[c.node];
    if (std::abs(x[0]) < 1e-9 || std::abs(x[1]) < 1e-9) continue;
    ASSERT_EQ(iso.result.contact[i].node, c.node);
    const Vec3 t = global_slip(iso.result.contact[i]);
    EXPECT_GT(std::abs(s[0]) / std::abs(s[1]), std::abs(t[0]) / std::abs(t[1]))
        << "node at " << x[0] << ", " << x[1];
    ++checked;
  }
  std::printf("anisotropic: sum |slip_1| %.4e, sum |slip_2| %.4e, %d slipping\n", sum1, sum2,
              slipping(r));
  EXPECT_GT(sum1, 3.0 * sum2);
  EXPECT_GT(checked, 0);
}

// mu = 0.04, 0.4, 0.6, 0.7, 0.75: progressively fewer slipping nodes (SPEC: only three at 0.75;
// measured 80, 78, 66, 44, 24). The thesis' three is not a target: the exact Coulomb law slips a
// mesh-converged share of the area (C3D21 n = 4: 23 of 81, n = 8: 90 of 289; C3D28 similar), the
// tied solution already has |tau|/p > 0.75 at 25 nodes, and CalculiX's penalty friction gives 2
// slipping nodes with its default stick slope but 12 / 15 with stick slopes 1e6 / 1e8: a few
// slipping nodes is what a soft (elastic) stick gives (docs/contact.md, "SPEC §3.2.4 at
// mu = 0.75").
TEST_F(ContactSpec32, PunchSlipZoneShrinksWithFriction) {
  int previous = 1 << 30;
  for (double mu : {0.04, 0.4, 0.6, 0.7, 0.75}) {
    const int count = slipping(punch(registry(), test::coulomb(mu)));
    std::printf("mu = %g: %d slipping nodes\n", mu, count);
    EXPECT_LE(count, previous) << "mu = " << mu;
    previous = count;
  }
}

}  // namespace
}  // namespace styk
