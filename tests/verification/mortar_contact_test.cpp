// Mortar contact (*CONTACT PAIR, TYPE=MORTAR; docs/contact.md "Mortar contact"): dual Lagrange
// multipliers on the slave faces (Wohlmuth 2000), so every slave node's row is one constraint,
// solved exactly through run_static_analysis.
//
// The contact patch test (Taylor and Papadopoulos 1991; issue "Contact engine at scale and
// exactness", item 2): a block [0,1]^2 x [1,2] (slave bottom, n x n elements) pressed by p = 1 on
// its top onto a block [0,1]^2 x [0,1] (master top, m x m) of the same stiffness, both on rollers.
// The exact solution is a uniform stress, so a formulation that passes the test carries pressure 1
// at every slave node. One-pass node-to-surface does not (0.63 ... 2.14,
// node_to_surface_contact_test.cpp); mortar must, to 1e-8.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "contact_model_kit.hpp"
#include "contact_spec_models.hpp"
#include "hex_model_builder.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/split.hpp"
#include "styk/solver/analysis.hpp"
#include "support/ccx_runner.hpp"
#include "support/plugin_registry_suite.hpp"
#include "support/test_scratch.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One side of the interface: element type of its contact layer and divisions along x and y.
struct Side {
  // C3D8, C3D20, C3D27 (a C3D20 block converted), C3D21/C3D28 (a C3D20 block whose contact layer
  // is converted), or C3D4/C3D10 (the body's bricks split into tetrahedra: mesher/split.hpp)
  std::string type;
  int divisions = 1;
};

std::string block_type(const std::string& type) {
  return type == "C3D8" || type == "C3D4" ? "C3D8" : "C3D20";
}

// The two blocks, their surfaces and the mortar pair (frictionless unless `friction`), no loads.
Model two_blocks(const Side& slave, const Side& master, double poisson,
                 std::optional<Friction> friction) {
  mesher::Mesh mesh;
  const mesher::Block lower =
      test::add_box(mesh, {0, 0, 0}, {1, 1, 1}, {master.divisions, master.divisions, 2},
                    block_type(master.type), "LOWER");
  const mesher::Block upper =
      test::add_box(mesh, {0, 0, 1}, {1, 1, 2}, {slave.divisions, slave.divisions, 2},
                    block_type(slave.type), "UPPER");
  mesh.add_to_surface("LOWER_TOP", lower.side_faces(2, 1));
  mesh.add_to_surface("UPPER_BOTTOM", upper.side_faces(2, -1));
  mesh.add_to_surface("LOAD", upper.side_faces(2, 1));
  for (int axis = 0; axis < 2; ++axis)
    for (int side : {-1, 1}) {
      const std::string suffix = std::to_string(axis) + (side > 0 ? "+" : "-");
      mesh.add_to_surface("UPPER_SIDE" + suffix, upper.side_faces(axis, side));
      mesh.add_to_surface("LOWER_SIDE" + suffix, lower.side_faces(axis, side));
    }
  for (const auto& [side, surface] :
       {std::make_pair(slave, "UPPER_BOTTOM"), std::make_pair(master, "LOWER_TOP")})
    if (side.type == "C3D21" || side.type == "C3D28")
      mesher::convert_elements(mesh, test::shared_registry(), side.type, surface);
  for (const auto& [side, body] : {std::make_pair(slave, "UPPER"), std::make_pair(master, "LOWER")})
    if (side.type == "C3D27")
      mesher::convert_elements(mesh, test::shared_registry(), side.type, "",
                               mesh.element_sets.at(body));
  for (const auto& [side, body] : {std::make_pair(slave, "UPPER"), std::make_pair(master, "LOWER")})
    if (side.type == "C3D4" || side.type == "C3D10")
      mesher::split_to_tetrahedra(mesh, test::shared_registry(), side.type,
                                  mesh.element_sets.at(body));
  Model model = test::contact_model(mesh, {{"LOWER", 1.0, poisson}, {"UPPER", 1.0, poisson}});
  test::add_contact_pair(model, "UPPER_BOTTOM", "LOWER_TOP", "MORTAR", friction);
  model.contact_pairs.back().type = ContactPair::Type::Mortar;
  return model;
}

