// The SPEC §4 joint reports (`styk study <joint>`, docs/joints.md) on the coarse meshes
// (JointOptions::coarse, the meshes of the joints' other tests): the same code that writes the
// committed reports at the builders' default densities, so every headline figure those reports
// quote comes from a tested path. Each test asserts
// - the physics against SPEC's reference (hand formula or the thesis' value) with the tolerance
//   the coarse mesh allows, stated at the check; and
// - the coarse figures themselves (measured 2026-11-26; the shrink fit's contact pressures again
//   2026-11-27, 0.75 % lower with the nodal area projected on the normal: its coarse quarter
//   has 4 elements around, docs/contact.md "Nodal area") to 0.5 %: the mesh and the loads are
//   fixed and the solve deterministic, so a change means the mechanics changed (contact iterations
//   end at the active set's 1e-9; 0.5 % leaves room for a different but converged active-set path).
// The pages are written once (conical fit, the quickest) and checked to list every figure, table
// and chart.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/studies/joints/joint_report.hpp"

namespace styk {
namespace {

studies::JointReport coarse_report(const std::string& joint) {
  const auto registry = test::registry_with_plugins();
  studies::JointOptions options;
  options.coarse = true;
  studies::JointReport report = studies::run_joint_study(joint, registry->registry, options);
  for (const studies::Headline& h : report.headlines)
    std::printf("%s %s = %.6g %s\n", joint.c_str(), h.key.c_str(), h.value, h.unit.c_str());
  return report;
}

void expect_measured(const studies::JointReport& r, const std::string& key, double measured) {
  EXPECT_NEAR(r.figure(key), measured, 0.005 * std::abs(measured)) << key;
}

// SPEC §4.2. Tab 4.1 (C3D21): elongation 0.1268, diametral growth 0.040096, for the frictionless
// heating; the coarse quarter (4 elements around, 4 along the fit) within 0.5 % of both, the
// pressure at mid-sleeve within 1 % of the plane-stress Lamé value 111.1 MPa (the short sleeve is
// free axially), and peaks at the sleeve's edges (edge > mid). With mu = 0.2 during the heating
// the shaft's growth under the sleeve is held: shorter elongation (asserted below the
// frictionless one). Axial capacity after the 72 MPa push inside the hand band 27.9-30.7 kN
// (mu pi d l p, p = 111-122 MPa); model B's torque at full slip and at 1.5 deg inside
// 559-614 N m (mu pi d^2 l p / 2).
// Notched variants I and II (SPEC §4.2, Fig 4.20-4.23: geometry lost, no published number;
// stand-ins: I a relief groove in each end face of the sleeve, II the sleeve turned down at its
// ends): both relieve the fit's edge, so the edge pressure and the largest pressure along the fit
// of each lie below the plain fit's (asserted), and the figures are the measured coarse ones to
// 0.5 % like the rest.
TEST(JointReports, ShrinkFit) {
  const studies::JointReport r = coarse_report("shrink-fit");
  EXPECT_NEAR(r.figure("elongation"), 0.1268, 0.005 * 0.1268);
  EXPECT_NEAR(r.figure("diametral_growth"), 0.040096, 0.005 * 0.040096);
  EXPECT_NEAR(r.figure("pressure_mid"), 111.1, 0.01 * 111.1);
  EXPECT_GT(r.figure("pressure_edge"), r.figure("pressure_mid"));
  EXPECT_LT(r.figure("elongation_mu0.2"), r.figure("elongation"));
  EXPECT_GT(r.figure("axial_capacity"), 27.9);
  EXPECT_LT(r.figure("axial_capacity"), 30.7);
  for (const char* key : {"torque_full_slip", "torque_end"}) {
    EXPECT_GT(r.figure(key), 559.0) << key;
    EXPECT_LT(r.figure(key), 614.0) << key;
  }
  expect_measured(r, "elongation", 0.12681);
  expect_measured(r, "diametral_growth", 0.0400343);
  expect_measured(r, "pressure_mid", 110.830);
  expect_measured(r, "pressure_edge", 163.110);
  expect_measured(r, "pressure_max", 163.110);
  expect_measured(r, "elongation_mu0.2", 0.12472);
  expect_measured(r, "diametral_growth_mu0.2", 0.0400229);
  expect_measured(r, "pressure_mid_mu0.2", 127.118);
  expect_measured(r, "pressure_edge_mu0.2", 112.659);
  expect_measured(r, "axial_capacity", 28.5705);
  expect_measured(r, "torque_full_slip", 569.4);
  expect_measured(r, "torque_end", 568.9);
  for (const char* variant : {"_notchI", "_notchII"}) {
    EXPECT_LT(r.figure(std::string("pressure_edge") + variant), r.figure("pressure_edge"))
        << variant;
    EXPECT_LT(r.figure(std::string("pressure_max") + variant), r.figure("pressure_max")) << variant;
  }
  expect_measured(r, "shaft_mises", 126.469);
  expect_measured(r, "sleeve_mises", 294.752);
  expect_measured(r, "pressure_edge_notchI", 34.8793);
  expect_measured(r, "pressure_max_notchI", 132.121);
  expect_measured(r, "pressure_mid_notchI", 91.2934);
  expect_measured(r, "shaft_mises_notchI", 125.037);
  expect_measured(r, "sleeve_mises_notchI", 324.12);
  expect_measured(r, "pressure_edge_notchII", 108.653);
  expect_measured(r, "pressure_max_notchII", 111.952);
  expect_measured(r, "pressure_mid_notchII", 111.952);
  expect_measured(r, "shaft_mises_notchII", 123.521);
  expect_measured(r, "sleeve_mises_notchII", 310.519);
  EXPECT_EQ(r.tables.size(), 4u);
  EXPECT_EQ(r.charts.size(), 3u);
}

// SPEC §4.6 with pressure penetration. Published leak 16 MPa (15 kN) and 12.5-13 (10 kN): the
// ordering is asserted (10 kN leaks first), the 3.5 mm gasket leaks within one increment (1 MPa)
// of the 5 mm one ("gasket thickness has little effect"), and Rötscher's p_crit =
// 8 x 15.5 kN / 6857.8 mm^2 = 18.08 MPa to 0.01. The bolt force falls with p on this stand-in
// (the measured cause of the lower leak, docs/joints/bolted-flange.md): asserted negative.
// The candidates for that trend, each changed alone: it stays negative without pressure
// penetration and without the end-cap thrust (neither is its cause), and a thicker ring (30, 40
// instead of 20) makes it less negative and the leak pressure higher, towards the published 16
// MPa (the ring's stiffness is). Leak pressures are increments' pressures: to round-off.
TEST(JointReports, BoltedFlange) {
  const studies::JointReport r = coarse_report("bolted-flange");
  EXPECT_NEAR(r.figure("p_crit_roetscher"), 18.08, 0.01);
  EXPECT_GT(r.figure("leak_15kN"), 0.0);
  EXPECT_GT(r.figure("leak_10kN"), 0.0);
  EXPECT_LT(r.figure("leak_10kN"), r.figure("leak_15kN"));
  EXPECT_LE(std::abs(r.figure("leak_15kN_gasket35") - r.figure("leak_15kN")), 1.0 + 1e-9);
  EXPECT_LT(r.figure("bolt_force_change_8MPa"), 0.0);
  // The leak pressures are increments' pressures (step fraction x 24 MPa): to round-off.
  EXPECT_NEAR(r.figure("leak_15kN"), 12.0, 1e-6);
  EXPECT_NEAR(r.figure("leak_10kN"), 8.0, 1e-6);
  EXPECT_NEAR(r.figure("leak_15kN_gasket35"), 12.0, 1e-6);
  expect_measured(r, "bolt_force_change_8MPa", -2.0839);
  // The coarse neck has one element layer: mid-neck and corner are the same element.
  expect_measured(r, "gauge_mises", 122.29);
  expect_measured(r, "neck_corner_mises", 122.29);
  EXPECT_LT(r.figure("bolt_force_change_8MPa_no_penetration"), 0.0);
  EXPECT_LT(r.figure("bolt_force_change_8MPa_no_end_cap"), 0.0);
  EXPECT_GT(r.figure("bolt_force_change_8MPa_ring30"), r.figure("bolt_force_change_8MPa"));
  EXPECT_GT(r.figure("bolt_force_change_8MPa_ring40"), r.figure("bolt_force_change_8MPa_ring30"));
  EXPECT_GT(r.figure("leak_15kN_ring30"), r.figure("leak_15kN"));
  EXPECT_GE(r.figure("leak_15kN_ring40"), r.figure("leak_15kN_ring30"));
  EXPECT_LE(r.figure("leak_15kN_ring40"), 16.0 + 1e-9);
  expect_measured(r, "bolt_force_change_8MPa_no_penetration", -1.20391);
  expect_measured(r, "bolt_force_change_8MPa_no_end_cap", -1.7405);
  expect_measured(r, "bolt_force_change_8MPa_ring30", -0.790474);
  expect_measured(r, "bolt_force_change_8MPa_ring40", -0.165087);
  expect_measured(r, "bolt_force_change_8MPa_steel_gasket", -2.27345);
  EXPECT_NEAR(r.figure("leak_15kN_no_end_cap"), 16.0, 1e-6);
  EXPECT_NEAR(r.figure("leak_15kN_ring30"), 14.0, 1e-6);
  EXPECT_NEAR(r.figure("leak_15kN_ring40"), 15.0, 1e-6);
  EXPECT_NEAR(r.figure("leak_15kN_steel_gasket"), 11.0, 1e-6);
}

// SPEC §4.3: published 58 / 42 / 35 MPa for mu = 0 / 0.2 / 0.4. Asserted: the stress falls with
// mu, and it follows the wedge's normal force (Mises x (sin alpha + mu cos alpha) equal within
// 5 %, SPEC "The conical fit"); frictionless, N sin alpha = F exactly (1e-6), with friction
// N (sin alpha + mu cos alpha) >= F (sticking nodes carry less than mu N). The default mesh is
// the coarse one here (528 elements): the values are those tests/verification/
// spec_4_3_conical_fit_test.cpp asserts.
TEST(JointReports, ConicalFit) {
  const studies::JointReport r = coarse_report("conical-fit");
  EXPECT_GT(r.figure("mises_mu0"), r.figure("mises_mu0.2"));
  EXPECT_GT(r.figure("mises_mu0.2"), r.figure("mises_mu0.4"));
  EXPECT_LT(r.figure("mises_scaling_spread"), 1.05);
  EXPECT_NEAR(r.figure("wedge_ratio_mu0"), 1.0, 1e-6);
  EXPECT_GE(r.figure("wedge_ratio_mu0.2"), 1.0 - 1e-6);
  EXPECT_GE(r.figure("wedge_ratio_mu0.4"), 1.0 - 1e-6);
  expect_measured(r, "mises_mu0", 336.6);
  expect_measured(r, "mises_mu0.2", 65.58);
  expect_measured(r, "mises_mu0.4", 37.68);
  // The page lists every figure, chart and CSV file it writes.
  const std::string dir = ::testing::TempDir() + "joint_report_conical";
  std::filesystem::remove_all(dir);
  const studies::JointLayout layout = studies::joint_output_layout(dir, r.joint);
  studies::write_joint_report(r, "styk study conical-fit --coarse", "test machine", layout);
  std::ifstream in(layout.markdown);
  std::stringstream page;
  page << in.rdbuf();
  for (const studies::Headline& h : r.headlines)
    EXPECT_NE(page.str().find(h.label), std::string::npos) << h.label;
  for (const studies::DataTable& t : r.tables) {
    const std::string file = r.joint + "-" + t.name + ".csv";
    EXPECT_NE(page.str().find(file), std::string::npos) << file;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / file)) << file;
  }
  for (const studies::JointChart& c : r.charts) {
    const std::string file = r.joint + "-" + c.name + ".png";
    EXPECT_NE(page.str().find(file), std::string::npos) << file;
    EXPECT_GT(std::filesystem::file_size(std::filesystem::path(dir) / file), 10000u) << file;
  }
  std::filesystem::remove_all(dir);
}

