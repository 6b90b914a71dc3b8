// Pixel-level checks of the rendered pictures that cannot pass by accident (SPEC §5: banded
// contours with 2..24 colours, layers toggled on/off, legend with the band limits).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

#include "image_compare.hpp"
#include "image_models.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

using render::Image;
using Colour = std::array<int, 3>;

struct Rendered {
  Image image;
  render::Overlay overlay;
};

Rendered render_scene(const TestScene& scene, const ElementRegistry& registry,
                      render::RenderOptions options) {
  const render::RenderJob job(scene.model, registry, scene.has_results ? &scene.increment : nullptr,
                              options);
  render::OsmesaRenderer renderer(options.width, options.height);
  const render::Frame frame = job.frame(1.0);
  return {renderer.render(frame), frame.overlay};
}

Colour bytes(const render::Rgb& c) {
  return {render::to_byte(c.r), render::to_byte(c.g), render::to_byte(c.b)};
}

// Colours in a rectangle, with their pixel counts, leaving out the paper and the ink.
std::map<Colour, int> colours_in(const Image& image, const render::PixelRect& r) {
  std::map<Colour, int> counts;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) {
      const auto* p = image.pixel(x, y);
      const Colour c{p[0], p[1], p[2]};
      if (c == Colour{255, 255, 255} || c == Colour{0, 0, 0}) continue;
      ++counts[c];
    }
  return counts;
}

// Pixels whose hue (the colour divided by its largest channel) is that of `colour`, i.e. the
// colour under any amount of light.
int pixels_of_hue(const Image& image, const render::PixelRect& r, const render::Rgb& colour) {
  const float top = std::max({colour.r, colour.g, colour.b});
  const float want[3] = {colour.r / top, colour.g / top, colour.b / top};
  int count = 0;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) {
      const auto* p = image.pixel(x, y);
      const float m = std::max({p[0], p[1], p[2]});
      if (m < 40 || (p[0] == 255 && p[1] == 255 && p[2] == 255)) continue;
      bool same = true;
      for (int c = 0; c < 3; ++c) same = same && std::abs(p[c] / m - want[c]) < 0.03f;
      count += same;
    }
  return count;
}

class PixelChecks : public ::testing::Test {
 protected:
  PixelChecks() : registry_(make_test_registry(libraries_)) {}
  PluginLibraries libraries_;
  ElementRegistry registry_;
};

// A banded render of a linear field (U.x = 0.01 x, exact in C3D20), seen square-on, shows exactly
// the requested number of colours in the model area, and they are the band colours.
TEST_F(PixelChecks, BandedLinearFieldShowsExactlyTheRequestedBandColours) {
  const TestScene scene = make_scene("box", registry_);
  for (int bands : {2, 5, 12, 24}) {
    render::RenderOptions options;
    options.width = 640, options.height = 480;
    options.field = "U.x";
    options.bands = bands;
    options.view.name = "+z";
    options.samples = 1;  // exact colours: multisampling would blend them along the edges
    const Rendered r = render_scene(scene, registry_, options);
    std::set<Colour> seen;
    for (const auto& [colour, count] : colours_in(r.image, r.overlay.model))
      if (count >= 10) seen.insert(colour);
    render::ColorScale scale;
    scale.bands = bands;
    std::set<Colour> expected;
    for (int i = 0; i < bands; ++i) expected.insert(bytes(scale.band_color(i)));
    EXPECT_EQ(seen.size(), static_cast<std::size_t>(bands)) << bands << " bands";
    EXPECT_EQ(seen, expected) << bands << " bands";
  }
}

// A smooth render of the same field shows many more colours than any banded one.
TEST_F(PixelChecks, SmoothContoursAreNotBanded) {
  const TestScene scene = make_scene("box", registry_);
  render::RenderOptions options;
  options.width = 640, options.height = 480;
  options.field = "U.x";
  options.smooth = true;
  options.view.name = "+z";
  const Rendered r = render_scene(scene, registry_, options);
  EXPECT_GT(colours_in(r.image, r.overlay.model).size(), 100u);
}

TEST_F(PixelChecks, HiddenLayerColourDoesNotAppear) {
  const TestScene scene = make_scene("box_mesh", registry_);
  render::RenderOptions options;
  options.width = 640, options.height = 480;
  options.layers = {"LEFT", "RIGHT"};
  const render::Rgb left = render::layer_palette(0), right = render::layer_palette(1);

  const Rendered both = render_scene(scene, registry_, options);
  EXPECT_GT(pixels_of_hue(both.image, both.overlay.model, left), 5000);
  EXPECT_GT(pixels_of_hue(both.image, both.overlay.model, right), 5000);

  options.hidden_layers = {"right"};
  const Rendered one = render_scene(scene, registry_, options);
  EXPECT_GT(pixels_of_hue(one.image, one.overlay.model, left), 5000);
  EXPECT_EQ(pixels_of_hue(one.image, one.overlay.model, right), 0);
}