Model pressed_patch(const Side& slave, const Side& master) {
  Model model = two_blocks(slave, master, 0.3, std::nullopt);
  test::add_pressure(model, "LOAD", 1.0);
  for (int axis = 0; axis < 3; ++axis)
    test::fix(model,
              test::nodes_where(model, [axis](const Vec3& x) { return std::abs(x[axis]) < 1e-9; }),
              {axis + 1});
  return model;
}

std::string sci(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", v);
  return text;
}

// The nodal areas integral N_i dA (SPEC §2.5) of the faces of `surface`, summed per node.
std::map<int, double> summed_nodal_areas(const Model& model, const ElementRegistry& registry,
                                         const std::string& surface) {
  std::map<int, double> area_of;
  for (const SurfaceFace& f : model.surfaces.at(surface).faces) {
    const Element& element = model.elements[f.element];
    ElementGeometry g;
    g.X.resize(element.node_count, 3);
    const int* nodes = model.element_nodes(f.element);
    for (int k = 0; k < element.node_count; ++k)
      for (int d = 0; d < 3; ++d) g.X(k, d) = model.coords[nodes[k]][d];
    Eigen::VectorXd area;
    registry.find(element.type)->nodal_areas(g, f.face - 1, area);
    for (int k = 0; k < element.node_count; ++k)
      if (area[k] != 0.0) area_of[nodes[k]] += area[k];
  }
  return area_of;
}

// Nodal forces of a uniform traction on the faces of `surface`: traction times the nodal areas
// integral N_i dA of each face (the consistent load), summed per node (a later *CLOAD line for the
// same node and dof would replace an earlier one).
void add_traction(Model& model, const ElementRegistry& registry, const std::string& surface,
                  const Eigen::Vector3d& traction) {
  for (const auto& [node, area] : summed_nodal_areas(model, registry, surface))
    for (int d = 0; d < 3; ++d)
      if (traction[d] != 0.0)
        model.steps[0].cloads.push_back({node, d + 1, traction[d] * area, {}});
}

class MortarContact : public test::PluginRegistrySuite<> {};

struct Spread {
  double low = INFINITY, high = -INFINITY;
  double worst(double exact) const { return std::max(high - exact, exact - low); }
};

// The patch test: every slave node closed with pressure 1 (1e-8), gap 0 (1e-12), the nodal
// areas D_j adding up to the face area 1 (1e-12; not on 8-node and 6-node slave faces, whose
// mid-edge rows carry integral N_j dA, the corners D^_j), the total force the applied load 1
// (1e-10), also as the pair's force. Returns the measured pressure spread.
Spread expect_patch_test(const ElementRegistry& registry, const Side& slave, const Side& master) {
  SCOPED_TRACE(slave.type + " " + std::to_string(slave.divisions) + " on " + master.type + " " +
               std::to_string(master.divisions));
  const Model model = pressed_patch(slave, master);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  Spread spread;
  double area = 0.0, force = 0.0;
  for (const ContactNodeResult& c : r.contact) {
    EXPECT_NE(c.status, ContactStatus::Open) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.pressure, 1.0, 1e-8) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.gap, 0.0, 1e-12);
    spread.low = std::min(spread.low, c.pressure);
    spread.high = std::max(spread.high, c.pressure);
    area += c.area;
    force += c.force[2];
  }
  EXPECT_FALSE(r.contact.empty());
  if (slave.type != "C3D20" && slave.type != "C3D10") {
    EXPECT_NEAR(area, 1.0, 1e-12);
    EXPECT_NEAR(force, 1.0, 1e-10);
  }
  EXPECT_NEAR(r.contact_pairs.at(0).force[2], 1.0, 1e-10);
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-8);
  return spread;
}

// The patch test on each (slave, master) pair; the worst deviation from 1 recorded per case.
void expect_patch_tests(const ElementRegistry& registry,
                        const std::vector<std::pair<Side, Side>>& cases) {
  for (const auto& [slave, master] : cases) {
    const Spread s = expect_patch_test(registry, slave, master);
    ::testing::Test::RecordProperty("worst_" + slave.type + "_" + std::to_string(slave.divisions) +
                                        "_on_" + master.type + "_" +
                                        std::to_string(master.divisions),
                                    sci(s.worst(1.0)));
  }
}

