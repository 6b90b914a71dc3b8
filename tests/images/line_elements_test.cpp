// Line elements in the renderer (docs/render.md "Line elements"): T3D2 bars have no faces, so no
// skin; they are drawn as bars through their nodes in every display mode but points, in the
// layer colour or the contour colours, deformed with the model, hidden behind solids and with
// their layer. The deck is tests/inputs/good/block_with_bars.inp (a 2 x 1 x 1 C3D8 block, bar 3
// from its tip corner (2,1,1) to (4,1,1), bar 4 from (0.5,2,0.5) to (1.5,2,0.5) behind it seen
// from -y); the results are synthetic: U = displacement_at(x) (image_models.hpp), so
// U.x = 0.01 x is known at every point of a bar.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "image_compare.hpp"
#include "image_models.hpp"
#include "render_args.hpp"
#include "styk/inp/reader.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

namespace fs = std::filesystem;
using render::Frame;
using render::Image;
using render::Rgb;

const std::string kDeck = std::string(STYK_SOURCE_DIR) + "/tests/inputs/good/block_with_bars.inp";

// The pixel (column, row of the picture) where a model point is drawn in `frame`.
std::array<int, 2> pixel_of(const Frame& frame, const Vec3& x) {
  const Vec3& o = frame.geometry.origin;
  const std::array<float, 3> ndc =
      render::project(frame.camera, {float(x[0] - o[0]), float(x[1] - o[1]), float(x[2] - o[2])});
  const render::PixelRect& area = frame.overlay.model;
  return {area.x + int(std::floor((ndc[0] + 1.0) * 0.5 * area.width)),
          area.y + int(std::floor((1.0 - ndc[1]) * 0.5 * area.height))};
}

bool same_colour(const std::uint8_t* p, const Rgb& c, int tolerance = 1) {
  return std::abs(p[0] - render::to_byte(c.r)) <= tolerance &&
         std::abs(p[1] - render::to_byte(c.g)) <= tolerance &&
         std::abs(p[2] - render::to_byte(c.b)) <= tolerance;
}

// Whether a pixel of colour `c` lies within `radius` pixels of (x, y).
bool colour_near(const Image& image, std::array<int, 2> at, const Rgb& c, int radius = 1) {
  for (int y = at[1] - radius; y <= at[1] + radius; ++y)
    for (int x = at[0] - radius; x <= at[0] + radius; ++x)
      if (x >= 0 && y >= 0 && x < image.width && y < image.height &&
          same_colour(image.pixel(x, y), c))
        return true;
  return false;
}

long count_colour(const Image& image, const render::PixelRect& r, const Rgb& c) {
  long count = 0;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) count += same_colour(image.pixel(x, y), c);
  return count;
}

Vec3 lerp(const Vec3& a, const Vec3& b, double s) {
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

class LineElements : public ::testing::Test {
 protected:
  LineElements() : registry_(make_test_registry(libraries_)), model_(read_inp(kDeck, registry_)) {
    increment_.step = 1, increment_.increment = 1;
    for (const Vec3& x : model_.coords) increment_.U.push_back(displacement_at(x));
  }

  // The block and the bars as two layers, 640 x 480.
  static render::RenderOptions options() {
    render::RenderOptions o;
    o.width = 640, o.height = 480;
    o.layers = {"BLOCK", "BARS"};
    o.samples = 1;  // exact colours: the 1 px outline is not blended with the paper
    return o;
  }

  struct Picture {
    Frame frame;
    Image image;
  };
  Picture render(const render::RenderOptions& o) const {
    const render::RenderJob job(model_, registry_, &increment_, o);
    Picture p{job.frame(1.0), {}};
    render::OsmesaRenderer renderer(o.width, o.height);
    p.image = renderer.render(p.frame);
    return p;
  }

  // The node coordinates of a node by its user id.
  Vec3 node(Id id) const { return model_.coords[model_.node_index(id)]; }

  PluginLibraries libraries_;
  ElementRegistry registry_;
  Model model_;
  IncrementResult increment_;
  const Rgb bar_colour_ = render::layer_palette(1);
};

TEST_F(LineElements, TrussesAreLineElementsAndBecomeBarsNotSkin) {
  // Detected from the formulation (no faces, 2 or 3 nodes), not from the name.
  EXPECT_TRUE(render::is_line_element(*registry_.find("T3D2")));
  for (const char* solid : {"C3D8", "C3D20", "CPS4", "C3D28"})
    EXPECT_FALSE(render::is_line_element(*registry_.find(solid))) << solid;
  EXPECT_EQ(render::line_node_order(*registry_.find("T3D2")), (std::vector<int>{0, 1}));

  const render::RenderJob job(model_, registry_, &increment_, options());
  ASSERT_EQ(job.skin().layers().size(), 2u);
  const auto& block = job.skin().layers()[0];
  const auto& bars = job.skin().layers()[1];
  EXPECT_EQ(block.faces.size(), 10u);  // 2 hexahedra: 12 faces, 2 shared
  EXPECT_TRUE(block.lines.empty());
  EXPECT_TRUE(bars.faces.empty());
  EXPECT_EQ(bars.lines, (std::vector<int>{2, 3}));  // elements 3 and 4

  // One segment per bar, from its first to its second node, relative to the frame origin.
  const Frame frame = job.frame();
  ASSERT_EQ(frame.geometry.bars.size(), 4u);
  const Vec3 ends[4] = {node(12), node(13), node(14), node(15)};
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d)
      EXPECT_FLOAT_EQ(frame.geometry.bars[k].position[d],
                      float(ends[k][d] - frame.geometry.origin[d]));
  // The bar reaches x = 4: the bounds (and so the camera) include it.
  EXPECT_FLOAT_EQ(frame.geometry.upper[0], float(4.0 - frame.geometry.origin[0]));
}