// SPEC §4.4 as the 120 deg sector: the flanks carry the whole 1000 N m (3 x the sector's contact
// moment, to 1e-6), only the loaded flank of each spline closes (50 % of the slave nodes), the
// shaft outside the hub near the nominal torsion stress 16 M / (pi d^3) x sqrt 3 = 38.5 MPa at the
// root circle (published max ≈ 35; the element means within 10 % of the nominal: the root
// circle's splines add material), and the flank pressure far above the uniform hand value 36.6
// MPa (published 0-166).
TEST(JointReports, Spline) {
  const studies::JointReport r = coarse_report("spline");
  EXPECT_NEAR(r.figure("contact_moment"), 1000.0, 1e-6 * 1000.0);
  EXPECT_NEAR(r.figure("closed_share"), 50.0, 1e-9);
  EXPECT_NEAR(r.figure("shaft_mises"), 38.5, 0.1 * 38.5);
  EXPECT_GT(r.figure("flank_pressure_max"), 2 * 36.6);
  expect_measured(r, "shaft_mises", 36.41);
  expect_measured(r, "hub_mises", 23.05);
  expect_measured(r, "flank_pressure_max", 229.4);
  expect_measured(r, "flank_pressure_inner", 129.95);
  EXPECT_LT(r.figure("flank_pressure_inner"), r.figure("flank_pressure_max"));
  expect_measured(r, "shaft_mises_peak", 177.4);
}