// Linear faces: C3D8 both ways round, and linear triangles (C3D4) on the same non-matching
// divisions. Measured worst deviation from 1: see docs/contact.md.
TEST_F(MortarContact, FlatPatchTestOnLinearFaces) {
  expect_patch_tests(
      registry(),
      {{{"C3D8", 3}, {"C3D8", 4}}, {{"C3D8", 4}, {"C3D8", 3}}, {{"C3D4", 3}, {"C3D4", 4}}});
}

// Quadratic and cubic faces: the thesis' contact layers C3D21 (9-node face) and C3D28 (16-node
// face) and C3D27 (9-node) as slaves on C3D20 (8-node) and C3D8 masters and the other way round
// where the slave face allows dual multipliers.
TEST_F(MortarContact, FlatPatchTestOnQuadraticFaces) {
  expect_patch_tests(registry(), {{{"C3D21", 3}, {"C3D20", 4}},
                                  {{"C3D21", 4}, {"C3D20", 3}},
                                  {{"C3D28", 3}, {"C3D20", 4}},
                                  {{"C3D28", 4}, {"C3D20", 3}},
                                  {{"C3D27", 3}, {"C3D27", 4}},
                                  {{"C3D8", 3}, {"C3D20", 4}},
                                  {{"C3D21", 4}, {"C3D28", 3}}});
}

// Serendipity slave faces (C3D20: 8 nodes, C3D10: 6-node triangles), whose corner integrals are
// negative or zero: the transformed slave basis (Popp et al. 2012) makes every multiplier's
// integral positive; the mid-edge rows couple the edge's corners. Pressure 1 at every node, corners
// included (node-to-surface opens them: node_to_surface_contact_test.cpp).
TEST_F(MortarContact, FlatPatchTestOnSerendipitySlaveFaces) {
  expect_patch_tests(registry(), {{{"C3D20", 3}, {"C3D8", 4}},
                                  {{"C3D20", 3}, {"C3D20", 4}},
                                  {{"C3D20", 4}, {"C3D20", 3}},
                                  {{"C3D10", 3}, {"C3D4", 4}}});
}

// A LINEAR penalty law (K = 100) on the pressed patch: pressure 1 and penetration 1 / K = 0.01 at
// every slave node (1e-8) — on a C3D20 slave as well, whose mid-edge rows are 3/5 of their node's
// gap (ContactConstraint::gap_scale: the spring and the reported gap are scaled back).
TEST_F(MortarContact, PenaltyPatchTest) {
  for (const std::pair<Side, Side>& sides :
       {std::pair<Side, Side>{{"C3D20", 3}, {"C3D8", 4}}, {{"C3D21", 4}, {"C3D20", 3}}}) {
    const Side& slave = sides.first;
    SCOPED_TRACE(slave.type);
    Model model = pressed_patch(slave, sides.second);
    PressureOverclosure& law = model.surface_interactions.at("MORTAR").behavior;
    law.law = PressureOverclosure::Law::Linear;
    law.slope = 100.0;
    const Results results =
        run_static_analysis(model, registry(), SolveOptions{}, nullptr, nullptr);
    const IncrementResult& r = results.increments.back();
    ASSERT_FALSE(r.contact.empty());
    double worst = 0.0;
    for (const ContactNodeResult& c : r.contact) {
      EXPECT_NEAR(c.pressure, 1.0, 1e-8) << "node " << model.node_ids[c.node];
      EXPECT_NEAR(c.gap, -0.01, 1e-8) << "node " << model.node_ids[c.node];
      worst = std::max({worst, std::abs(c.pressure - 1.0), std::abs(c.gap + 0.01) * 100.0});
    }
    EXPECT_NEAR(r.contact_pairs.at(0).force[2], 1.0, 1e-10);
    ::testing::Test::RecordProperty("penalty_" + slave.type, sci(worst));
  }
}

