// The unrolled contact map (styk render --unroll): a contact field laid flat over (angle, axial
// position) for a cylindrical or conical surface, over two in-plane axes for a flat one.
//
// SPEC §3.2.2: two concentric cylinders (Lamé), plane strain; analytic contact pressure 3.294,
// uniform (published: 3.3 with C3D21 and C3D28). Solved here with the `cylinders` builder's C3D21
// contact layers (16 elements around the quarter): the map is drawn with a scale of three bands,
// the middle one 3.294 +- 1 %, and every pixel of the map is that band's colour; the fitted axis
// is the z axis through the origin and the radius the interface's, 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "image_models.hpp"
#include "render_args.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/io/results_file.hpp"
#include "styk/render/image.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

constexpr double kLame = 3.294;  // SPEC §3.2.2, analytic contact pressure

class UnrolledMap : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    libraries_ = std::make_unique<PluginLibraries>();
    registry_ = std::make_unique<ElementRegistry>(make_test_registry(*libraries_));
    cylinders_ = std::make_unique<TestScene>(make_scene("cylinders_c3d21", *registry_));
    block_ = std::make_unique<TestScene>(make_scene("contact_block", *registry_));
  }
  static void TearDownTestSuite() {
    cylinders_.reset();
    block_.reset();
    registry_.reset();
    libraries_.reset();
  }
  static render::RenderOptions map_options() {
    render::RenderOptions o;
    o.width = 800, o.height = 500;
    o.field = "CPRESS";
    o.unroll = true;
    o.samples = 1;  // exact colours
    return o;
  }
  static std::unique_ptr<PluginLibraries> libraries_;
  static std::unique_ptr<ElementRegistry> registry_;
  static std::unique_ptr<TestScene> cylinders_, block_;
};
std::unique_ptr<PluginLibraries> UnrolledMap::libraries_;
std::unique_ptr<ElementRegistry> UnrolledMap::registry_;
std::unique_ptr<TestScene> UnrolledMap::cylinders_, UnrolledMap::block_;

TEST_F(UnrolledMap, ConcentricCylindersAreUniformWithinTheBandOfTheLamePressure) {
  // The data first: every slave node within 1 % of 3.294.
  ASSERT_EQ(cylinders_->increment.contact.size(), 33u * 3u);  // 33 nodes around x 3 along z
  for (const ContactNodeResult& c : cylinders_->increment.contact)
    ASSERT_NEAR(c.pressure, kLame, 0.01 * kLame) << "node " << c.node;

  render::RenderOptions o = map_options();
  o.bands = 3;
  o.range = std::array<double, 2>{0.97 * kLame, 1.03 * kLame};  // middle band: 3.294 +- 1 %
  const render::RenderJob job(cylinders_->model, *registry_, &cylinders_->increment, o);
  const render::UnrolledSurface& s = *job.unrolled();
  EXPECT_EQ(s.kind, render::UnrolledSurface::Kind::Revolved);
  EXPECT_NEAR(std::abs(s.axis.direction[2]), 1.0, 1e-9);
  EXPECT_NEAR(std::hypot(s.axis.point[0], s.axis.point[1]), 0.0, 1e-4);
  EXPECT_NEAR(s.radius, 2.0, 2e-3);
  EXPECT_LT(s.fit_error, 1e-3);
  EXPECT_NEAR(render::map_degrees(s, s.u_range[1]) - render::map_degrees(s, s.u_range[0]), 90.0,
              1e-3);
  EXPECT_NEAR(s.v_range[1] - s.v_range[0], 1.0, 1e-9);  // the cylinders' length

  const render::Frame frame = job.frame();
  render::OsmesaRenderer renderer(o.width, o.height);
  const render::Image image = renderer.render(frame);
  const render::Rgb middle = job.colors().band_color(1);
  const std::array<int, 3> want{render::to_byte(middle.r), render::to_byte(middle.g),
                                render::to_byte(middle.b)};
  // The map's pixels: inside its extent, two pixels in from its edges (the frame and the
  // element edges of shaded mode's feature lines lie on the extent).
  const auto pixel = [&](double u, double v) {
    const std::array<float, 3> ndc = render::project(frame.camera, {float(u), float(v), 0.0f});
    const render::PixelRect& m = frame.overlay.model;
    return std::array<double, 2>{m.x + (ndc[0] + 1) * 0.5 * m.width,
                                 m.y + (1 - ndc[1]) * 0.5 * m.height};
  };
  const auto low = pixel(s.u_range[0], s.v_range[0]), high = pixel(s.u_range[1], s.v_range[1]);
  long inside = 0, off_band = 0;
  for (int y = int(high[1]) + 2; y <= int(low[1]) - 2; ++y)
    for (int x = int(low[0]) + 2; x <= int(high[0]) - 2; ++x) {
      const auto* q = image.pixel(x, y);
      ++inside;
      off_band += std::array<int, 3>{q[0], q[1], q[2]} != want;
    }
  EXPECT_GT(inside, 100000);  // 800 x 500: the map is most of it
  EXPECT_EQ(off_band, 0) << "of " << inside << " map pixels";
}

