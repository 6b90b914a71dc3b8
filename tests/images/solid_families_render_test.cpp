// Tetrahedra, wedges and axisymmetric rings in the renderer (docs/render.md): the skin of a split
// block is its outer surface in triangles (tetrahedra) or triangles and quadrilaterals (wedges),
// closed and turned outwards (wedge faces 2-5 list their corners the other way round from
// tetrahedra and bricks: the renderer orients by geometry, not by node order), with every shading
// normal pointing out of the convex block; an axisymmetric section drawn revolved shows the ring
// with its bore.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image_models.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/split.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

class SolidFamilies : public ::testing::Test {
 protected:
  SolidFamilies() : registry_(make_test_registry(libraries_)) {}

  // The box [0,3] x [0,2] x [0,1] of 3 x 2 x 2 bricks of `brick`, split to `type` (or not).
  Model split_box(const std::string& brick, const std::string& type) const {
    mesher::Mesh mesh;
    mesher::mesh_block(mesh,
                       [](const Vec3& xi) {
                         return Vec3{1.5 * (xi[0] + 1), xi[1] + 1, 0.5 * (xi[2] + 1)};
                       },
                       {brick, {3, 2, 2}, {1, 1, 1}, "EALL"});
    if (type == "C3D4" || type == "C3D10") mesher::split_to_tetrahedra(mesh, registry_, type);
    if (type == "C3D6" || type == "C3D15") mesher::split_to_wedges(mesh, registry_, type);
    return mesher::to_model(mesh);
  }

  PluginLibraries libraries_;
  ElementRegistry registry_;
};

TEST_F(SolidFamilies, SplitBlocksHaveAClosedOutwardSkin) {
  struct Case {
    const char* brick;
    const char* type;
    std::size_t faces;  // skin faces of the box
  };
  // The box's surface: 2 (3 x 2) + 2 (3 x 2) + 2 (2 x 2) = 32 brick faces; tetrahedra halve
  // every one; wedges along z halve the 12 top and bottom faces only.
  for (const Case c :
       {Case{"C3D8", "C3D8", 32}, Case{"C3D8", "C3D4", 64}, Case{"C3D20", "C3D10", 64},
        Case{"C3D8", "C3D6", 44}, Case{"C3D20", "C3D15", 44}}) {
    const Model model = split_box(c.brick, c.type);
    render::RenderOptions o;
    o.width = 320, o.height = 240;
    o.mode = render::DisplayMode::Shaded;
    const render::RenderJob job(model, registry_, nullptr, o);
    EXPECT_EQ(job.skin().layers()[0].faces.size(), c.faces) << c.type;
    const render::Frame frame = job.frame(1.0);
    EXPECT_TRUE(frame.geometry.closed) << c.type;
    // Shading normals point out of the convex box: away from its centre.
    const Vec3 centre{1.5, 1.0, 0.5};
    int inward = 0;
    for (const render::Vertex& v : frame.geometry.face_vertices) {
      double dot = 0.0;
      for (int d = 0; d < 3; ++d)
        dot += v.normal[d] * (v.position[d] + frame.geometry.origin[d] - centre[d]);
      inward += dot < 0.0;
    }
    EXPECT_EQ(inward, 0) << c.type;
  }
}

// A CAX8 ring (r 2..4, z 0..1; 2 x 1 sections) drawn revolved through 360 degrees and seen along
// the axis (+y): the bore (r < 2) is background, the ring is drawn; 24 sectors of 2 sections make
// 48 C3D20 bricks whose outer skin is 24 x (2 + 2 + 2) faces (inner, outer walls and the two
// rims).
TEST_F(SolidFamilies, AxisymmetricSectionDrawnRevolved) {
  Model model;
  int id = 0;
  const double rs[5] = {2.0, 2.5, 3.0, 3.5, 4.0}, zs[3] = {0.0, 0.5, 1.0};
  for (double z : zs)
    for (double r : rs) model.add_node(++id, {r, z, 0.0}, {});
  const auto node = [](int i, int j) { return 5 * j + i; };  // index of (rs[i], zs[j])
  for (int e = 0; e < 2; ++e) {
    const int i = 2 * e;
    model.add_element(e + 1, "CAX8",
                      {node(i, 0), node(i + 2, 0), node(i + 2, 2), node(i, 2), node(i + 1, 0),
                       node(i + 2, 1), node(i + 1, 2), node(i, 1)},
                      {});
  }
  render::RenderOptions o;
  o.width = 300, o.height = 300;
  o.view.name = "+y";
  o.revolve_degrees = 360.0;
  const render::RenderJob job(model, registry_, nullptr, o);
  EXPECT_EQ(job.skin().layers()[0].faces.size(), 24u * 6u);
  render::OsmesaRenderer renderer(o.width, o.height);
  const render::Image image = renderer.render(job.frame(1.0));
  const std::uint8_t* centre = image.pixel(150, 150);
  EXPECT_TRUE(centre[0] == 255 && centre[1] == 255 && centre[2] == 255);  // the bore
  int drawn = 0;
  for (int x = 0; x < image.width; ++x) {
    const std::uint8_t* p = image.pixel(x, 150);
    drawn += !(p[0] == 255 && p[1] == 255 && p[2] == 255);
  }
  EXPECT_GT(drawn, 60);  // the ring's two walls across the middle row
  // Without the request the section is drawn flat, as a plane element.
  render::RenderOptions flat = o;
  flat.revolve_degrees = 0.0;
  const render::RenderJob plain(model, registry_, nullptr, flat);
  EXPECT_EQ(plain.skin().layers()[0].faces.size(), 2u);
}

}  // namespace
}  // namespace styk::render_test
