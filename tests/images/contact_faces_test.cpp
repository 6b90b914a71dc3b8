// Contact fields drawn on the faces that carry them (docs/render.md "Contact results"): only the
// slave faces are coloured, every other face stays neutral grey; a face whose nodes are all slave
// nodes but which is not a slave face (a cut face, the far face of a thin layer) stays grey too;
// and when the slave faces are hidden in the view (under the master body), the picture shows them
// alone, with a note in the title block.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

#include "image_models.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

using Colour = std::array<int, 3>;

Colour bytes(const render::Rgb& c) {
  return {render::to_byte(c.r), render::to_byte(c.g), render::to_byte(c.b)};
}

class ContactFaces : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    libraries_ = std::make_unique<PluginLibraries>();
    registry_ = std::make_unique<ElementRegistry>(make_test_registry(*libraries_));
    scene_ = std::make_unique<TestScene>(make_scene("contact_block", *registry_));
  }
  static void TearDownTestSuite() {
    scene_.reset();
    registry_.reset();
    libraries_.reset();
  }
  static render::RenderOptions cpress() {
    render::RenderOptions o;
    o.width = 640, o.height = 480;
    o.field = "CPRESS";
    o.bands = 8;
    o.samples = 1;  // exact colours
    return o;
  }
  struct Picture {
    render::Image image;
    render::Frame frame;
    std::set<Colour> bands;
  };
  static Picture draw(const Model& model, const IncrementResult& inc,
                      const render::RenderOptions& options) {
    const render::RenderJob job(model, *registry_, &inc, options);
    Picture p{render::Image{}, job.frame(1.0), {}};
    for (int i = 0; i < job.colors().bands; ++i) p.bands.insert(bytes(job.colors().band_color(i)));
    render::OsmesaRenderer renderer(options.width, options.height);
    p.image = renderer.render(p.frame);
    return p;
  }
  // Pixels of the model area in a band colour.
  static long band_pixels(const Picture& p) {
    long count = 0;
    const render::PixelRect& m = p.frame.overlay.model;
    for (int y = m.y; y < m.y + m.height; ++y)
      for (int x = m.x; x < m.x + m.width; ++x) {
        const auto* q = p.image.pixel(x, y);
        count += p.bands.count({q[0], q[1], q[2]});
      }
    return count;
  }
  // Face-vertex triangles coloured by the field (t >= 0 at all three corners).
  static std::size_t field_triangles(const render::FrameGeometry& g) {
    std::size_t count = 0;
    for (std::size_t t = 0; t + 2 < g.triangles.size(); t += 3)
      count += g.face_vertices[g.triangles[t]].t >= 0 &&
               g.face_vertices[g.triangles[t + 1]].t >= 0 &&
               g.face_vertices[g.triangles[t + 2]].t >= 0;
    return count;
  }

  static std::unique_ptr<PluginLibraries> libraries_;
  static std::unique_ptr<ElementRegistry> registry_;
  static std::unique_ptr<TestScene> scene_;
};
std::unique_ptr<PluginLibraries> ContactFaces::libraries_;
std::unique_ptr<ElementRegistry> ContactFaces::registry_;
std::unique_ptr<TestScene> ContactFaces::scene_;

// Whether a pixel is a band colour under some light: the band colour scaled by one factor.
bool lit_band_colour(const std::uint8_t* q, const std::set<Colour>& bands) {
  for (const Colour& c : bands) {
    const int top = std::max({c[0], c[1], c[2]});
    const double shade = double(std::max({q[0], q[1], q[2]})) / top;
    if (shade < 0.3) continue;
    bool same = true;
    for (int k = 0; k < 3; ++k) same = same && std::abs(q[k] - shade * c[k]) <= 2.0;
    if (same) return true;
  }
  return false;
}

// Seen from below with the slab hidden, every pixel of the model is paper, ink, the neutral grey
// of the faces without contact output (under any light: equal channels), or a band colour under
// some light; the band colours cover the block's bottom only.
TEST_F(ContactFaces, NonContactFacesStayGrey) {
  render::RenderOptions o = cpress();
  o.layers = {"SLAB", "BLOCK"};
  o.hidden_layers = {"SLAB"};
  o.view.elevation = -75;
  o.undeformed_outline = false;
  const Picture p = draw(scene_->model, scene_->increment, o);
  long grey = 0, band = 0, other = 0;
  const render::PixelRect& m = p.frame.overlay.model;
  for (int y = m.y; y < m.y + m.height; ++y)
    for (int x = m.x; x < m.x + m.width; ++x) {
      const auto* q = p.image.pixel(x, y);
      if (q[0] == q[1] && q[1] == q[2])
        ++grey;  // paper, ink and the lit neutral grey
      else if (lit_band_colour(q, p.bands))
        ++band;
      else
        ++other;
    }
  EXPECT_GT(band, 5000);
  EXPECT_GT(grey, 5000);
  EXPECT_EQ(other, 0);
  // The coloured triangles are those of the 16 bottom faces of the block, nothing else.
  EXPECT_EQ(field_triangles(p.frame.geometry),
            field_triangles(draw(scene_->model, scene_->increment,
                                 [&] {
                                   render::RenderOptions only = o;
                                   only.field_faces = render::FieldFaces::Only;
                                   return only;
                                 }())
                                .frame.geometry));
}