// Coulomb friction under a uniform shear (nu = 0, E = 1, G = 1/2): the stress sigma_zz = -1,
// sigma_xz = tau everywhere is exact when the lower block's bottom is clamped, the upper block's
// top carries pressure 1 and is moved by u_x = delta, both blocks' x faces carry the shear
// traction +-tau e_z and y = 0 is on rollers. Stick (mu = 0.5): delta = 2 tau / G = 0.8 with
// tau = 0.2, the interface sticks and transmits tau. Full slip (mu = 0.1): delta = 1 exceeds the
// blocks' shear strain at tau = mu p (0.4), every node slips and transmits mu p = 0.1. Pressure 1
// and shear traction tau (x component of the force on the slave: -tau A) at every slave node to
// 1e-8.
void expect_uniform_shear(const ElementRegistry& registry, const Side& slave, const Side& master,
                          double mu, double tau, double delta, ContactStatus status) {
  SCOPED_TRACE(slave.type + " " + std::to_string(slave.divisions) + " on " + master.type + " " +
               std::to_string(master.divisions) + ", mu " + std::to_string(mu));
  Model model = two_blocks(slave, master, 0.0, test::coulomb(mu));
  test::add_pressure(model, "LOAD", 1.0);
  for (const char* body : {"UPPER", "LOWER"}) {
    add_traction(model, registry, std::string(body) + "_SIDE0+", {0, 0, tau});
    add_traction(model, registry, std::string(body) + "_SIDE0-", {0, 0, -tau});
  }
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return std::abs(x[2]) < 1e-9; }),
            {1, 2, 3});
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return std::abs(x[1]) < 1e-9; }),
            {2});
  for (int n : test::nodes_where(model, [](const Vec3& x) { return std::abs(x[2] - 2.0) < 1e-9; }))
    model.steps[0].boundaries.push_back({n, 1, delta, {}});
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  ASSERT_FALSE(r.contact.empty());
  double worst = 0.0;
  for (const ContactNodeResult& c : r.contact) {
    EXPECT_EQ(c.status, status) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.pressure, 1.0, 1e-8) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.force[0] / c.area, -tau, 1e-8) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.force[1] / c.area, 0.0, 1e-8) << "node " << model.node_ids[c.node];
    worst = std::max({worst, std::abs(c.pressure - 1.0), std::abs(c.force[0] / c.area + tau)});
    // Full slip is uniform: the upper block's interface moves by delta - 2 mu p / G = 0.6 more
    // than the lower block's (slip of the slave relative to the master, along x).
    if (status == ContactStatus::Slip) {
      EXPECT_NEAR(std::abs(c.slip[0] * c.t1[0] + c.slip[1] * c.t2[0]), 0.6, 1e-8)
          << "node " << model.node_ids[c.node];
    }
  }
  EXPECT_NEAR(r.contact_pairs.at(0).force[0], -tau, 1e-10);
  ::testing::Test::RecordProperty(std::string(status == ContactStatus::Stick ? "stick_" : "slip_") +
                                      slave.type + "_" + std::to_string(slave.divisions) + "_on_" +
                                      std::to_string(master.divisions),
                                  sci(worst));
}

TEST_F(MortarContact, UniformShearSticks) {
  expect_uniform_shear(registry(), {"C3D8", 3}, {"C3D8", 4}, 0.5, 0.2, 0.8, ContactStatus::Stick);
  expect_uniform_shear(registry(), {"C3D8", 4}, {"C3D8", 3}, 0.5, 0.2, 0.8, ContactStatus::Stick);
  expect_uniform_shear(registry(), {"C3D21", 3}, {"C3D20", 4}, 0.5, 0.2, 0.8, ContactStatus::Stick);
  expect_uniform_shear(registry(), {"C3D28", 4}, {"C3D20", 3}, 0.5, 0.2, 0.8, ContactStatus::Stick);
  expect_uniform_shear(registry(), {"C3D20", 3}, {"C3D20", 4}, 0.5, 0.2, 0.8, ContactStatus::Stick);
}