TEST_F(LineElements, BarsAreDrawnInTheLayerColourInEveryModeButPoints) {
  using render::DisplayMode;
  for (DisplayMode mode : {DisplayMode::Shaded, DisplayMode::ShadedEdges, DisplayMode::HiddenLine,
                           DisplayMode::Wireframe, DisplayMode::Points}) {
    render::RenderOptions o = options();
    o.mode = mode;
    const Picture p = render(o);
    const std::string name = render::display_mode_name(mode);
    // Bar 3 along its length (its nodes are points in every mode; its middle only a bar).
    const auto middle = pixel_of(p.frame, lerp(node(12), node(13), 0.5));
    const auto far = pixel_of(p.frame, lerp(node(12), node(13), 0.8));
    if (mode == DisplayMode::Points) {
      EXPECT_FALSE(colour_near(p.image, middle, bar_colour_, 2)) << name;
      continue;
    }
    EXPECT_TRUE(colour_near(p.image, middle, bar_colour_)) << name;
    EXPECT_TRUE(colour_near(p.image, far, bar_colour_)) << name;
    // A bar of frame.bar_width pixels, not a 1 px line: at least 70 % of its projected length
    // times that width (measured 0 to 5 % over, the square caps).
    const auto a = pixel_of(p.frame, node(12)), b = pixel_of(p.frame, node(13));
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    EXPECT_GE(count_colour(p.image, p.frame.overlay.model, bar_colour_),
              long(0.7 * length * p.frame.bar_width))
        << name;
  }
}

// With U.x in 12 bands (range 0 .. 0.04, the largest x being the bar's free end at x = 4), the
// bar's pixels at x = 2.2 and x = 3.8 have the band colours of U.x = 0.022 (band 6) and
// 0.038 (band 11): different colours, each matching the scale exactly (+-1 per channel).
TEST_F(LineElements, ContourColoursTheBarEndsFromTheColourScale) {
  render::RenderOptions o = options();
  o.field = "U.x";
  o.bands = 12;
  const Picture p = render(o);
  const render::ColorScale& scale = p.frame.colors;
  EXPECT_DOUBLE_EQ(scale.min, 0.0);
  EXPECT_DOUBLE_EQ(scale.max, 0.04);
  int bands[2] = {};
  for (int k = 0; k < 2; ++k) {
    const double s = k == 0 ? 0.1 : 0.9;  // x = 2.2, 3.8
    const Vec3 x = lerp(node(12), node(13), s);
    const double t = scale.normalized(0.01 * x[0]);
    bands[k] = std::min(int(std::floor(t * scale.bands)), scale.bands - 1);
    EXPECT_TRUE(colour_near(p.image, pixel_of(p.frame, x), scale.band_color(bands[k])))
        << "x = " << x[0] << ", band " << bands[k];
    EXPECT_FALSE(colour_near(p.image, pixel_of(p.frame, x), bar_colour_, 2));
  }
  EXPECT_EQ(bands[0], 6);
  EXPECT_EQ(bands[1], 11);
  // Smooth colours: the two ends differ too (rainbow, not band colours).
  o.smooth = true;
  const Picture smooth = render(o);
  const auto* near_end =
      smooth.image.pixel(pixel_of(smooth.frame, lerp(node(12), node(13), 0.1))[0],
                         pixel_of(smooth.frame, lerp(node(12), node(13), 0.1))[1]);
  const auto* far_end =
      smooth.image.pixel(pixel_of(smooth.frame, lerp(node(12), node(13), 0.9))[0],
                         pixel_of(smooth.frame, lerp(node(12), node(13), 0.9))[1]);
  EXPECT_GT(std::abs(near_end[0] - far_end[0]) + std::abs(near_end[1] - far_end[1]) +
                std::abs(near_end[2] - far_end[2]),
            100);
}

// Deformed by a factor 20: bar 3 runs from node 12 at (2.4, 1, 0.9) to node 13 at (4.8, 1, 0.6);
// its deformed middle (3.6, 1, 0.75) is drawn in the bar colour, its undeformed middle (3, 1, 1)
// in the grey of the undeformed outline.
TEST_F(LineElements, DeformedBarsFollowTheDisplacementOverTheirUndeformedOutline) {
  render::RenderOptions o = options();
  o.deform = render::parse_deform("20");
  const Picture p = render(o);
  const Vec3 deformed_middle{3.6, 1.0, 0.75};
  EXPECT_TRUE(colour_near(p.image, pixel_of(p.frame, deformed_middle), bar_colour_));
  const auto undeformed = pixel_of(p.frame, lerp(node(12), node(13), 0.5));
  EXPECT_FALSE(colour_near(p.image, undeformed, bar_colour_, 2));
  EXPECT_TRUE(colour_near(p.image, undeformed, render::kOutline));
}