// Contact output at every node of the block's lowest element layer (a synthetic copy: the nodes
// at z = 0.5 get entries too, with the bottom's normal): the side faces of that layer then have
// all their nodes in the output, but they are no slave faces. With the model's surfaces (the
// slave surface BLOCK_BOTTOM) and without them (as read from a results file, which keeps no
// surfaces: the normal test), only the 16 bottom faces are coloured.
TEST_F(ContactFaces, FacesWithEveryNodeInTheOutputButNoSlaveFaceStayGrey) {
  IncrementResult inc = scene_->increment;
  const Model& model = scene_->model;
  const std::vector<ContactNodeResult> bottom = inc.contact;
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    if (std::abs(x[2] - 0.5) < 1e-9 && x[0] > 1 - 1e-9 && x[0] < 3 + 1e-9 && x[1] > 1 - 1e-9 &&
        x[1] < 3 + 1e-9) {
      ContactNodeResult extra = bottom.front();
      extra.node = n;
      inc.contact.push_back(extra);
    }
  }
  render::RenderOptions o = cpress();
  o.layers = {"SLAB", "BLOCK"};
  o.hidden_layers = {"SLAB"};
  o.field_faces = render::FieldFaces::Only;
  const render::FrameGeometry with_surfaces = draw(model, inc, o).frame.geometry;
  Model results_file_model = model;  // a results file keeps neither surfaces nor pairs
  results_file_model.surfaces.clear();
  results_file_model.contact_pairs.clear();
  const render::FrameGeometry from_normals = draw(results_file_model, inc, o).frame.geometry;
  // 16 faces, 2 triangles each (flat C3D8 faces).
  EXPECT_EQ(field_triangles(with_surfaces), 32u);
  EXPECT_EQ(field_triangles(from_normals), 32u);
  EXPECT_EQ(with_surfaces.triangles.size(), 3u * 32u);  // only those faces are drawn
  EXPECT_EQ(from_normals.triangles.size(), 3u * 32u);
  for (const render::Vertex& v : from_normals.face_vertices)
    EXPECT_NEAR(v.position[2] + from_normals.origin[2], 0.0, 1e-6);  // all at the bottom, z = 0
}

// Seen from above with both bodies shown, the block's bottom lies under the block: the automatic
// choice draws the contact faces alone and says so in the title block; --all-faces keeps the
// grey model (no band colour seen), and from below with the slab hidden nothing is switched.
TEST_F(ContactFaces, HiddenContactFacesAreShownAloneWithANote) {
  const render::RenderOptions o = cpress();  // iso, from above, SLAB and BLOCK as one layer
  const render::RenderJob automatic(scene_->model, *registry_, &scene_->increment, o);
  EXPECT_TRUE(automatic.field_faces_only());
  EXPECT_NE(automatic.note().find("CPRESS on its faces alone"), std::string::npos)
      << automatic.note();
  const Picture shown = draw(scene_->model, scene_->increment, o);
  EXPECT_GT(band_pixels(shown), 10000);
  const std::vector<render::TextItem>& texts = shown.frame.overlay.texts;
  EXPECT_TRUE(std::any_of(texts.begin(), texts.end(), [](const render::TextItem& t) {
    return t.text.find("CPRESS on its faces alone") == 0;
  }));

  render::RenderOptions all = o;
  all.field_faces = render::FieldFaces::All;
  const render::RenderJob forced(scene_->model, *registry_, &scene_->increment, all);
  EXPECT_FALSE(forced.field_faces_only());
  EXPECT_TRUE(forced.note().empty());
  EXPECT_EQ(band_pixels(draw(scene_->model, scene_->increment, all)), 0);

  render::RenderOptions below = o;
  below.layers = {"SLAB", "BLOCK"};
  below.hidden_layers = {"SLAB"};
  below.view.elevation = -75;
  const render::RenderJob seen(scene_->model, *registry_, &scene_->increment, below);
  EXPECT_FALSE(seen.field_faces_only());
  EXPECT_TRUE(seen.note().empty());
}

// --contact-pair: by the slave surface's name, or by the pair's number when the model keeps no
// names (a results file); unknown ones are refused naming what exists.
TEST_F(ContactFaces, ContactPairIsChosenByNameOrNumber) {
  render::RenderOptions o = cpress();
  o.contact_pair = "block_bottom";
  EXPECT_EQ(render::RenderJob(scene_->model, *registry_, &scene_->increment, o).field()->name,
            "CPRESS");
  o.contact_pair = "1";
  EXPECT_NO_THROW(render::RenderJob(scene_->model, *registry_, &scene_->increment, o));
  o.contact_pair = "SLAB_TOP";
  try {
    render::RenderJob(scene_->model, *registry_, &scene_->increment, o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slave surfaces: BLOCK_BOTTOM"), std::string::npos)
        << e.what();
  }
  o.contact_pair = "2";
  EXPECT_THROW(render::RenderJob(scene_->model, *registry_, &scene_->increment, o), InputError);
  o.field = "U.x";
  o.contact_pair = "1";
  EXPECT_THROW(render::RenderJob(scene_->model, *registry_, &scene_->increment, o), InputError);
}

}  // namespace
}  // namespace styk::render_test