// Quadratic slaves on a linear master in stick: the slave rows on the y = 0 rollers reach free
// interior master nodes, and with their y components kept the stuck rows over-determined the
// system ("singular contact system"); the slave's held direction is taken out of the multiplier
// space (LinearContactSystem::held, docs/contact.md "Mortar contact").
TEST_F(MortarContact, UniformShearSticksWithQuadraticSlavesOnALinearMaster) {
  expect_uniform_shear(registry(), {"C3D20", 3}, {"C3D8", 4}, 0.5, 0.2, 0.8, ContactStatus::Stick);
  expect_uniform_shear(registry(), {"C3D21", 3}, {"C3D8", 4}, 0.5, 0.2, 0.8, ContactStatus::Stick);
  expect_uniform_shear(registry(), {"C3D28", 3}, {"C3D8", 4}, 0.5, 0.2, 0.8, ContactStatus::Stick);
}

TEST_F(MortarContact, UniformShearSlips) {
  expect_uniform_shear(registry(), {"C3D8", 3}, {"C3D8", 4}, 0.1, 0.1, 1.0, ContactStatus::Slip);
  expect_uniform_shear(registry(), {"C3D8", 4}, {"C3D8", 3}, 0.1, 0.1, 1.0, ContactStatus::Slip);
  expect_uniform_shear(registry(), {"C3D21", 3}, {"C3D20", 4}, 0.1, 0.1, 1.0, ContactStatus::Slip);
  expect_uniform_shear(registry(), {"C3D28", 4}, {"C3D20", 3}, 0.1, 0.1, 1.0, ContactStatus::Slip);
  expect_uniform_shear(registry(), {"C3D20", 3}, {"C3D8", 4}, 0.1, 0.1, 1.0, ContactStatus::Slip);
}

// ---------------------------------------------------------------------------------------------
// SPEC §3.2.2 concentric cylinders on non-matching meshes (contact_spec_models.hpp), paired
// mortar by default.
Model cylinders(int inner_around, int outer_around, const std::string& slave_type,
                ContactPair::Type type = ContactPair::Type::Mortar) {
  return test::nonmatching_cylinders_model(inner_around, outer_around, slave_type, "MORTAR", type);
}

// The slave nodes' pressures by position (angle in degrees and z, rounded), so that meshes with the
// same slave side can be compared node by node.
using PressureMap = std::map<std::pair<long, long>, double>;

// SPEC §3.2.2: Lamé's contact pressure 3.294, uniform. Every slave node's pressure within
// `tolerance` (relative) of it, the resultant on the quarter interface F_x = F_y = p r L within
// 0.5 %, the nodal areas adding up to the quarter bore pi r L / 2 = pi within the quadratic faces'
// interpolation of the circle (1e-4), gaps closed to round-off. Returns the pressures.
PressureMap expect_uniform_lame(const ElementRegistry& registry, int inner_around, int outer_around,
                                const std::string& slave_type, double tolerance) {
  const std::string name =
      slave_type + "_" + std::to_string(outer_around) + "_on_" + std::to_string(inner_around);
  SCOPED_TRACE(name);
  const Model model = cylinders(inner_around, outer_around, slave_type);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  const double lame = 3.294, radius = 2.0;
  EXPECT_FALSE(r.contact.empty());
  Spread spread;
  double area = 0.0;
  PressureMap pressures;
  for (const ContactNodeResult& c : r.contact) {
    const Vec3& x = model.coords[c.node];
    EXPECT_NE(c.status, ContactStatus::Open) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.gap, 0.0, 1e-12);
    EXPECT_NEAR(c.pressure, lame, tolerance * lame) << "node " << model.node_ids[c.node];
    spread.low = std::min(spread.low, c.pressure);
    spread.high = std::max(spread.high, c.pressure);
    area += c.area;
    pressures[{std::lround(std::atan2(x[1], x[0]) * 180.0 / kPi * 1e4), std::lround(x[2] * 1e4)}] =
        c.pressure;
  }
  EXPECT_NEAR(area, kPi, 1e-4 * kPi);
  for (int d = 0; d < 2; ++d)
    EXPECT_NEAR(r.contact_pairs.at(0).force[d], lame * radius, 0.005 * lame * radius);
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-8);
  ::testing::Test::RecordProperty("low_" + name, sci(spread.low / lame - 1.0));
  ::testing::Test::RecordProperty("high_" + name, sci(spread.high / lame - 1.0));
  ::testing::Test::RecordProperty("resultant_" + name,
                                  sci(r.contact_pairs.at(0).force[0] / radius / lame - 1.0));
  return pressures;
}