// SPEC §4.5 as the 120 deg sector: rim displacement 0.41 mm to 10 % (stand-in geometry, coarse
// mesh), the hub's largest element-mean Mises against the published 141 MPa within 15 % (coarse:
// 36 elements around against the default 48), the contact recedes (more than half the bore lifts
// off) and, frictionless without interference, the lifted share does not depend on the torque
// (500 and 1000 N m equal to 1e-9: the problem is positively homogeneous in the load).
// The hub Mises' measured cause (docs/joints/p3g.md): refining the hub raises the element-mean
// peak (it converges from below, away from 141), the integration-point peak of that element lies
// above its mean, and with the flange at the shoulder the peak falls while the rim displacement
// falls too (below the default's): asserted as inequalities, the figures to 0.5 %.
TEST(JointReports, P3g) {
  const studies::JointReport r = coarse_report("p3g");
  EXPECT_NEAR(r.figure("rim_displacement"), 0.41, 0.041);
  EXPECT_NEAR(r.figure("hub_mises"), 141.0, 0.15 * 141.0);
  EXPECT_GT(r.figure("open_share"), 50.0);
  EXPECT_LT(r.figure("open_share"), 100.0);
  EXPECT_NEAR(r.figure("open_share_500"), r.figure("open_share"), 1e-9);
  expect_measured(r, "rim_displacement", 0.3849);
  expect_measured(r, "hub_mises", 124.8);
  expect_measured(r, "shaft_mises", 88.57);
  EXPECT_GT(r.figure("hub_mises_refined"), r.figure("hub_mises"));
  EXPECT_GT(r.figure("hub_ip_mises"), r.figure("hub_mises"));
  EXPECT_GT(r.figure("hub_ip_mises_refined"), r.figure("hub_mises_refined"));
  EXPECT_LT(r.figure("hub_mises_flange_shoulder"), r.figure("hub_mises"));
  EXPECT_LT(r.figure("rim_displacement_flange_shoulder"), r.figure("rim_displacement"));
  expect_measured(r, "hub_ip_mises", 168.79);
  expect_measured(r, "hub_mises_refined", 131.084);
  expect_measured(r, "hub_ip_mises_refined", 171.966);
  expect_measured(r, "hub_mises_flange_shoulder", 117.523);
  expect_measured(r, "rim_displacement_flange_shoulder", 0.36285);
}

TEST(JointReports, UnknownJointIsRefused) {
  const auto registry = test::registry_with_plugins();
  EXPECT_FALSE(studies::is_joint_study("gear"));
  EXPECT_THROW(studies::run_joint_study("gear", registry->registry, {}), std::invalid_argument);
}

}  // namespace
}  // namespace styk
