// Node and element numbers on screen (drawn only where their point is seen) and values at the
// integration points drawn as points coloured by value (SPEC §5: "stresses at Gauss points").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "image_models.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

class Annotations : public ::testing::Test {
 protected:
  Annotations() : registry_(make_test_registry(libraries_)) {}
  render::Image draw(const TestScene& scene, const render::RenderOptions& o,
                     render::Frame* frame_out = nullptr) {
    const render::RenderJob job(scene.model, registry_,
                                scene.has_results ? &scene.increment : nullptr, o);
    const render::Frame frame = job.frame(1.0);
    if (frame_out) *frame_out = frame;
    render::OsmesaRenderer renderer(o.width, o.height);
    return renderer.render(frame);
  }
  static long differing(const render::Image& a, const render::Image& b) {
    long count = 0;
    for (std::size_t k = 0; k < a.rgba.size(); k += 4)
      count += a.rgba[k] != b.rgba[k] || a.rgba[k + 1] != b.rgba[k + 1] ||
               a.rgba[k + 2] != b.rgba[k + 2];
    return count;
  }
  static int node_at(const Model& model, const Vec3& x) {
    for (int n = 0; n < model.node_count(); ++n)
      if (std::abs(model.coords[n][0] - x[0]) + std::abs(model.coords[n][1] - x[1]) +
              std::abs(model.coords[n][2] - x[2]) <
          1e-9)
        return n;
    return -1;
  }
  PluginLibraries libraries_;
  ElementRegistry registry_;
};

// The 4 x 1 x 1 box seen from +z: the number of a node on the top face is drawn (the picture
// changes near it), that of the node right below it on the bottom face is not (hidden by the
// box: the picture equals the one without labels); element labels only for the elements with a
// face turned towards the eye, at that face.
TEST_F(Annotations, NumbersOfSeenEntitiesOnly) {
  const TestScene box = make_scene("box_mesh", registry_);
  render::RenderOptions o;
  o.width = 480, o.height = 360;
  o.view.name = "+z";
  const render::Image plain = draw(box, o);
  const int top = node_at(box.model, {2.0, 0.5, 1.0}), bottom = node_at(box.model, {2.0, 0.5, 0.0});
  ASSERT_GE(top, 0);
  ASSERT_GE(bottom, 0);
  o.labels.nodes = true;
  o.labels.only_nodes = {top};
  const render::Image labelled_top = draw(box, o);
  o.labels.only_nodes = {bottom};
  const render::Image labelled_bottom = draw(box, o);
  EXPECT_GT(differing(labelled_top, plain), 20);  // the marker and the digits
  EXPECT_EQ(differing(labelled_bottom, plain), 0);

  // Every skin node is a candidate; element labels for the 8 elements under the top face.
  o.labels.only_nodes.clear();
  o.labels.elements = true;
  render::Frame frame;
  draw(box, o, &frame);
  long nodes = 0, elements = 0;
  for (const render::SceneLabel& l : frame.overlay.labels) (l.marker ? nodes : elements) += 1;
  EXPECT_EQ(elements, 8);
  // The skin nodes: every node of a face of the box's skin.
  std::set<int> skin_nodes;
  const render::SkinModel skin(box.model, registry_, {render::whole_model_layer(box.model)}, {});
  const std::vector<FaceDef> faces = render::drawn_faces(*registry_.find("C3D20"));
  for (const auto& layer : skin.layers())
    for (const render::SkinFace& f : layer.faces)
      for (int a : faces[f.face].nodes) skin_nodes.insert(box.model.element_nodes(f.element)[a]);
  EXPECT_EQ(nodes, long(skin_nodes.size()));
  for (const render::SceneLabel& l : frame.overlay.labels) {
    if (l.marker) continue;  // element labels sit on the top face
    EXPECT_NEAR(l.position[2] + frame.geometry.origin[2], 1.0, 1e-6) << l.text;
  }
}