// The largest difference, relative to Lamé's 3.294, between the pressures of two solutions with
// the same slave mesh (every node of `a` present in `b`).
double largest_difference(const PressureMap& a, const PressureMap& b) {
  double worst = 0.0;
  for (const auto& [at, p] : a) {
    const auto other = b.find(at);
    EXPECT_NE(other, b.end());
    if (other != b.end()) worst = std::max(worst, std::abs(p - other->second) / 3.294);
  }
  return worst;
}

// 6 slave elements around the quarter on 4: within 0.5 % of Lamé at every node with either
// contact layer (measured C3D21 -0.04 % ... +0.06 %, C3D28 -0.20 % ... +0.45 %; with the nodal
// area A_i instead of its projection on the normal C3D21 had -0.22 % ... +0.40 %).
TEST_F(MortarContact, ConcentricCylindersSixSlaveElementsOnFour) {
  for (const char* layer : {"C3D21", "C3D28"}) {
    const PressureMap mortar = expect_uniform_lame(registry(), 4, 6, layer, 0.005);
    const PressureMap matching = expect_uniform_lame(registry(), 6, 6, layer, 0.005);
    ::testing::Test::RecordProperty(std::string("versus_matching_") + layer + "_6_on_4",
                                    sci(largest_difference(mortar, matching)));
  }
}

// 4 slave elements on 6 (issue target: every node within 0.5 % of Lamé): measured C3D28
// -0.02 % ... +0.07 %, C3D21 -0.01 % ... +0.03 %; node by node the C3D21 layer is within 0.05 %
// of Lamé of its matching 4 on 4 mesh (measured 0.043 %: the non-matching pairing's own error).
TEST_F(MortarContact, ConcentricCylindersFourSlaveElementsOnSix) {
  expect_uniform_lame(registry(), 6, 4, "C3D28", 0.005);
  const PressureMap mortar = expect_uniform_lame(registry(), 6, 4, "C3D21", 0.005);
  const PressureMap matching = expect_uniform_lame(registry(), 4, 4, "C3D21", 0.005);
  const double difference = largest_difference(mortar, matching);
  EXPECT_LT(difference, 5e-4);
  ::testing::Test::RecordProperty("versus_matching_C3D21_4_on_6", sci(difference));
}

// Why the nodal area is projected on the node's normal (docs/contact.md, "Nodal area"). Under a
// uniform pressure p on a curved face the node's normal force is p times V_i . n_i = integral
// N_i n.n_i dA, not p times A_i = integral N_i dA (SPEC §2.5). On a circle of quadratic elements
// of angle alpha (n.n_i = cos(theta) ~ 1 - theta^2 / 2 over the node's support) the ratio
// V_i . n_i / A_i is 1 + alpha^2 / 20 at a corner node (its shape function is negative on the far
// half of each element, where the normal has turned most) and 1 - alpha^2 / 40 at a mid-edge node,
// to O(alpha^4): with 4 C3D21 elements around the quarter (alpha = pi / 8) +0.771 % and
// -0.386 %, the deviations the pressures had with A_i (measured +0.77 % / -0.39 % at the corner /
// mid-edge nodes). Asserted here: that ratio of the constraints' area to A_i (nodal_areas of the
// slave faces) on the matching 4 on 4 mesh at every slave node within 3e-4 of the formula
// (measured 1.00756 / 0.99616 against 1.00771 / 0.99614); and with the projected area every node
// within 0.05 % of Lamé on the matching meshes with 4, 6 and 8 elements around (measured 0.020 %,
// 0.009 %, 0.006 %; the resultant alone is 3.0e-5 low on all three, the radial discretisation).
TEST_F(MortarContact, ProjectedNodalAreaRemovesTheCurvatureError) {
  const Model model = cylinders(4, 4, "C3D21", ContactPair::Type::NodeToSurface);
  const Results results = run_static_analysis(model, registry(), SolveOptions{}, nullptr, nullptr);
  const std::map<int, double> scalar_area = summed_nodal_areas(model, registry(), "OUTER_IN");
  const double alpha2 = (kPi / 8.0) * (kPi / 8.0);
  int corners = 0, mid_edges = 0;
  for (const ContactNodeResult& c : results.increments.back().contact) {
    const Vec3& x = model.coords[c.node];
    // Corner nodes at multiples of alpha = 22.5 deg, mid-edge nodes half-way; along the straight
    // axial direction the normal does not turn, so every axial position has the same ratio.
    const double eighths = std::atan2(x[1], x[0]) / (kPi / 8.0);
    const bool corner = std::abs(eighths - std::round(eighths)) < 1e-6;
    const double expected = corner ? 1.0 + alpha2 / 20.0 : 1.0 - alpha2 / 40.0;
    EXPECT_NEAR(c.area / scalar_area.at(c.node), expected, 3e-4)
        << "node " << model.node_ids[c.node];
    ++(corner ? corners : mid_edges);
  }
  EXPECT_EQ(corners, 15);  // 5 angles x 3 axial positions
  EXPECT_EQ(mid_edges, 12);
  for (int around : {4, 6, 8}) {
    const PressureMap pressures = expect_uniform_lame(registry(), around, around, "C3D21", 5e-4);
    double worst = 0.0;
    for (const auto& [at, p] : pressures) worst = std::max(worst, std::abs(p / 3.294 - 1.0));
    ::testing::Test::RecordProperty("worst_C3D21_" + std::to_string(around) + "_matching",
                                    sci(worst));
  }
}

