// Node-to-surface contact of non-matching meshes (SPEC §2.5 normals and areas, docs/contact.md
// "Constraints" and "Node-to-surface on non-matching meshes"): every slave node projected on a
// master face, solved exactly (Lagrange multipliers) through run_static_analysis.
//
// - Flat patch: a block [0,1]^2 x [1,2] (slave bottom, n x n elements) pressed by p = 1 on its top
//   onto a block [0,1]^2 x [0,1] (master top, m x m), frictionless, both on rollers (uz = 0 at
//   z = 0, ux = 0 on x = 0, uy = 0 on y = 0); the upper block is held in z by the contact alone.
//   Exact solution: uniform stress, pressure 1.
// - SPEC §3.2.2 concentric cylinders with 4 and 6 elements around the quarter on the two sides.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "contact_model_kit.hpp"
#include "contact_spec_models.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/split.hpp"
#include "styk/solver/analysis.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One side of the interface: element type of its contact layer and divisions along x and y.
struct Side {
  // C3D8, C3D20, C3D21 (a C3D20 block whose contact layer is converted), or a tetrahedron or
  // wedge type (the body's bricks split: mesher/split.hpp; wedges along z, triangles in contact)
  std::string type;
  int divisions = 1;
};

bool tetrahedra(const std::string& type) { return type == "C3D4" || type == "C3D10"; }
bool wedges(const std::string& type) { return type == "C3D6" || type == "C3D15"; }

Model flat_patch(const Side& slave, const Side& master, double master_young) {
  mesher::Mesh mesh;
  auto block_type = [](const std::string& t) {
    return t == "C3D8" || t == "C3D4" || t == "C3D6" ? "C3D8" : "C3D20";
  };
  const mesher::Block lower =
      test::add_box(mesh, {0, 0, 0}, {1, 1, 1}, {master.divisions, master.divisions, 2},
                    block_type(master.type), "LOWER");
  const mesher::Block upper =
      test::add_box(mesh, {0, 0, 1}, {1, 1, 2}, {slave.divisions, slave.divisions, 2},
                    block_type(slave.type), "UPPER");
  mesh.add_to_surface("LOWER_TOP", lower.side_faces(2, 1));
  mesh.add_to_surface("UPPER_BOTTOM", upper.side_faces(2, -1));
  mesh.add_to_surface("LOAD", upper.side_faces(2, 1));
  if (slave.type == "C3D21")
    mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "UPPER_BOTTOM");
  if (master.type == "C3D21")
    mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "LOWER_TOP");
  for (const auto& [side, body] :
       {std::make_pair(slave, "UPPER"), std::make_pair(master, "LOWER")}) {
    const std::vector<int> bricks = mesh.element_sets.at(body);
    if (tetrahedra(side.type))
      mesher::split_to_tetrahedra(mesh, test::shared_registry(), side.type, bricks);
    if (wedges(side.type))
      mesher::split_to_wedges(mesh, test::shared_registry(), side.type, 2, bricks);
  }
  Model model = test::contact_model(mesh, {{"LOWER", master_young, 0.3}, {"UPPER", 1.0, 0.3}});
  test::add_contact_pair(model, "UPPER_BOTTOM", "LOWER_TOP", "SMOOTH", std::nullopt);
  test::add_pressure(model, "LOAD", 1.0);
  for (int axis = 0; axis < 3; ++axis)
    test::fix(model,
              test::nodes_where(model, [axis](const Vec3& x) { return std::abs(x[axis]) < 1e-9; }),
              {axis + 1});
  return model;
}

class NodeToSurfaceContact : public test::PluginRegistrySuite<> {};

struct PatchResult {
  double low = INFINITY, high = -INFINITY;  // extreme nodal pressures of the closed nodes
  int open = 0;
  std::size_t nodes = 0;
};

// Solves the flat patch and asserts what holds for every mesh pair: total contact force = applied
// load p A = 1 to 1e-8 (SPEC §3.2 exact enforcement; measured 1e-15), penetration at round-off
// at closed nodes (|gap| <= 1e-12; measured 2e-14), nodal areas summing to the face area 1 (1e-12),
// equilibrium.
PatchResult solve_patch(const ElementRegistry& registry, const Side& slave, const Side& master,
                        double master_young) {
  const Model model = flat_patch(slave, master, master_young);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  PatchResult out;
  out.nodes = r.contact.size();
  double area = 0.0, force = 0.0;
  for (const ContactNodeResult& c : r.contact) {
    area += c.area;
    force += c.force[2];
    if (c.status == ContactStatus::Open) {
      ++out.open;
      EXPECT_EQ(c.force[2], 0.0);
      EXPECT_GT(c.gap, 0.0);
      continue;
    }
    EXPECT_NEAR(c.gap, 0.0, 1e-12) << "node " << model.node_ids[c.node];
    out.low = std::min(out.low, c.pressure);
    out.high = std::max(out.high, c.pressure);
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_NEAR(force, 1.0, 1e-8);
  EXPECT_NEAR(r.contact_pairs.at(0).force[2], 1.0, 1e-8);
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-8);
  return out;
}