// Bar 4 (y = 2) seen from -y lies behind the block (y 0..1), which covers its whole projection:
// not one of its pixels shows, in shaded and hidden-line modes. Seen from +y it is in front.
TEST_F(LineElements, BarBehindTheBlockIsHidden) {
  const Vec3 middle = lerp(node(14), node(15), 0.5), quarter = lerp(node(14), node(15), 0.25);
  for (render::DisplayMode mode : {render::DisplayMode::Shaded, render::DisplayMode::HiddenLine}) {
    render::RenderOptions o = options();
    o.mode = mode;
    o.view.name = "+y";
    const Picture front = render(o);
    EXPECT_TRUE(colour_near(front.image, pixel_of(front.frame, middle), bar_colour_));
    EXPECT_TRUE(colour_near(front.image, pixel_of(front.frame, quarter), bar_colour_));
    o.view.name = "-y";
    const Picture behind = render(o);
    EXPECT_FALSE(colour_near(behind.image, pixel_of(behind.frame, middle), bar_colour_, 4));
    EXPECT_FALSE(colour_near(behind.image, pixel_of(behind.frame, quarter), bar_colour_, 4));
    // Bar 3 sticks out of the block's side and stays visible.
    EXPECT_TRUE(colour_near(behind.image, pixel_of(behind.frame, lerp(node(12), node(13), 0.5)),
                            bar_colour_));
  }
}

TEST_F(LineElements, HiddenLayerHidesItsBars) {
  render::RenderOptions o = options();
  const Picture shown = render(o);
  EXPECT_GT(count_colour(shown.image, shown.frame.overlay.model, bar_colour_), 200);
  o.hidden_layers = {"BARS"};
  const Picture hidden = render(o);
  EXPECT_TRUE(hidden.frame.geometry.bars.empty());
  EXPECT_EQ(count_colour(hidden.image, hidden.frame.overlay.model, bar_colour_), 0);
  // The element filter leaves them out the same way.
  o.hidden_layers = {};
  o.filter = render::parse_element_filter("", "C3D8");
  const Picture filtered = render(o);
  EXPECT_EQ(count_colour(filtered.image, filtered.frame.overlay.model, bar_colour_), 0);
}

// The retained path (GL buffers uploaded once, views drawn without another upload) draws the
// bars exactly like the one-shot path: identical pixels, with a field and a deformed shape.
TEST_F(LineElements, RetainedViewsMatchOneShotPicturesWithBars) {
  render::RenderOptions o = options();
  o.width = 320, o.height = 240;
  o.field = "U.x";
  o.deform = render::parse_deform("auto");
  const render::RenderJob job(model_, registry_, &increment_, o);
  const Frame frame = job.frame(1.0);
  ASSERT_FALSE(frame.geometry.bars.empty());
  render::OsmesaRenderer one_shot(320, 240), retained(320, 240);
  retained.set_geometry(frame.geometry);
  for (double azimuth : {0.0, 60.0, 200.0}) {
    Frame view = frame;
    render::ViewSpec spec;
    spec.azimuth = azimuth;
    view.camera =
        render::fit_camera(spec, frame.geometry.lower, frame.geometry.upper,
                           double(frame.overlay.model.width) / frame.overlay.model.height);
    const Image expected = one_shot.render(view);
    EXPECT_EQ(compare_images(retained.render_view(view), expected, 0).differing, 0)
        << "azimuth " << azimuth;
    // The bars are in the picture: leaving them out changes it.
    Frame without = view;
    without.geometry.bars.clear();
    EXPECT_GT(compare_images(one_shot.render(without), expected, 0).differing, 50)
        << "azimuth " << azimuth;
  }
}

// `styk render` of the deck (mesh only) draws the bars.
TEST_F(LineElements, RenderCommandDrawsTheBarsOfADeck) {
  const fs::path dir = fs::path(STYK_BINARY_DIR) / "tests/images/cli/line_elements";
  fs::create_directories(dir);
  setenv("STYK_PLUGIN_PATH", STYK_PLUGIN_BUILD_DIR, 1);
  cli::RenderArgs args;
  args.input = kDeck;
  args.size = "400x300";
  args.layers = "BLOCK,BARS";
  args.output = (dir / "bars.png").string();
  ASSERT_EQ(cli::render_command(args), 0);
  const Image with = render::read_png(args.output);
  const render::PixelRect all{0, 0, with.width, with.height};
  EXPECT_GT(count_colour(with, all, bar_colour_), 100);
  args.hide_layers = "BARS";
  args.output = (dir / "no-bars.png").string();
  ASSERT_EQ(cli::render_command(args), 0);
  EXPECT_EQ(count_colour(render::read_png(args.output), all, bar_colour_), 0);
}

}  // namespace
}  // namespace styk::render_test