// The given axis gives the same map; a flat contact surface is mapped over its own plane.
TEST_F(UnrolledMap, GivenAxisAndFlatSurface) {
  render::RenderOptions o = map_options();
  o.unroll_axis = render::parse_unroll_axis("0,0,5, 0,0,2");
  const render::RenderJob given(cylinders_->model, *registry_, &cylinders_->increment, o);
  EXPECT_TRUE(given.unrolled()->axis_given);
  EXPECT_NEAR(given.unrolled()->radius, 2.0, 2e-3);
  EXPECT_NEAR(given.unrolled()->axis.point[2], 0.0, 1e-12);  // the point nearest the origin

  const render::RenderJob flat(block_->model, *registry_, &block_->increment, map_options());
  const render::UnrolledSurface& f = *flat.unrolled();
  EXPECT_EQ(f.kind, render::UnrolledSurface::Kind::Flat);
  EXPECT_NEAR(std::abs(f.axis.direction[2]), 1.0, 1e-9);
  EXPECT_EQ(f.first_name, "x");
  EXPECT_EQ(f.second_name, "y");
  EXPECT_NEAR(f.u_range[0], 1.0, 1e-9);
  EXPECT_NEAR(f.u_range[1], 3.0, 1e-9);
  EXPECT_NEAR(f.v_range[0], 1.0, 1e-9);
  EXPECT_NEAR(f.v_range[1], 3.0, 1e-9);
}

TEST_F(UnrolledMap, RefusesWhatItCannotDraw) {
  const auto refused = [&](render::RenderOptions o, const std::string& words) {
    try {
      render::RenderJob(cylinders_->model, *registry_, &cylinders_->increment, o);
      ADD_FAILURE() << "no error for " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  render::RenderOptions o = map_options();
  o.field = "S.mises";
  refused(o, "lives on surfaces");
  o = map_options();
  o.mode = render::DisplayMode::Wireframe;
  refused(o, "drawn shaded");
  o = map_options();
  o.labels.nodes = true;
  refused(o, "not on the unrolled map");
  EXPECT_THROW(render::parse_unroll_axis("0,0,0,0,0,0"), InputError);
  EXPECT_THROW(render::parse_unroll_axis("0,0,0,1"), InputError);
  EXPECT_THROW(render::parse_unroll_axis("0,0,0,1,x,0"), InputError);
}

// `styk render RESULTS --field CPRESS --unroll -o map.bmp` through the command body, from a
// results file (which keeps no surfaces): a 24-bit BMP of the requested size.
TEST_F(UnrolledMap, RenderCommandWritesTheMapAsBmp) {
  const std::filesystem::path dir =
      std::filesystem::path(STYK_BINARY_DIR) / "tests/images/cli" / "unroll";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  setenv("STYK_PLUGIN_PATH", STYK_PLUGIN_BUILD_DIR, 1);
  Results results;
  results.increments.push_back(cylinders_->increment);
  const std::string path = (dir / "cylinders.styk.h5").string();
  write_results_file(path, cylinders_->model, results);
  cli::RenderArgs args;
  args.input = path;
  args.field = "CPRESS";
  args.unroll = true;
  args.size = "400x300";
  args.output = (dir / "map.bmp").string();
  EXPECT_EQ(cli::render_command(args), 0);
  const render::Image image = render::read_bmp(args.output);
  EXPECT_EQ(image.width, 400);
  EXPECT_EQ(image.height, 300);
  args.animate = 3;
  EXPECT_THROW(cli::render_command(args), InputError);
}

}  // namespace
}  // namespace styk::render_test
