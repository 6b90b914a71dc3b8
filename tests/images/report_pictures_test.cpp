// Pictures fit for a report: anti-aliased text from a packaged font (FreeType, DejaVu Sans), edges
// smoothed by multisampling, BMP as well as PNG, and legend numbers with as many digits as the
// bands need.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "image_compare.hpp"
#include "image_models.hpp"
#include "render_args.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/render/image.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

class ReportPictures : public ::testing::Test {
 protected:
  ReportPictures() : registry_(make_test_registry(libraries_)) {}
  render::Image draw(const TestScene& scene, const render::RenderOptions& o,
                     render::Frame* frame_out = nullptr) {
    const render::RenderJob job(scene.model, registry_,
                                scene.has_results ? &scene.increment : nullptr, o);
    const render::Frame frame = job.frame(1.0);
    if (frame_out) *frame_out = frame;
    render::OsmesaRenderer renderer(o.width, o.height);
    return renderer.render(frame);
  }
  PluginLibraries libraries_;
  ElementRegistry registry_;
};

// The legend's and title's text is anti-aliased: its glyphs' edges take many grey levels between
// ink and paper (a bitmap font has two), and every text item reads back exactly from the pixels.
TEST_F(ReportPictures, TextIsAntiAliasedAndReadsBack) {
  const TestScene box = make_scene("box", registry_);
  render::RenderOptions o;
  o.width = 800, o.height = 600;
  o.field = "S.mises";
  render::Frame frame;
  const render::Image image = draw(box, o, &frame);
  std::set<int> greys;
  render::Typeface typeface;
  for (const render::TextItem& item : frame.overlay.texts) {
    const int width = typeface.text_width(item.text, item.pixels);
    for (int y = item.y; y < item.y + typeface.line_height(item.pixels); ++y)
      for (int x = item.x; x < item.x + width; ++x) {
        const auto* p = image.pixel(x, y);
        if (p[0] == p[1] && p[1] == p[2]) greys.insert(p[0]);
      }
  }
  EXPECT_GT(greys.size(), 40u);
  for (const render::TextItem& label : frame.overlay.legend_labels)
    EXPECT_EQ(read_text(image, typeface, label), label.text);
  EXPECT_EQ(frame.overlay.legend_labels.front().pixels, 12);  // 600 rows / 50, at least 11
}

// Multisampling (4 samples, styk render's default) changes only pixels on edges: every pixel that
// differs from the single-sampled picture by more than the image tests' 24/255 has a neighbour of
// another colour in the single-sampled one; and there are such pixels (the silhouette is smooth).
TEST_F(ReportPictures, MultisamplingSmoothsEdgesOnly) {
  const TestScene box = make_scene("box_mesh", registry_);
  render::RenderOptions o;
  o.width = 480, o.height = 360;
  o.samples = 1;
  const render::Image aliased = draw(box, o);
  o.samples = 4;
  const render::Image smooth = draw(box, o);
  long changed = 0, off_edge = 0;
  for (int y = 1; y + 1 < o.height; ++y)
    for (int x = 1; x + 1 < o.width; ++x) {
      const auto* a = aliased.pixel(x, y);
      const auto* s = smooth.pixel(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(s[c])));
      if (worst <= 24) continue;
      ++changed;
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto* n = aliased.pixel(x + dx, y + dy);
          for (int c = 0; c < 3; ++c) edge = edge || std::abs(int(n[c]) - int(a[c])) > 24;
        }
      off_edge += !edge;
    }
  EXPECT_GT(changed, 200);
  EXPECT_EQ(off_edge, 0);
  o.samples = 17;
  EXPECT_THROW(render::RenderJob(box.model, registry_, nullptr, o), InputError);
}

