// The "Revolve" geometry object (SPEC §5 volumes: geometry objects meshed isoparametrically with
// user densities): the SPEC §4.2 shrink-fit bodies built from two revolves, their surfaces, the
// coincident interface nodes, the contact layer, and what the dialog refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "refusal.hpp"
#include "session/revolve.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/mesher/quality.hpp"

namespace styk::gui {
namespace {

constexpr double kPi = 3.14159265358979323846;

using test::refusal;

double radius(const Vec3& x) { return std::hypot(x[0], x[1]); }

// SPEC §4.2 geometry: shaft Ø20 x 60 (solid), sleeve Ø20/Ø30 x 20 centred; quarter models.
RevolveInput shaft_input() {
  RevolveInput in;
  in.name = "SHAFT";
  in.r_inner = 0;
  in.r_outer = 10;
  in.z0 = 0;
  in.z1 = 60;
  in.angle = 90;
  in.radial = 2;
  in.axial = 12;
  in.around = 6;
  in.material = "STEEL";
  return in;
}
RevolveInput sleeve_input() {
  RevolveInput in;
  in.name = "SLEEVE";
  in.r_inner = 10;
  in.r_outer = 15;
  in.z0 = 20;
  in.z1 = 40;
  in.angle = 90;
  in.radial = 2;
  in.axial = 4;
  in.around = 6;
  in.material = "STEEL";
  return in;
}

class RevolveTest : public ::testing::Test {
 protected:
  RevolveTest() {
    setup_element_registry(registry, libraries, {build_plugin_directory()});
    Material m;
    m.name = "STEEL";
    m.young = 200000.0;
    m.poisson = 0.3;
    model.materials.push_back(m);
  }
  PluginLibraries libraries;
  ElementRegistry registry;
  Model model;
};

// A solid quarter: O-grid of 3 x 3 core + 2 x (2 x 3) ring elements per row, 12 rows = 252
// elements; the volume of the C3D20 mesh (nodes exactly on the circle) is the quarter cylinder's
// pi 10^2 60 / 4 = 4712.389 within 1e-4 (quadratic arcs of 15 degrees: measured -9.8e-6).
TEST_F(RevolveTest, SolidQuarterIsAnOGridWithItsSurfaces) {
  const Model m = model_with_revolve(model, shaft_input(), registry);
  EXPECT_EQ(m.element_count(), 252);
  const mesher::QualityReport q = mesher::assess_quality(m, registry);
  EXPECT_GT(q.min_jacobian_ratio, 0.0);
  std::printf("quarter shaft volume %.6f, relative error %.2e\n", q.volume,
              q.volume / (kPi * 100 * 60 / 4) - 1);
  EXPECT_NEAR(q.volume, kPi * 100 * 60 / 4, 1e-4 * kPi * 100 * 60 / 4);
  EXPECT_FALSE(m.surfaces.count("SHAFT_INNER"));
  EXPECT_EQ(m.surfaces.at("SHAFT_OUTER").faces.size(), 6u * 12u);
  EXPECT_EQ(m.surfaces.at("SHAFT_BOTTOM").faces.size(), 21u);
  EXPECT_EQ(m.surfaces.at("SHAFT_TOP").faces.size(), 21u);
  EXPECT_EQ(m.surfaces.at("SHAFT_CUT0").faces.size(), 5u * 12u);  // (3 core + 2 ring) x 12
  EXPECT_EQ(m.surfaces.at("SHAFT_CUT1").faces.size(), 5u * 12u);
  for (int n : m.nsets.at("SHAFT_OUTER").nodes) EXPECT_NEAR(radius(m.coords[n]), 10.0, 1e-9);
  for (int n : m.nsets.at("SHAFT_CUT0").nodes) EXPECT_NEAR(m.coords[n][1], 0.0, 1e-9);  // y = 0
  for (int n : m.nsets.at("SHAFT_CUT1").nodes) EXPECT_NEAR(m.coords[n][0], 0.0, 1e-9);  // x = 0
  for (int n : m.nsets.at("SHAFT_TOP").nodes) EXPECT_NEAR(m.coords[n][2], 60.0, 1e-9);
  EXPECT_EQ(m.nsets.at("SHAFT").nodes.size(), static_cast<std::size_t>(m.node_count()));
  for (const Element& e : m.elements) EXPECT_EQ(e.section, 0);
}

// The sleeve shares the shaft's cylinder r = 10 over z 20..40: every node of SLEEVE_INNER has a
// coincident node on SHAFT_OUTER (to 1e-9), and none is shared (two bodies, a contact interface).
TEST_F(RevolveTest, TwoRevolvesSharingACylinderGetCoincidentSeparateNodes) {
  Model m = model_with_revolve(model, shaft_input(), registry);
  m = model_with_revolve(m, sleeve_input(), registry);
  const mesher::QualityReport q = mesher::assess_quality(m, registry);
  EXPECT_NEAR(q.volume, kPi * 100 * 60 / 4 + kPi * 125 * 20 / 4, 1e-4 * q.volume);
  const std::vector<int>& shaft = m.nsets.at("SHAFT_OUTER").nodes;
  const std::vector<int>& sleeve = m.nsets.at("SLEEVE_INNER").nodes;
  EXPECT_EQ(sleeve.size(), 93u);  // (9 x 13) grid points of 4 x 6 quadratic faces, less 24 centres
  for (int s : sleeve) {
    EXPECT_FALSE(std::binary_search(shaft.begin(), shaft.end(), s));
    int coincident = 0;
    for (int n : shaft) {
      const Vec3 &a = m.coords[s], &b = m.coords[n];
      coincident += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) < 1e-9;
    }
    EXPECT_EQ(coincident, 1) << "sleeve node " << m.node_ids[s];
  }
  EXPECT_GT(*std::min_element(m.node_ids.begin(), m.node_ids.end()), 0);
  EXPECT_EQ(m.sections.size(), 2u);
}

// A full ring closes on itself (no cut planes; nodes at 0 and 360 degrees merged): C3D8, one
// element radially and axially, 8 around = 2 x 2 x 8 nodes.
TEST_F(RevolveTest, FullRingClosesWithoutCutPlanes) {
  RevolveInput in = sleeve_input();
  in.type = "C3D8";
  in.angle = 360;
  in.radial = 1;
  in.axial = 1;
  in.around = 8;
  in.axis = {1, 0, 0};  // about x: angle 0 along y (revolve_reference_direction)
  const Model m = model_with_revolve(model, in, registry);
  EXPECT_EQ(m.node_count(), 32);
  EXPECT_EQ(m.element_count(), 8);
  EXPECT_FALSE(m.surfaces.count("SLEEVE_CUT0"));
  EXPECT_EQ(m.surfaces.at("SLEEVE_OUTER").faces.size(), 8u);
  for (int n : m.nsets.at("SLEEVE_BOTTOM").nodes) EXPECT_NEAR(m.coords[n][0], 20.0, 1e-9);
  EXPECT_GT(mesher::assess_quality(m, registry).min_jacobian_ratio, 0.0);
}

// C3D21 contact layer on the sleeve's bore: the 6 x 4 elements touching it, their S1 on it.
TEST_F(RevolveTest, ContactLayerOnTheChosenSide) {
  RevolveInput in = sleeve_input();
  in.type = "C3D21";
  in.layer_side = "INNER";
  const Model m = model_with_revolve(model, in, registry);
  int c3d21 = 0;
  for (const Element& e : m.elements) c3d21 += e.type == "C3D21";
  EXPECT_EQ(c3d21, 24);
  for (const SurfaceFace& f : m.surfaces.at("SLEEVE_INNER").faces) {
    EXPECT_EQ(m.elements[f.element].type, "C3D21");
    EXPECT_EQ(f.face, 1);
  }
  EXPECT_GT(mesher::assess_quality(m, registry).min_jacobian_ratio, 0.0);
}

TEST_F(RevolveTest, RefusesWhatCannotBeMeshed) {
  const auto refused = [&](const std::function<void(RevolveInput&)>& change) {
    RevolveInput in = shaft_input();
    change(in);
    return refusal([&] { check_revolve(in, model, registry); });
  };
  EXPECT_EQ(refused([](RevolveInput&) {}), "(accepted)");
  EXPECT_EQ(refused([](RevolveInput& in) { in.angle = 45; }),
            "a solid (inner radius 0) is meshed as an O-grid and needs an angle of 90, 180, 270 "
            "or 360 degrees");
  EXPECT_EQ(refused([](RevolveInput& in) { in.around = 5; }),
            "a solid (inner radius 0) needs an even number of divisions around per 90 degrees: 5 "
            "around 90 degrees is not a multiple of 2");
  EXPECT_EQ(refused([](RevolveInput& in) { in.z1 = 0; }), "z to must be above z from");
  EXPECT_EQ(refused([](RevolveInput& in) { in.r_outer = -1; }),
            "outer radius must be above the inner radius");
  EXPECT_EQ(refused([](RevolveInput& in) {
              in.axis = {0, 0, 0};
            }),
            "the axis direction must not be zero");
  EXPECT_EQ(refused([](RevolveInput& in) { in.axial = 0; }),
            "axial divisions must be at least 1, not 0");
  EXPECT_EQ(refused([](RevolveInput& in) { in.material = "BRASS"; }),
            "no material BRASS in the model");
  EXPECT_EQ(refused([](RevolveInput& in) {
              in.type = "C3D28";
              in.layer_side = "INNER";
            }),
            "a solid (inner radius 0) has no INNER side");
  const Model m = model_with_revolve(model, shaft_input(), registry);
  EXPECT_EQ(refusal([&] { check_revolve(shaft_input(), m, registry); }),
            "a set SHAFT exists already; choose another name");
}

TEST_F(RevolveTest, CommandIsUndoable) {
  UndoStack history;
  history.push(model, revolve_command(model, shaft_input(), registry));
  EXPECT_EQ(model.element_count(), 252);
  EXPECT_EQ(history.undo_text(), "Revolve SHAFT");
  history.undo(model);
  EXPECT_EQ(model.element_count(), 0);
  EXPECT_TRUE(model.surfaces.empty());
}

}  // namespace
}  // namespace styk::gui