// C3D20 slave faces (the transformed quadratic basis) on the SPEC §3.2.2 cylinders, matching 4 on
// 4, quarter model: the solution is the C3D21 layer's (the displacement at every node both meshes
// have within 1e-8 of the largest; measured 2.5e-10), but the pair's force is 1.0 % low
// (F_x = 6.5216 against the layer's 6.5878 = Lamé's p r L to 3e-5). The cause is at the symmetry
// plane x = 0: a mid-edge row acts on its edge's corners with shares 1/5 along the mid-edge node's
// normal; at an interior corner the shares of the two neighbouring edges have opposite hoop
// components and cancel, but a corner on the plane has one neighbour, and the symmetry support
// takes that hoop component (the mirrored half's share in the whole ring). The pair, which sums
// the forces on the slave nodes, counts it: the difference equals -1/5 of the x-forces of the two
// hoop-edge mid-edge rows next to the plane (theta = 78.75 deg) within 2 % (measured -0.06624
// against -0.06686; the rest is the quadratic faces' normal error at the plane's nodes, 2e-3).
TEST_F(MortarContact, SerendipitySlaveFacesOnAQuarterCylinderReportTheSymmetryPlaneShares) {
  const Model layer = cylinders(4, 4, "C3D21");
  const Model plain = cylinders(4, 4, "C3D20");
  const Results with_layer =
      run_static_analysis(layer, registry(), SolveOptions{}, nullptr, nullptr);
  const Results with_plain =
      run_static_analysis(plain, registry(), SolveOptions{}, nullptr, nullptr);
  const IncrementResult& a = with_layer.increments.back();
  const IncrementResult& b = with_plain.increments.back();
  // The layer's mesh has the plain mesh's nodes first (C3D21 adds a node per converted face).
  ASSERT_EQ(layer.node_count() - plain.node_count(), 4);
  double worst = 0.0, largest = 0.0;
  for (int n = 0; n < plain.node_count(); ++n)
    for (int d = 0; d < 3; ++d) {
      ASSERT_NEAR(plain.coords[n][d], layer.coords[n][d], 1e-12);
      worst = std::max(worst, std::abs(a.U[n][d] - b.U[n][d]));
      largest = std::max(largest, std::abs(a.U[n][d]));
    }
  EXPECT_LT(worst, 1e-8 * largest);
  const double lame = 3.294 * 2.0;
  EXPECT_NEAR(a.contact_pairs.at(0).force[0], lame, 1e-4 * lame);
  EXPECT_NEAR(b.contact_pairs.at(0).force[0] / lame - 1.0, -0.010, 0.001);
  double corner_shares = 0.0;
  for (const ContactNodeResult& c : b.contact) {
    const Vec3& x = plain.coords[c.node];
    const bool hoop_edge = std::abs(x[2]) < 1e-9 || std::abs(x[2] - 1.0) < 1e-9;
    if (hoop_edge && std::abs(std::atan2(x[1], x[0]) - 78.75 * kPi / 180.0) < 1e-9)
      corner_shares -= 0.2 * c.force[0];
  }
  const double difference = b.contact_pairs.at(0).force[0] - a.contact_pairs.at(0).force[0];
  EXPECT_NEAR(difference, corner_shares, 0.02 * std::abs(corner_shares));
  ::testing::Test::RecordProperty("displacement_difference", sci(worst / largest));
  ::testing::Test::RecordProperty("pair_difference", sci(difference));
  ::testing::Test::RecordProperty("corner_shares", sci(corner_shares));
}