// BMP: 24-bit, read back equal to the picture; the format follows the extension.
TEST_F(ReportPictures, BmpPicturesRoundTrip) {
  const TestScene box = make_scene("box", registry_);
  render::RenderOptions o;
  o.width = 321, o.height = 200;  // an odd width: BMP rows are padded to 4 bytes
  o.field = "U.mag";
  const render::Image image = draw(box, o);
  const std::filesystem::path dir = std::filesystem::path(STYK_BINARY_DIR) / "tests/images/bmp";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "box.BMP").string();
  render::write_picture(path, image);
  std::ifstream file(path, std::ios::binary);
  char magic[2] = {};
  file.read(magic, 2);
  EXPECT_EQ(std::string(magic, 2), "BM");
  EXPECT_EQ(std::filesystem::file_size(path), 54u + (321u * 3u + 1u) * 200u);  // 24 bit, padded
  const render::Image back = render::read_bmp(path);
  ASSERT_EQ(back.width, 321);
  ASSERT_EQ(back.height, 200);
  EXPECT_TRUE(back.rgba == image.rgba);  // the picture is opaque: alpha 255 both ways
  EXPECT_EQ(render::picture_format("a/b.png"), "png");
  EXPECT_EQ(render::picture_format("a.b/c"), "");
  EXPECT_THROW(render::write_picture((dir / "box.jpg").string(), image), std::invalid_argument);

  setenv("STYK_PLUGIN_PATH", STYK_PLUGIN_BUILD_DIR, 1);
  cli::RenderArgs args;
  args.input = STYK_SOURCE_DIR "/samples/cantilever-c3d20.inp";
  args.size = "200x150";
  args.output = (dir / "mesh.jpg").string();
  EXPECT_THROW(cli::render_command(args), InputError);  // refused by name before drawing
  EXPECT_FALSE(std::filesystem::exists(args.output));
  args.output = (dir / "mesh.bmp").string();
  EXPECT_EQ(cli::render_command(args), 0);
  EXPECT_EQ(render::read_bmp(args.output).width, 200);
}

// Legend numbers: the band width resolved to two significant digits (at least three in all), one
// number of decimals for the whole scale, fixed notation from 1e-3 to below 1e6.
TEST(LegendNumbers, DigitsFollowTheBandWidth) {
  const auto limits = [](double lo, double hi, int bands) {
    const render::NumberFormat f = render::number_format(lo, hi, bands);
    std::vector<std::string> out;
    for (int i = 0; i <= bands; ++i) out.push_back(f(lo + (hi - lo) * i / bands));
    return out;
  };
  // The shrink fit's pressure, 98.98 .. 203.6 in 12 bands: steps of 8.7 -> one decimal.
  EXPECT_EQ(limits(98.98, 203.6, 12).front(), "99.0");
  EXPECT_EQ(limits(98.98, 203.6, 12).back(), "203.6");
  // A nearly uniform pressure, 3.293 .. 3.2957: steps of 2.25e-4 -> five decimals, no repeats.
  const std::vector<std::string> uniform = limits(3.293, 3.2957, 12);
  EXPECT_EQ(uniform.front(), "3.29300");
  EXPECT_EQ(std::set<std::string>(uniform.begin(), uniform.end()).size(), uniform.size());
  EXPECT_EQ(limits(0.0, 3.409, 8).back(), "3.41");
  EXPECT_EQ(limits(0.0, 350.0, 7)[1], "50");
  EXPECT_EQ(limits(0.0, 0.0123, 12).back(), "0.0123");
  EXPECT_EQ(limits(0.0, 2.5e11, 12).back(), "2.50E+11");
  EXPECT_EQ(limits(-2e-7, 2e-7, 4).front(), "-2.00E-07");
  EXPECT_EQ(render::number_format(0.0, 0.0, 12)(0.0), "0");
  EXPECT_EQ(render::number_format(-1.0, 1.0, 8)(-1e-9), "0.00");  // no "-0.00"
  // Every scale of the test ranges prints distinct neighbours.
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
           {0, 1}, {-5e-5, 7e-4}, {1e5, 1.00001e5}, {-3e8, 2e9}, {12.5, 12.5001}}) {
    const std::vector<std::string> l = limits(lo, hi, 24);
    for (std::size_t k = 1; k < l.size(); ++k) EXPECT_NE(l[k], l[k - 1]) << lo << ".." << hi;
  }
  const render::NumberFormat f = render::number_format(98.98, 203.6, 12);
  EXPECT_DOUBLE_EQ(f.resolution(150.0), 0.05);
}

}  // namespace
}  // namespace styk::render_test
