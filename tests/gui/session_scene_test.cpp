// The CPU side of the 3D view: layers hide geometry, fields and deformation come from the results,
// orbit/pan/zoom change only the camera, the probe finds the node under the cursor, and the
// path chart reads the field along a node set.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "session/document.hpp"
#include "session/path_plot.hpp"
#include "session/scene.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/render/camera.hpp"

namespace styk::gui {
namespace {

const std::string kCantilever = std::string(STYK_SOURCE_DIR) + "/samples/cantilever-c3d20.inp";

class SceneTest : public ::testing::Test {
 protected:
  SceneTest() : doc(registry) {
    register_builtin_elements(registry);
    doc.open_inp(kCantilever);
  }
  // Results made up from the coordinates (a bending-like displacement and an axial stress that
  // grows along the beam), so the view logic is tested without the solver.
  void solve() {
    const Model& m = doc.model();
    IncrementResult inc;
    for (const Vec3& x : m.coords) {
      inc.U.push_back({1e-4 * x[2], 2e-5 * x[0], -1e-3 * x[0] * x[0]});
      inc.RF.push_back({0, 0, 0});
      inc.S_nodal_I.push_back({10.0 * x[0], x[1], 0, 0.5 * x[2], 0, 0});
      inc.S_nodal_II.push_back({9.0 * x[0], 0, 0, 0, 0, 0});
    }
    Results results;
    results.increments.push_back(inc);
    doc.attach_results(results, "");
  }
  ElementRegistry registry;
  Document doc;
};

TEST_F(SceneTest, MeshOnlySceneAndHiddenLayers) {
  Scene scene;
  DisplaySettings settings;
  scene.rebuild(doc, settings);
  ASSERT_FALSE(scene.empty());
  EXPECT_GT(scene.triangle_count(), 0u);
  EXPECT_FALSE(scene.frame(400, 300, {}).has_field);
  settings.field = "S.mises";
  EXPECT_THROW(scene.rebuild(doc, settings), InputError);  // no results yet
  doc.layers().set_visible(doc.layers().layers()[0].name, false);
  settings.field.clear();
  scene.rebuild(doc, settings);
  EXPECT_TRUE(scene.empty());
}

TEST_F(SceneTest, MisesContourAndDeformationFromTheResults) {
  solve();
  Scene scene;
  DisplaySettings settings;
  settings.field = "S.mises";
  settings.averaging = render::Averaging::MethodI;
  settings.bands = 8;
  scene.rebuild(doc, settings);
  ASSERT_TRUE(scene.field());
  const render::ScalarField expected = render::evaluate_field(
      doc.model(), doc.results()->increments.back(), "S.mises", render::Averaging::MethodI);
  double lo = 1e300, hi = -1e300;
  for (double v : expected.values) lo = std::min(lo, v), hi = std::max(hi, v);
  EXPECT_DOUBLE_EQ(scene.colors().min, lo);
  EXPECT_DOUBLE_EQ(scene.colors().max, hi);
  EXPECT_EQ(scene.colors().bands, 8);
  // Auto scale: the largest displacement is drawn as 0.1 of the model size.
  const double umax = render::max_displacement(doc.results()->increments.back(), {});
  const render::Frame& frame = scene.frame(640, 480, {});
  const auto& g = frame.geometry;
  const double diagonal =
      std::hypot(g.upper[0] - g.lower[0], g.upper[1] - g.lower[1], g.upper[2] - g.lower[2]);
  EXPECT_GT(scene.deformation_scale() * umax, 0.05 * diagonal);
  EXPECT_LT(scene.deformation_scale() * umax, 0.2 * diagonal);
  settings.auto_scale = false;
  settings.scale = 3.0;
  scene.rebuild(doc, settings);
  EXPECT_DOUBLE_EQ(scene.deformation_scale(), 3.0);
  settings.bands = 30;
  EXPECT_THROW(scene.rebuild(doc, settings), InputError);
  // An edit makes the results stale: they are dropped.
  doc.apply(material_command(doc.model(), {"EXTRA", 1.0, 0.3, 0.0}));
  EXPECT_EQ(doc.results(), nullptr);
}

TEST_F(SceneTest, OrbitPanAndZoomChangeOnlyTheCamera) {
  Scene scene;
  scene.rebuild(doc, {});
  ViewState view;
  const std::vector<render::Vertex> before = scene.frame(400, 300, view).geometry.face_vertices;
  const render::Mat4 iso = scene.frame(400, 300, view).camera.view;
  view.spec.azimuth = 30;
  view.spec.zoom = 2;
  view.pan_right = 0.1;
  const render::Frame& turned = scene.frame(400, 300, view);
  EXPECT_NE(turned.camera.view, iso);
  EXPECT_EQ(turned.geometry.face_vertices.size(), before.size());
  EXPECT_EQ(std::memcmp(turned.geometry.face_vertices.data(), before.data(),
                        before.size() * sizeof(render::Vertex)),
            0);
}

TEST_F(SceneTest, ProbeFindsTheNodeUnderTheCursorAndItsValue) {
  solve();
  Scene scene;
  DisplaySettings settings;
  settings.field = "U.mag";
  settings.deformed = false;
  scene.rebuild(doc, settings);
  const render::Frame& frame = scene.frame(800, 600, {});
  // Project a tip node (the largest x) to pixels and probe there.
  const NodeSet* tip = doc.model().find_nset("TIP");
  ASSERT_TRUE(tip);
  int target = -1;
  float nearest = 1e30f;
  for (int n : tip->nodes) {
    const Vec3& x = doc.model().coords[n];
    const Vec3& o = frame.geometry.origin;
    const auto ndc =
        render::project(frame.camera, {float(x[0] - o[0]), float(x[1] - o[1]), float(x[2] - o[2])});
    if (ndc[2] < nearest) nearest = ndc[2], target = n;
  }
  const Vec3& x = doc.model().coords[target];
  const Vec3& o = frame.geometry.origin;
  const auto ndc =
      render::project(frame.camera, {float(x[0] - o[0]), float(x[1] - o[1]), float(x[2] - o[2])});
  const auto& area = frame.overlay.model;
  const int px = int(std::lround(area.x + (ndc[0] + 1) * 0.5 * area.width));
  const int py = int(std::lround(area.y + (1 - ndc[1]) * 0.5 * area.height));
  const std::optional<ProbeResult> hit = scene.probe(px, py, 3);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->node, target);
  const Vec3& u = doc.results()->increments.back().U[target];
  ASSERT_TRUE(hit->value);
  EXPECT_NEAR(*hit->value, std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), 1e-12);
  EXPECT_FALSE(scene.probe(1, 1, 3));  // the corner of the picture: no node
}

TEST_F(SceneTest, PathChartRunsAlongTheNodeSet) {
  solve();
  Scene scene;
  DisplaySettings settings;
  settings.field = "U.z";
  scene.rebuild(doc, settings);
  const std::vector<PathPoint> points = field_along_node_set(scene, doc.model(), "NALL");
  ASSERT_EQ(points.size(), doc.model().find_nset("NALL")->nodes.size());
  for (std::size_t i = 1; i < points.size(); ++i)
    EXPECT_LE(points[i - 1].distance, points[i].distance);
  for (const PathPoint& p : points) {
    const int n = doc.model().node_index(p.node_id);
    EXPECT_DOUBLE_EQ(p.value, doc.results()->increments.back().U[n][2]);
  }
  EXPECT_THROW(field_along_node_set(scene, doc.model(), "NOPE"), InputError);
}

}  // namespace
}  // namespace styk::gui