// S.11 at the 27 Gauss points of each of the 16 C3D20 elements: one point each, coloured by its
// value; seen from +z, the points of the top layer of elements lie in front, and the pixel at such
// a point has the band colour of its value.
TEST_F(Annotations, IntegrationPointValuesAreColouredPoints) {
  const TestScene box = make_scene("box", registry_);
  render::RenderOptions o;
  o.width = 640, o.height = 480;
  o.field = "S.11";
  o.ip_values = true;
  o.bands = 8;
  o.view.name = "+z";
  o.samples = 1;
  const render::RenderJob job(box.model, registry_, &box.increment, o);
  ASSERT_NE(job.point_field(), nullptr);
  const render::PointField& f = *job.point_field();
  EXPECT_EQ(f.values.size(), 16u * 27u);
  const auto [lo, hi] = std::minmax_element(f.values.begin(), f.values.end());
  EXPECT_DOUBLE_EQ(job.colors().min, *lo);
  EXPECT_DOUBLE_EQ(job.colors().max, *hi);
  const render::Frame frame = job.frame();
  EXPECT_EQ(frame.mode, render::DisplayMode::Wireframe);  // the points are seen through the mesh
  ASSERT_EQ(frame.geometry.ip_points.size(), 16u * 27u);
  render::OsmesaRenderer renderer(o.width, o.height);
  const render::Image image = renderer.render(frame);
  // The point with the largest z of all (top layer, top Gauss row) that lies inside the box's
  // x-y extent at the middle: check a handful of the top points.
  float top_z = -1e30f;
  for (const render::Vertex& v : frame.geometry.ip_points) top_z = std::max(top_z, v.position[2]);
  int checked = 0;
  for (std::size_t q = 0; q < frame.geometry.ip_points.size(); ++q) {
    const render::Vertex& v = frame.geometry.ip_points[q];
    if (v.position[2] < top_z - 1e-5f) continue;
    const std::array<float, 3> ndc =
        render::project(frame.camera, {v.position[0], v.position[1], v.position[2]});
    const render::PixelRect& m = frame.overlay.model;
    const int x = m.x + int((ndc[0] + 1) * 0.5f * m.width),
              y = m.y + int((1 - ndc[1]) * 0.5f * m.height);
    const double value = f.values[q];
    const int band = std::min(7, int(job.colors().normalized(value) * 8));
    const render::Rgb c = job.colors().band_color(band);
    const auto* p = image.pixel(x, y);
    EXPECT_EQ(p[0], render::to_byte(c.r)) << "point " << q;
    EXPECT_EQ(p[1], render::to_byte(c.g)) << "point " << q;
    EXPECT_EQ(p[2], render::to_byte(c.b)) << "point " << q;
    ++checked;
  }
  EXPECT_EQ(checked, 8 * 9);  // 8 top elements x 9 points of their top Gauss row
}

// The probe's list: the 27 points of element 1, in the rule's order, at the mapped positions,
// with the stored values.
TEST_F(Annotations, ElementPointValuesListTheStoredValues) {
  const TestScene box = make_scene("box", registry_);
  const render::PointField f = render::evaluate_point_field(box.model, box.increment, "S.mises");
  const TElement& c3d20 = *registry_.find("C3D20");
  const std::vector<render::PointValue> points =
      render::element_point_values(box.model, c3d20, f, 1);
  ASSERT_EQ(points.size(), 27u);
  for (const render::PointValue& p : points) {
    EXPECT_DOUBLE_EQ(p.value, f.values[box.increment.ip_offset[1] + p.number - 1]);
    const Tensor6 s = box.increment.S[box.increment.ip_offset[1] + p.number - 1];
    const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
    EXPECT_NEAR(
        p.value,
        std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])),
        1e-9);
  }
  // Point 1 is the rule's first, (-sqrt(0.6), -sqrt(0.6), -sqrt(0.6)), in element 1 (x 1..2).
  EXPECT_NEAR(points[0].natural[0], -std::sqrt(0.6), 1e-12);
  EXPECT_GT(points[0].position[0], 1.0);
  EXPECT_LT(points[0].position[0], 1.5);
  EXPECT_THROW(render::evaluate_point_field(box.model, box.increment, "U.x"), InputError);
}

}  // namespace
}  // namespace styk::render_test
