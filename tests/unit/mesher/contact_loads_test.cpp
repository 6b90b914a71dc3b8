// What the contact builders put in their decks besides the mesh: loads and their resultants,
// friction laws from --mu/--mu2, the SPEC §3.2.4 contact node counts, the §4.2 heating step, the
// torque couples, the cylindrical *TRANSFORM and the parameter errors.
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/mesher/builders.hpp"

namespace styk {
namespace {

class ContactLoads : public ::testing::Test {
 protected:
  mesher::BuildResult build(const std::string& builder,
                            std::map<std::string, std::string> args) const {
    return mesher::run_builder(builder, args, elements_.registry);
  }
  std::string error_of(const std::string& builder, std::map<std::string, std::string> args) const {
    try {
      build(builder, args);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  test::Elements elements_;
};

int slave_node_count(const Model& model, const ElementRegistry& registry) {
  std::set<int> nodes;
  for (const SurfaceFace& f : model.surfaces.at(model.contact_pairs.at(0).slave).faces) {
    const TElement& t = *registry.find(model.elements[f.element].type);
    for (int local : t.faces().at(f.face - 1).nodes)
      nodes.insert(model.element_nodes(f.element)[local]);
  }
  return static_cast<int>(nodes.size());
}

// SPEC §3.2.2: analytic contact pressure 3.294 (Lamé, plane strain), stated in the heading;
// internal pressure 5 on the 16 bore faces, external 3 on the 16 rim faces.
TEST_F(ContactLoads, CylindersPressuresAndAnalyticValue) {
  const auto r = build("cylinders", {});
  const std::string key = "analytic contact pressure ";
  const std::size_t at = r.model.heading.find(key);
  ASSERT_NE(at, std::string::npos) << r.model.heading;
  EXPECT_NEAR(std::atof(r.model.heading.c_str() + at + key.size()), 3.294, 1e-3);
  std::map<double, int> faces_by_pressure;
  for (const DistributedLoad& d : r.model.steps.at(0).dloads) ++faces_by_pressure[d.magnitude];
  EXPECT_EQ(faces_by_pressure[5.0], 16);
  EXPECT_EQ(faces_by_pressure[3.0], 16);
  EXPECT_FALSE(r.model.surface_interactions.at("CYLINDERS").friction.has_value());  // mu = 0
}

// SPEC §3.2.3: pressure 2e6 on the 40 top faces of the upper beam; --mu picks the law.
TEST_F(ContactLoads, TwoCantileversFrictionLaws) {
  const auto r = build("two-cantilevers", {});
  EXPECT_EQ(r.model.steps.at(0).dloads.size(), 40u);
  for (const DistributedLoad& d : r.model.steps.at(0).dloads) EXPECT_EQ(d.magnitude, 2e6);
  const auto& friction = r.model.surface_interactions.at("BEAMS").friction;
  ASSERT_TRUE(friction.has_value());
  EXPECT_EQ(friction->kind, Friction::Kind::Isotropic);
  EXPECT_EQ(friction->mu, 0.2);
  const auto rough = build("two-cantilevers", {{"mu", "rough"}});
  EXPECT_EQ(rough.model.surface_interactions.at("BEAMS").friction->kind, Friction::Kind::Rough);
  const auto smooth = build("two-cantilevers", {{"mu", "0"}});
  EXPECT_FALSE(smooth.model.surface_interactions.at("BEAMS").friction.has_value());
  EXPECT_NE(error_of("two-cantilevers", {{"mu", "-1"}}).find("--mu: expected a coefficient"),
            std::string::npos);
  // The tip set holds the upper beam's own end nodes only (3 x 2 corner nodes for C3D8).
  const auto c8 = build("two-cantilevers", {{"element", "C3D8"}});
  EXPECT_EQ(c8.model.nsets.at("TIP").nodes.size(), 6u);
}

// SPEC §3.2.4: C3D21 contact mesh 4 x 4 = 9 x 9 = 81 nodes, C3D28 3 x 3 = 10 x 10 = 100 nodes;
// P = 1000 down at the punch's top corner on the axis; --mu2 makes the friction anisotropic.
TEST_F(ContactLoads, PunchOnHalfSpaceContactNodesAndFriction) {
  const auto c21 = build("punch-halfspace", {{"element", "C3D21"}});
  EXPECT_EQ(slave_node_count(c21.model, elements_.registry), 81);
  const auto c28 = build("punch-halfspace", {{"element", "C3D28"}});
  EXPECT_EQ(slave_node_count(c28.model, elements_.registry), 100);
  ASSERT_EQ(c21.model.steps.at(0).cloads.size(), 1u);
  const ConcentratedLoad& load = c21.model.steps[0].cloads[0];
  EXPECT_EQ(load.dof, 3);
  EXPECT_EQ(load.value, -1000.0);
  const Vec3& x = c21.model.coords[load.node];
  EXPECT_NEAR(std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2] - 10), 0.0, 1e-12);
  EXPECT_EQ(c21.model.surface_interactions.at("PAD").friction->mu, 0.04);