// On a master 1e6 times stiffer than the slave the patch test is passed: pressure 1 at every node
// within 1e-5 (measured 5.2e-7 for C3D8, 2.3e-6 for C3D21 on C3D20). The remaining deviation is
// the master's deformation under the node-to-surface load transfer, so it must fall in proportion
// to the master's compliance: from stiffness ratio 1e3 to 1e6 by 1000 (asserted 900-1100; measured
// 5.245e-4 -> 5.245e-7). Over a rigid master the pairing, normals and areas are exact.
TEST_F(NodeToSurfaceContact, FlatPatchOverAStiffMasterIsUniform) {
  // Also on the faces of tetrahedra and wedges (triangles; the linear ones as slaves, whose corner
  // areas are A/3 > 0; the quadratic ones as masters, projected on exactly).
  const std::pair<Side, Side> cases[] = {{{"C3D8", 3}, {"C3D8", 4}},   {{"C3D8", 4}, {"C3D8", 3}},
                                         {{"C3D21", 3}, {"C3D20", 4}}, {{"C3D21", 4}, {"C3D20", 3}},
                                         {{"C3D4", 3}, {"C3D4", 4}},   {{"C3D6", 3}, {"C3D15", 4}},
                                         {{"C3D8", 3}, {"C3D10", 4}}};
  for (const auto& [slave, master] : cases) {
    SCOPED_TRACE(slave.type + " " + std::to_string(slave.divisions) + " on " + master.type + " " +
                 std::to_string(master.divisions));
    const PatchResult stiff = solve_patch(registry(), slave, master, 1e6);
    const PatchResult stiffer_by_1e3 = solve_patch(registry(), slave, master, 1e3);
    EXPECT_EQ(stiff.open, 0);
    EXPECT_LT(std::max(stiff.high - 1.0, 1.0 - stiff.low), 1e-5);
    const double ratio = std::max(stiffer_by_1e3.high - 1.0, 1.0 - stiffer_by_1e3.low) /
                         std::max(stiff.high - 1.0, 1.0 - stiff.low);
    EXPECT_GT(ratio, 900.0);
    EXPECT_LT(ratio, 1100.0);
  }
}

// Equal stiffness: the total force is exact (asserted in solve_patch) but the nodal pressures are
// not uniform — the one-pass node-to-surface pairing hands the slave forces to the master nodes
// with the master's shape functions at the slave points, not as the consistent load of a uniform
// pressure on the master mesh, so it does not pass the contact patch test (Taylor & Papadopoulos
// 1991; docs/contact.md). Measured spreads, asserted with a margin as a regression bound:
// C3D8 3x3 on 4x4 0.761-1.119 (bound 0.72-1.16), 4x4 on 3x3 0.828-1.083 (0.79-1.12),
// C3D21 4x4 on C3D20 3x3 0.947-1.025 (0.92-1.05): the finer mesh as slave is the better choice.
TEST_F(NodeToSurfaceContact, FlatPatchOfEqualStiffnessKeepsTheTotalAndBoundsTheSpread) {
  struct Case {
    Side slave, master;
    double low, high;
  };
  const Case cases[] = {{{"C3D8", 3}, {"C3D8", 4}, 0.72, 1.16},
                        {{"C3D8", 4}, {"C3D8", 3}, 0.79, 1.12},
                        {{"C3D21", 4}, {"C3D20", 3}, 0.92, 1.05}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.slave.type + " " + std::to_string(c.slave.divisions) + " on " + c.master.type);
    const PatchResult r = solve_patch(registry(), c.slave, c.master, 1.0);
    EXPECT_EQ(r.open, 0);
    EXPECT_GT(r.low, c.low);
    EXPECT_LT(r.high, c.high);
  }
}

// A C3D20 slave face has negative corner areas (−1/12 of the face, docs/contact.md): a uniform
// pressure would need those nodes to pull, so they open. 3x3 C3D20 slave on 4x4 C3D8: 40 slave
// nodes, the 16 corner nodes open with zero force, the 24 mid-edge nodes carry the whole load
// (total still 1 to 1e-8). This is what C3D21/C3D28 contact layers are for.
TEST_F(NodeToSurfaceContact, C3D20SlaveOpensItsCornerNodes) {
  const PatchResult r = solve_patch(registry(), {"C3D20", 3}, {"C3D8", 4}, 1.0);
  EXPECT_EQ(r.nodes, 40u);
  EXPECT_EQ(r.open, 16);
  EXPECT_GT(r.low, 0.0);
}