// The legend's first and last numbers, read back from the pixels (each glyph matched against the
// typeface's), are the field's maximum and minimum, computed here straight from the results
// arrays, for every averaging method, to the legend's last printed digit.
TEST_F(PixelChecks, LegendNumbersMatchTheFieldRangeForEveryAveraging) {
  const TestScene scene = make_scene("box", registry_);
  const IncrementResult& inc = scene.increment;
  struct Expectation {
    const char* averaging;
    const std::vector<Tensor6>* values;
  };
  for (const Expectation& e :
       {Expectation{"none", &inc.S_element_nodes}, Expectation{"I", &inc.S_nodal_I},
        Expectation{"II", &inc.S_nodal_II}, Expectation{"centroid", &inc.S_centroid}}) {
    double lo = 1e300, hi = -1e300;
    for (const Tensor6& s : *e.values) lo = std::min(lo, s[0]), hi = std::max(hi, s[0]);
    render::RenderOptions options;
    options.width = 640, options.height = 480;
    options.field = "S.11";
    options.averaging = render::parse_averaging(e.averaging);
    options.bands = 8;
    const Rendered r = render_scene(scene, registry_, options);
    ASSERT_EQ(r.overlay.legend_labels.size(), 9u);
    const render::TextItem& top = r.overlay.legend_labels.front();
    const render::TextItem& bottom = r.overlay.legend_labels.back();
    render::Typeface typeface;
    const std::string top_text = read_text(r.image, typeface, top);
    const std::string bottom_text = read_text(r.image, typeface, bottom);
    const render::NumberFormat format = render::number_format(lo, hi, 8);
    char* end = nullptr;
    const double top_value = std::strtod(top_text.c_str(), &end);
    EXPECT_EQ(*end, '\0') << "legend text '" << top_text << "'";
    const double bottom_value = std::strtod(bottom_text.c_str(), &end);
    EXPECT_EQ(*end, '\0') << "legend text '" << bottom_text << "'";
    EXPECT_NEAR(top_value, hi, format.resolution(hi)) << e.averaging << ": '" << top_text << "'";
    EXPECT_NEAR(bottom_value, lo, format.resolution(lo))
        << e.averaging << ": '" << bottom_text << "'";
  }
  // The jumps of +-20 make the unaveraged range the widest: averaging must change the picture.
}

// Auto deformation: the largest displacement becomes 0.1 of the model size. Box 4 x 1 x 1:
// size sqrt(18); largest |U| at x = 4: |(0.04, 0, -0.02)| = sqrt(0.002).
TEST_F(PixelChecks, AutoDeformationScaleMakesTheLargestDisplacementATenthOfTheModel) {
  const TestScene scene = make_scene("box", registry_);
  render::RenderOptions options;
  options.deform = render::parse_deform("auto");
  const render::RenderJob job(scene.model, registry_, &scene.increment, options);
  EXPECT_NEAR(job.deformation_scale() * std::sqrt(0.002), 0.1 * std::sqrt(18.0), 1e-12);
}

TEST_F(PixelChecks, RenderingIsDeterministic) {
  const TestScene scene = make_scene("c3d28", registry_);
  render::RenderOptions options;
  options.width = 320, options.height = 240;
  options.field = "S.mises";
  options.mode = render::DisplayMode::ShadedEdges;
  options.deform = render::parse_deform("auto");
  const render::RenderJob job(scene.model, registry_, &scene.increment, options);
  render::OsmesaRenderer renderer(320, 240);
  const Image first = renderer.render(job.frame(1.0));
  const Image second = renderer.render(job.frame(1.0));
  render::OsmesaRenderer fresh(320, 240);
  const Image third = fresh.render(job.frame(1.0));
  EXPECT_TRUE(first.rgba == second.rgba);
  EXPECT_TRUE(first.rgba == third.rgba);
}

// Animation frames run from the undeformed shape to the full scale with one camera: frame 0 of a
// deformed job equals the undeformed picture's model area.
TEST_F(PixelChecks, AnimationStartsUndeformed) {
  const TestScene scene = make_scene("box", registry_);
  render::RenderOptions options;
  options.width = 320, options.height = 240;
  options.deform = render::parse_deform("auto");
  const render::RenderJob job(scene.model, registry_, &scene.increment, options);
  render::OsmesaRenderer renderer(320, 240);
  const render::Frame start = job.frame(0.0), end = job.frame(1.0);
  EXPECT_TRUE(start.geometry.outline.empty());
  EXPECT_FALSE(end.geometry.outline.empty());
  const Image a = renderer.render(start), b = renderer.render(end);
  const render::PixelRect& m = start.overlay.model;
  long differ = 0;
  for (int y = m.y; y < m.y + m.height; ++y)
    for (int x = m.x; x < m.x + m.width; ++x) differ += a.pixel(x, y)[0] != b.pixel(x, y)[0];
  EXPECT_GT(differ, 1000);
}

}  // namespace
}  // namespace styk::render_test