  const auto aniso = build("punch-halfspace", {{"mu", "0.04"}, {"mu2", "0.4"}});
  const Friction& f = *aniso.model.surface_interactions.at("PAD").friction;
  EXPECT_EQ(f.kind, Friction::Kind::Anisotropic);
  EXPECT_EQ(f.mu, 0.04);
  EXPECT_EQ(f.mu2, 0.4);
  ASSERT_TRUE(aniso.model.orientations.count(f.orientation));
  EXPECT_NE(error_of("punch-halfspace", {{"mu", "0"}, {"mu2", "0.4"}}).find("--mu2 needs"),
            std::string::npos);
}

// SPEC §3.2.1 stand-in: the 8 contact elements shrink 4:1 towards the punch edge x = 1; unit
// pressure on the 8 punch-top faces.
TEST_F(ContactLoads, PunchOnFoundationGrading) {
  const auto r = build("punch-foundation", {{"element", "C3D8"}});
  std::set<double> xs;
  for (int n : r.model.nsets.at("PUNCHBOTTOM").nodes) xs.insert(r.model.coords[n][0]);
  ASSERT_EQ(xs.size(), 9u);
  const std::vector<double> x(xs.begin(), xs.end());
  EXPECT_NEAR((x[1] - x[0]) / (x[8] - x[7]), 4.0, 1e-9);
  EXPECT_EQ(r.model.steps.at(0).dloads.size(), 8u);
}

// SPEC §4.2 model A: heating the shaft by 100 with alpha 2e-5 (step 1), then the axial pressures
// 52.5 and 72 on the sleeve's top annulus (12 x 4 faces of the quarter).
TEST_F(ContactLoads, ShrinkFitAxialSteps) {
  const auto r = build("shrink-fit", {{"element", "C3D8"}});
  const Model& m = r.model;
  ASSERT_EQ(m.steps.size(), 3u);
  EXPECT_EQ(m.materials.at(m.sections.at(0).material_index).expansion.value_or(0), 2e-5);
  EXPECT_EQ(static_cast<int>(m.initial_temperatures.size()), m.node_count());
  std::set<int> shaft_nodes;
  for (int e : m.elsets.at("SHAFT").elements)
    for (int k = 0; k < m.elements[e].node_count; ++k) shaft_nodes.insert(m.element_nodes(e)[k]);
  EXPECT_EQ(m.steps[0].temperatures.size(), shaft_nodes.size());
  for (const NodalTemperature& t : m.steps[0].temperatures) {
    EXPECT_EQ(t.value, 100.0);
    EXPECT_EQ(shaft_nodes.count(t.node), 1u);
  }
  EXPECT_EQ(m.steps[1].dloads.size(), 48u);
  EXPECT_EQ(m.steps[1].dloads.at(0).magnitude, 52.5);
  EXPECT_EQ(m.steps[2].dloads.at(0).magnitude, 72.0);
  EXPECT_EQ(m.surface_interactions.at("FIT").friction->mu, 0.2);

  const auto clearance = build("shrink-fit", {{"element", "C3D8"}, {"fit", "clearance"}});
  EXPECT_NEAR(clearance.model.contact_pairs.at(0).clearance.value_or(0), -0.02, 1e-15);
  EXPECT_TRUE(clearance.model.steps[0].temperatures.empty());
  EXPECT_NE(error_of("shrink-fit", {{"load-case", "torque"}}).find("needs --model B"),
            std::string::npos);
  EXPECT_NE(error_of("shrink-fit", {{"around", "5"}}).find("--around must be even"),
            std::string::npos);
}

// SPEC §4.2 model B, load case 2B: torques 300 and 850 Nm (N mm here) as tangential forces on the
// sleeve's lower outer circle: zero resultant force, moment about z = T; the shaft base is held
// tangentially through a cylindrical *TRANSFORM; mu = 0.4.
TEST_F(ContactLoads, ShrinkFitTorqueCouples) {
  for (const char* fam : {"C3D8", "C3D20"}) {
    const auto r = build("shrink-fit", {{"element", fam}, {"model", "B"}});
    const Model& m = r.model;
    ASSERT_EQ(m.steps.size(), 3u);
    const double torques[2] = {300e3, 850e3};
    for (int s = 1; s <= 2; ++s) {
      double fx = 0, fy = 0, mz = 0;
      for (const ConcentratedLoad& c : m.steps[s].cloads) {
        const Vec3& x = m.coords[c.node];
        EXPECT_NEAR(std::hypot(x[0], x[1]), 15.0, 1e-9);
        EXPECT_NEAR(x[2], 20.0, 1e-9);
        if (c.dof == 1) {
          fx += c.value;
          mz -= x[1] * c.value;
        } else {
          fy += c.value;
          mz += x[0] * c.value;
        }
      }
      EXPECT_NEAR(fx, 0.0, 1e-9 * torques[s - 1]) << fam;
      EXPECT_NEAR(fy, 0.0, 1e-9 * torques[s - 1]) << fam;
      EXPECT_NEAR(mz, torques[s - 1], 1e-9 * torques[s - 1]) << fam;
    }
    ASSERT_EQ(m.transforms.size(), 1u);
    EXPECT_EQ(m.transforms[0].axes.system, CoordinateSystem::Cylindrical);
    EXPECT_EQ(m.surface_interactions.at("FIT").friction->mu, 0.4);
  }
}

// SPEC §4.3: 20 MPa on the pin's 24 top faces; only the sleeve's bottom is held (the pin's bottom
// face lies in the same plane z = 0 and must stay free to be pushed in).
TEST_F(ContactLoads, ConicalFitHoldsTheSleeveOnly) {
  const auto r = build("conical-fit", {{"element", "C3D20"}});
  const Model& m = r.model;
  EXPECT_EQ(m.steps.at(0).dloads.size(), 24u);
  for (const DistributedLoad& d : m.steps[0].dloads) EXPECT_EQ(d.magnitude, 20.0);
  std::set<int> pin_nodes;
  for (int e : m.elsets.at("PIN").elements)
    for (int k = 0; k < m.elements[e].node_count; ++k) pin_nodes.insert(m.element_nodes(e)[k]);
  const auto& base = m.nsets.at("SLEEVE_BASE").nodes;
  EXPECT_FALSE(base.empty());
  for (int n : base) EXPECT_EQ(pin_nodes.count(n), 0u);
  for (const Boundary& b : m.boundaries) {
    if (b.dof == 3) {
      EXPECT_EQ(pin_nodes.count(b.node), 0u) << "pin node held axially";
    }
  }
}

}  // namespace
}  // namespace styk
