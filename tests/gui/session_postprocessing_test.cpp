// The desktop program's post-processing (docs/gui.md "Reading contact and integration-point
// results"), on the CPU side of the view: a contact field whose faces lie under the other body is
// drawn on those faces alone with a note; the unrolled contact map; values at the integration
// points and the probe's list of them; node numbers of the selection only.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "session/document.hpp"
#include "session/scene.hpp"
#include "session/selection_info.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::gui {
namespace {

const std::string kCylinders =
    std::string(STYK_SOURCE_DIR) + "/samples/spec-3.2.2-cylinders-c3d21.inp";
const std::string kCantilever = std::string(STYK_SOURCE_DIR) + "/samples/cantilever-c3d20.inp";

bool title_has(const render::Frame& frame, const std::string& words) {
  return std::any_of(
      frame.overlay.texts.begin(), frame.overlay.texts.end(),
      [&](const render::TextItem& t) { return t.text.find(words) != std::string::npos; });
}

// SPEC §3.2.2 cylinders (C3D21 contact layers), solved in process once for the suite.
class ContactPostprocessing : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    libraries_ = std::make_unique<PluginLibraries>();
    registry_ = std::make_unique<ElementRegistry>();
    ASSERT_TRUE(
        setup_element_registry(*registry_, *libraries_, {build_plugin_directory()}).empty());
    doc_ = std::make_unique<Document>(*registry_);
    doc_->open_inp(kCylinders);
    doc_->attach_results(
        run_static_analysis(doc_->model(), *registry_, SolveOptions{}, nullptr, nullptr), "");
  }
  static void TearDownTestSuite() {
    doc_.reset();
    registry_.reset();
    libraries_.reset();
  }
  static std::unique_ptr<PluginLibraries> libraries_;
  static std::unique_ptr<ElementRegistry> registry_;
  static std::unique_ptr<Document> doc_;
};
std::unique_ptr<PluginLibraries> ContactPostprocessing::libraries_;
std::unique_ptr<ElementRegistry> ContactPostprocessing::registry_;
std::unique_ptr<Document> ContactPostprocessing::doc_;

// In the iso view the inner cylinder's contact face lies under the outer cylinder: the first frame
// draws it alone, says so in the title block, and orbiting afterwards keeps that drawing. With
// "all faces" the grey model is drawn as asked.
TEST_F(ContactPostprocessing, HiddenContactFacesAreDrawnAloneWithANote) {
  Scene scene;
  DisplaySettings settings;
  settings.field = "CPRESS";
  settings.deformed = false;
  scene.rebuild(*doc_, settings);
  const std::size_t all_triangles = scene.triangle_count();
  const long before = scene.geometry_revision();
  const render::Frame& first = scene.frame(640, 480, {});
  EXPECT_TRUE(scene.field_faces_only());
  EXPECT_NE(scene.note().find("CPRESS on its faces alone"), std::string::npos) << scene.note();
  EXPECT_TRUE(title_has(first, "CPRESS on its faces alone"));
  EXPECT_GT(scene.geometry_revision(), before);  // the view uploads the new geometry
  // Its 16 C3D21 faces, on the finest grids: 32 x 32 cells of 2 triangles (the nearly uniform
  // pressure's corner/mid-edge ripple is large against its 12 narrow bands).
  EXPECT_EQ(scene.triangle_count(), 16u * 32u * 32u * 2u);
  ViewState turned;
  turned.spec.azimuth = 150;
  scene.frame(640, 480, turned);
  EXPECT_TRUE(scene.field_faces_only());

  settings.field_faces = render::FieldFaces::All;
  scene.rebuild(*doc_, settings);
  scene.frame(640, 480, {});
  EXPECT_FALSE(scene.field_faces_only());
  EXPECT_TRUE(scene.note().empty());
  EXPECT_EQ(scene.triangle_count(), all_triangles);
}

