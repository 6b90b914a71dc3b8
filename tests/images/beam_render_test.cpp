// Beams in the renderer (docs/render.md "Beams"): drawn as their cross-sections extruded along the
// axis, not as bars; stress fields from the fibre tensors, so a bent beam shows tension and
// compression on opposite faces. The model is samples/beam-frame.inp (mm, N: a BOX 300 x 300
// column along z to z = 3000, a RECT 100 x 200 arm along x to x = 2500 with its 200 along z, a
// PIPE r 50 arm along y), solved here; the arm's tip carries -5000 along z.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "image_models.hpp"
#include "pixel_probe.hpp"
#include "styk/inp/reader.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::render_test {
namespace {

using render::Frame;
using render::Image;

const std::string kDeck = std::string(STYK_SOURCE_DIR) + "/samples/beam-frame.inp";

class BeamRender : public ::testing::Test {
 protected:
  BeamRender() : registry_(make_test_registry(libraries_)), model_(read_inp(kDeck, registry_)) {
    Results results = run_static_analysis(model_, registry_, SolveOptions{}, nullptr, nullptr);
    increment_ = std::move(results.increments.back());
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

  PluginLibraries libraries_;
  ElementRegistry registry_;
  Model model_;
  IncrementResult increment_;
};

// The 12 beams are extruded sections (no skin faces, no bars); the undeformed tubes reach the
// section extents: the BOX column to x = -150, the RECT arm's top to z = 3100.
TEST_F(BeamRender, BeamsAreExtrudedSectionsNotBars) {
  const render::RenderJob job(model_, registry_, &increment_, render::RenderOptions{});
  ASSERT_EQ(job.skin().layers().size(), 1u);
  const auto& layer = job.skin().layers()[0];
  EXPECT_EQ(layer.beams.size(), 12u);
  EXPECT_TRUE(layer.lines.empty());
  EXPECT_TRUE(layer.faces.empty());
  const Frame frame = job.frame();
  EXPECT_FALSE(frame.geometry.triangles.empty());
  EXPECT_TRUE(frame.geometry.bars.empty());
  EXPECT_FALSE(frame.geometry.closed);  // tubes are drawn without culling
  const Vec3& o = frame.geometry.origin;
  EXPECT_NEAR(frame.geometry.lower[0], -150.0 - o[0], 1e-2);
  EXPECT_NEAR(frame.geometry.upper[2], 3100.0 - o[2], 1e-2);
}

// S.11 seen from -y on the undeformed shape: near the arm's root (x = 300) its top fibres are in
// tension (S11 = M c / I = 5000 x 2200 x 80 / 6.67e7 = +13.2) and its bottom fibres in compression
// (-13.2); with 12 bands over the symmetric range +-18.75 (the arm's extreme fibres at its first
// station) that is band 10 at the top and band 1 at the bottom.
TEST_F(BeamRender, BendingShowsTensionAndCompressionOnOppositeFaces) {
  render::RenderOptions o;
  o.width = 640, o.height = 480;
  o.field = "S.11";
  o.view.name = "-y";
  o.layers = {"ARM"};  // the camera fits the arm alone
  o.samples = 1;  // the neutral axis is a band edge: a multisampled pixel there blends two bands
  const Picture p = render(o);
  const render::ColorScale& scale = p.frame.colors;
  EXPECT_NEAR(scale.min, -18.75, 0.01);
  EXPECT_NEAR(scale.max, 18.75, 0.01);
  const int top = band_at(p.image, pixel_of(p.frame, {300.0, -50.0, 3080.0}), scale);
  const int bottom = band_at(p.image, pixel_of(p.frame, {300.0, -50.0, 2920.0}), scale);
  EXPECT_EQ(top, 10);
  EXPECT_EQ(bottom, 1);
  // The neutral axis (z = 3000) has S11 = 0: the two middle bands.
  const int middle = band_at(p.image, pixel_of(p.frame, {300.0, -50.0, 3000.0}), scale);
  EXPECT_TRUE(middle == 5 || middle == 6) << middle;
}

// A nodal field colours the tubes along the axis: |U| grows from the arm's root to its tip.
TEST_F(BeamRender, NodalFieldsAreInterpolatedAlongTheAxis) {
  render::RenderOptions o;
  o.width = 640, o.height = 480;
  o.field = "U.mag";
  o.view.name = "-y";
  o.layers = {"ARM"};
  const Picture p = render(o);
  const int root = band_at(p.image, pixel_of(p.frame, {200.0, -50.0, 3000.0}), p.frame.colors);
  const int tip = band_at(p.image, pixel_of(p.frame, {2400.0, -50.0, 3000.0}), p.frame.colors);
  ASSERT_GE(root, 0);
  ASSERT_GE(tip, 0);
  EXPECT_GT(tip, root + 4);
}

// Section forces are fields (docs/render.md): SF.2 of the arm is the tip load's shear, -5000 at
// every station by statics (the arm carries -5000 along z at its tip), so the scale over the arm
// spans -5000 .. -5000 (1e-6 relative); SM.3 (torque) of the arm is 0 (to 1e-6 of the arm's
// largest bending moment, 5000 x 2500).
TEST_F(BeamRender, SectionForcesAreFields) {
  render::RenderOptions o;
  o.width = 320, o.height = 240;
  o.field = "SF.2";
  o.layers = {"ARM"};
  const render::RenderJob shear(model_, registry_, &increment_, o);
  EXPECT_NEAR(shear.colors().min, -5000.0, 5e-3);
  EXPECT_NEAR(shear.colors().max, -5000.0, 5e-3);
  o.field = "SM.3";
  const render::RenderJob torque(model_, registry_, &increment_, o);
  EXPECT_NEAR(torque.colors().min, 0.0, 1e-6 * 5000.0 * 2500.0);
  EXPECT_NEAR(torque.colors().max, 0.0, 1e-6 * 5000.0 * 2500.0);
}

}  // namespace
}  // namespace styk::render_test