// On matching meshes the mortar weights are 1 on the coincident master node (the dual function's
// integral against the master's shape functions is D_j delta_jk) when the two faces are the same
// surface. On the 4 on 4 cylinders the C3D21 slave face (9 nodes) and the C3D20 master face (8
// nodes) interpolate the circle slightly differently, and mortar differs from node-to-node by
// 1.25e-5 of Lamé at most (asserted 5e-5).
TEST_F(MortarContact, MatchingMeshesGiveNodeToNode) {
  PressureMap by_type[2];
  const ContactPair::Type types[2] = {ContactPair::Type::Mortar, ContactPair::Type::NodeToSurface};
  for (int t = 0; t < 2; ++t) {
    const Model model = cylinders(4, 4, "C3D21", types[t]);
    const Results results =
        run_static_analysis(model, registry(), SolveOptions{}, nullptr, nullptr);
    for (const ContactNodeResult& c : results.increments.back().contact) {
      const Vec3& x = model.coords[c.node];
      by_type[t][{std::lround(std::atan2(x[1], x[0]) * 180.0 / kPi * 1e4),
                  std::lround(x[2] * 1e4)}] = c.pressure;
    }
  }
  ASSERT_EQ(by_type[0].size(), 27u);
  ASSERT_EQ(by_type[1].size(), 27u);
  const double difference = largest_difference(by_type[0], by_type[1]);
  EXPECT_LT(difference, 5e-5);
  ::testing::Test::RecordProperty("mortar_versus_node_to_node", sci(difference));
}

// The deck Styk writes for a mortar pair says TYPE=MORTAR and runs in CalculiX 2.20 (which has its
// own mortar contact): no input error, the job finishes. The model is the SPEC §3.2.3 two
// cantilevers (C3D8, 10 x 2 elements each, mu = 0.2: the builder's deck that CalculiX converges
// on). On the non-matching flat patch CalculiX's mortar stops inside its solver (exit 255) while
// the same deck with NODE TO SURFACE or SURFACE TO SURFACE finishes: a limit of CalculiX's mortar.
TEST_F(MortarContact, WrittenDeckRunsInCalculix) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  Model model =
      mesher::run_builder("two-cantilevers", {{"element", "C3D8"}, {"n", "10"}}, registry()).model;
  ASSERT_EQ(model.contact_pairs.size(), 1u);
  model.contact_pairs[0].type = ContactPair::Type::Mortar;
  const std::filesystem::path dir = test::test_scratch_dir("mortar_ccx");
  {
    std::ofstream out(dir / "patch.inp");
    write_inp(model, out);
  }
  std::ifstream written(dir / "patch.inp");
  std::stringstream text;
  text << written.rdbuf();
  EXPECT_NE(text.str().find("TYPE=MORTAR"), std::string::npos);
  const test::CcxRun run = test::run_ccx(dir, "patch", 300);
  EXPECT_EQ(run.exit_code, 0) << run.log.substr(0, 3000);
  EXPECT_EQ(run.log.find("*ERROR"), std::string::npos) << run.log.substr(0, 3000);
  EXPECT_NE(run.log.find("Job finished"), std::string::npos)
      << run.log.substr(run.log.size() > 3000 ? run.log.size() - 3000 : 0);
}

}  // namespace
}  // namespace styk