// The unrolled map: the z axis, radius 2, a quarter turn; a field that does not live on surfaces
// is refused with the reason.
TEST_F(ContactPostprocessing, UnrolledMapOfTheContactPressure) {
  Scene scene;
  DisplaySettings settings;
  settings.field = "CPRESS";
  settings.unrolled = true;
  scene.rebuild(*doc_, settings);
  ASSERT_NE(scene.unrolled(), nullptr);
  const render::UnrolledSurface& s = *scene.unrolled();
  EXPECT_EQ(s.kind, render::UnrolledSurface::Kind::Revolved);
  EXPECT_NEAR(s.radius, 2.0, 2e-3);
  EXPECT_NEAR(render::map_degrees(s, s.u_range[1]) - render::map_degrees(s, s.u_range[0]), 90.0,
              1e-3);
  const render::Frame& frame = scene.frame(640, 480, {});
  EXPECT_TRUE(title_has(frame, "Unrolled about the axis through (0, 0, 0) along (0, 0, 1)"));
  EXPECT_TRUE(title_has(frame, "angle"));
  EXPECT_TRUE(title_has(frame, "axial position"));
  EXPECT_EQ(frame.geometry.closed, false);
  for (const render::Vertex& v : frame.geometry.face_vertices) EXPECT_EQ(v.position[2], 0.0f);
  settings.field = "S.mises";
  try {
    scene.rebuild(*doc_, settings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lives on surfaces"), std::string::npos) << e.what();
  }
}

// Stresses at the integration points of the cantilever sample (made up from the points'
// positions: S.11 = 10 x), the probe's list for an element, and node numbers of the selection.
class PointPostprocessing : public ::testing::Test {
 protected:
  PointPostprocessing() : doc(registry) {
    register_builtin_elements(registry);
    doc.open_inp(kCantilever);
    const Model& m = doc.model();
    IncrementResult inc;
    inc.U.assign(m.coords.size(), Vec3{0, 0, 0});
    inc.ip_offset.push_back(0);
    Eigen::VectorXd N(20);
    Eigen::MatrixXd dN(20, 3);
    for (int e = 0; e < m.element_count(); ++e) {
      const TElement& element = *registry.find(m.elements[e].type);
      for (const Vec3& xi : element.rule(RuleKind::Full).points) {
        element.der(xi, N, dN);
        double x = 0.0;
        for (int a = 0; a < element.node_count(); ++a)
          x += N(a) * m.coords[m.element_nodes(e)[a]][0];
        inc.S.push_back({10.0 * x, 0, 0, 0, 0, 0});
      }
      inc.ip_offset.push_back(static_cast<int>(inc.S.size()));
    }
    Results results;
    results.increments.push_back(inc);
    doc.attach_results(results, "");
  }
  ElementRegistry registry;
  Document doc;
};

TEST_F(PointPostprocessing, IntegrationPointValuesAndTheProbe) {
  Scene scene;
  DisplaySettings settings;
  settings.field = "S.11";
  settings.ip_values = true;
  settings.deformed = false;
  scene.rebuild(doc, settings);
  ASSERT_NE(scene.point_field(), nullptr);
  const render::Frame& frame = scene.frame(640, 480, {});
  EXPECT_EQ(frame.mode, render::DisplayMode::Wireframe);
  EXPECT_EQ(frame.geometry.ip_points.size(), scene.point_field()->values.size());
  EXPECT_TRUE(title_has(frame, "S.11 (integration points)"));
  const std::optional<ElementProbe> probe = scene.element_probe(0);
  ASSERT_TRUE(probe);
  ASSERT_EQ(probe->points.size(), 27u);
  for (const render::PointValue& p : probe->points)
    EXPECT_NEAR(p.value, 10.0 * p.position[0], 1e-9);  // the value stored at that point
  const std::string summary = element_probe_summary(*probe);
  EXPECT_EQ(summary.rfind("element " + std::to_string(doc.model().elements[0].id) +
                              " C3D20: S.11 at 27 integration points, ",
                          0),
            0u)
      << summary;
  EXPECT_EQ(describe_element_probe(*probe).size(), 27u);
  EXPECT_EQ(describe_element_probe(*probe).front().rfind("point 1 (-0.774597", 0), 0u);
  // Without nodal stresses the nodal S.11 is refused, naming what the increment holds.
  settings.ip_values = false;
  try {
    scene.rebuild(doc, settings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("integration-point S (drawn at the points"),
              std::string::npos)
        << e.what();
  }
  settings.field = "U.x";
  scene.rebuild(doc, settings);
  EXPECT_FALSE(scene.element_probe(0));  // only with the integration-point display
  settings.ip_values = true;
  EXPECT_THROW(scene.rebuild(doc, settings), InputError);  // U has no values at the points
}

TEST_F(PointPostprocessing, NumbersOfTheSelectionOnly) {
  Scene scene;
  DisplaySettings settings;
  settings.labels.nodes = true;
  scene.rebuild(doc, settings);
  const std::size_t every = scene.frame(640, 480, {}).overlay.labels.size();
  EXPECT_GT(every, 50u);
  settings.labels_of_selection = true;
  scene.rebuild(doc, settings);
  EXPECT_TRUE(scene.frame(640, 480, {}).overlay.labels.empty());  // nothing selected
  Selection selection(PickKind::Node);
  selection.apply(SelectOp::Add, {PickedItem{PickKind::Node, 7, -1, 0}});
  scene.set_selection(selection);
  const render::Frame& frame = scene.frame(640, 480, {});
  ASSERT_EQ(frame.overlay.labels.size(), 1u);
  EXPECT_EQ(frame.overlay.labels.front().text, std::to_string(doc.model().node_ids[7]));
  EXPECT_GT(frame.overlay.label_pixels, 0);
}

}  // namespace
}  // namespace styk::gui