// ---------------------------------------------------------------------------------------------
// SPEC §3.2.2 concentric cylinders on non-matching meshes (contact_spec_models.hpp): a C3D21
// slave layer (every nodal area positive), node to surface. Nodes coincide only at the angles both
// divisions share (0, 22.5°, 45°, ...): the rest pair node-to-surface.
Model cylinders(int inner_around, int outer_around) {
  return test::nonmatching_cylinders_model(inner_around, outer_around, "C3D21", "SMOOTH",
                                           ContactPair::Type::NodeToSurface);
}

// SPEC §3.2.2: Lamé contact pressure 3.294 (uniform), asserted within 2 % on the interface means:
// the resultant on the quarter interface, F_x = F_y = p r L = 6.588 (measured p = 3.2914 for 6
// slave elements on 4, 3.2918 for 4 on 6), and the force per area sum(lambda) / sum(A) (3.2918,
// 3.2918; A: the nodal areas projected on the normals, docs/contact.md "Nodal area"). The slave
// normals are radial to 1e-12 away from the symmetry planes (the two faces' errors cancel at a
// shared node; measured 1e-15) and within the quadratic face's normal error on them (bound h^2/3 =
// 0.0129 rad for 22.5° elements, measured 1.86e-3); the nodal areas add up to the quarter bore, pi
// r L / 2 = pi, within the quadratic faces' interpolation of the circle (asserted 1e-4 relative;
// measured -1.0e-5 with 6 elements, -4.9e-5 with 4). Nodal pressures scatter around the mean by the
// node-to-surface transfer error, as on the flat patch (measured -22 % ... +27 %, bounded at 30 %),
// where the matching 16 + 16 mesh of spec_3_2_contact_test.cpp is uniform within 1 %.
void expect_lame(const ElementRegistry& registry, int inner_around, int outer_around) {
  SCOPED_TRACE("inner " + std::to_string(inner_around) + ", outer " + std::to_string(outer_around));
  const Model model = cylinders(inner_around, outer_around);
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  const double lame = 3.294, radius = 2.0;
  ASSERT_EQ(r.contact.size(), static_cast<std::size_t>(3 * (2 * outer_around + 1)));
  double force = 0.0, area = 0.0, worst_interior = 0.0, worst_plane = 0.0;
  for (const ContactNodeResult& c : r.contact) {
    const Vec3& x = model.coords[c.node];
    const Eigen::Vector3d inward(-x[0] / radius, -x[1] / radius, 0.0);  // out of the bore
    const double normal_error =
        (Eigen::Vector3d(c.normal[0], c.normal[1], c.normal[2]) - inward).norm();
    const bool on_plane = std::abs(x[0]) < 1e-9 || std::abs(x[1]) < 1e-9;
    double& worst = on_plane ? worst_plane : worst_interior;
    worst = std::max(worst, normal_error);
    EXPECT_NE(c.status, ContactStatus::Open) << "node " << model.node_ids[c.node];
    EXPECT_NEAR(c.gap, 0.0, 1e-12);
    EXPECT_NEAR(c.pressure, lame, 0.30 * lame) << "node " << model.node_ids[c.node];
    force += c.pressure * c.area;
    area += c.area;
  }
  EXPECT_LT(worst_interior, 1e-12);
  EXPECT_LT(worst_plane, (kPi / 16) * (kPi / 16) / 3.0);
  EXPECT_NEAR(area, kPi, 1e-4 * kPi);
  EXPECT_NEAR(force / area, lame, 0.02 * lame);
  for (int d = 0; d < 2; ++d)
    EXPECT_NEAR(r.contact_pairs.at(0).force[d], lame * radius, 0.02 * lame * radius);
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-8);
  ::testing::Test::RecordProperty(
      "pressure_" + std::to_string(inner_around) + "_" + std::to_string(outer_around),
      std::to_string(r.contact_pairs.at(0).force[0] / radius));
  ::testing::Test::RecordProperty(
      "area_error_" + std::to_string(inner_around) + "_" + std::to_string(outer_around),
      std::to_string(area / kPi - 1.0));
  ::testing::Test::RecordProperty(
      "force_per_area_" + std::to_string(inner_around) + "_" + std::to_string(outer_around),
      std::to_string(force / area));
}

TEST_F(NodeToSurfaceContact, ConcentricCylindersSixSlaveElementsOnFour) {
  expect_lame(registry(), 4, 6);
}

TEST_F(NodeToSurfaceContact, ConcentricCylindersFourSlaveElementsOnSix) {
  expect_lame(registry(), 6, 4);
}

}  // namespace
}  // namespace styk
