// Contact fields in the renderer (CPRESS, CSHEAR, CSLIP, CGAP, CSTATUS) on a model solved through
// the solver (contact_scene.hpp): pixel checks that cannot pass by accident -- the status picture
// shows exactly the status colours present in the results, the pressure legend's limits are the
// smallest and largest pressure of the results -- plus the messages for absent or unknown contact
// data and `styk render --field CPRESS` on a results file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include "contact_scene.hpp"
#include "image_compare.hpp"
#include "image_models.hpp"
#include "render_args.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/io/results_file.hpp"
#include "styk/render/image.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

using Colour = std::array<int, 3>;

Colour bytes(const render::Rgb& c) {
  return {render::to_byte(c.r), render::to_byte(c.g), render::to_byte(c.b)};
}

// Colours in a rectangle seen on at least `minimum` pixels, paper and ink left out.
std::map<Colour, int> colours_in(const render::Image& image, const render::PixelRect& r,
                                 int minimum) {
  std::map<Colour, int> counts;
  for (int y = r.y; y < r.y + r.height; ++y)
    for (int x = r.x; x < r.x + r.width; ++x) {
      const auto* p = image.pixel(x, y);
      const Colour c{p[0], p[1], p[2]};
      if (c == Colour{255, 255, 255} || c == Colour{0, 0, 0}) continue;
      ++counts[c];
    }
  for (auto it = counts.begin(); it != counts.end();)
    it = it->second < minimum ? counts.erase(it) : std::next(it);
  return counts;
}

double read_number(const render::Image& image, const render::TextItem& item) {
  render::Typeface typeface;
  const std::string text = read_text(image, typeface, item);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  EXPECT_EQ(*end, '\0') << "legend text '" << text << "'";
  return value;
}

// The model is solved once for the whole suite.
class ContactRender : public ::testing::Test {
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
  static const Model& model() { return scene_->model; }
  static const IncrementResult& increment() { return scene_->increment; }

  struct Rendered {
    render::Image image;
    render::Overlay overlay;
  };
  static Rendered render(const render::RenderOptions& options) {
    const render::RenderJob job(model(), *registry_, &increment(), options);
    render::OsmesaRenderer renderer(options.width, options.height);
    const render::Frame frame = job.frame(1.0);
    return {renderer.render(frame), frame.overlay};
  }

  static std::unique_ptr<PluginLibraries> libraries_;
  static std::unique_ptr<ElementRegistry> registry_;
  static std::unique_ptr<TestScene> scene_;
};
std::unique_ptr<PluginLibraries> ContactRender::libraries_;
std::unique_ptr<ElementRegistry> ContactRender::registry_;
std::unique_ptr<TestScene> ContactRender::scene_;

// The scene is meant to show every state; the counts are the solver's (not asserted exactly, only
// that each state is there, so the status picture below has three categories to tell apart).
TEST_F(ContactRender, SolvedModelHasEveryStatus) {
  std::map<ContactStatus, int> count;
  for (const ContactNodeResult& c : increment().contact) ++count[c.status];
  std::printf("contact nodes %zu: open %d, stick %d, slip %d\n", increment().contact.size(),
              count[ContactStatus::Open], count[ContactStatus::Stick], count[ContactStatus::Slip]);
  EXPECT_EQ(increment().contact.size(), 25u);  // the 5 x 5 nodes of the block's bottom
  for (ContactStatus s : {ContactStatus::Open, ContactStatus::Stick, ContactStatus::Slip})
    EXPECT_GT(count[s], 0) << "status " << static_cast<int>(s);
  EXPECT_LT(increment().contact_equilibrium.relative_residual, 1e-8);
}

// Seen square-on from below with only the contact faces drawn, the status picture holds exactly
// the colours of the statuses present in the results -- no other colour, none missing -- and the
// legend names the three statuses, read back from the pixels.
TEST_F(ContactRender, StatusPictureShowsExactlyTheStatusColoursOfTheResults) {
  std::set<Colour> expected;
  for (const ContactNodeResult& c : increment().contact)
    expected.insert(bytes(render::contact_status_color(static_cast<int>(c.status))));
  ASSERT_EQ(expected.size(), 3u);

  render::RenderOptions options;
  options.width = 640, options.height = 480;
  options.field = "CSTATUS";
  options.field_faces = render::FieldFaces::Only;
  options.view.name = "-z";
  options.samples = 1;  // exact colours: multisampling would blend them along the edges
  const Rendered r = render(options);
  std::set<Colour> seen;
  for (const auto& [colour, count] : colours_in(r.image, r.overlay.model, 10)) seen.insert(colour);
  EXPECT_EQ(seen, expected);

  ASSERT_EQ(r.overlay.legend_labels.size(), 3u);
  const char* names[] = {"slip", "stick", "open"};  // top to bottom
  for (int i = 0; i < 3; ++i) {
    const render::TextItem& label = r.overlay.legend_labels[i];
    EXPECT_EQ(label.text, names[i]);
    render::Typeface typeface;
    EXPECT_EQ(read_text(r.image, typeface, label), names[i]);
  }

  // Drop the sticking nodes from a copy of the results: their colour must leave the picture.
  IncrementResult no_stick = increment();
  for (ContactNodeResult& c : no_stick.contact)
    if (c.status == ContactStatus::Stick) c.status = ContactStatus::Slip;
  const render::RenderJob job(model(), *registry_, &no_stick, options);
  render::OsmesaRenderer renderer(options.width, options.height);
  const render::Frame frame = job.frame(1.0);
  std::set<Colour> without;
  for (const auto& [colour, count] : colours_in(renderer.render(frame), frame.overlay.model, 10))
    without.insert(colour);
  expected.erase(bytes(render::contact_status_color(1)));
  EXPECT_EQ(without, expected);
}

// The pressure legend runs from the smallest to the largest contact pressure of the results
// (read back from the pixels; 4 significant digits, so 5e-4 of the largest), and the contact area
// shows band colours only, the lowest and the highest among them.
TEST_F(ContactRender, PressureLegendLimitsAreTheResultsPressureRange) {
  double lo = 1e300, hi = -1e300;
  for (const ContactNodeResult& c : increment().contact)
    lo = std::min(lo, c.pressure), hi = std::max(hi, c.pressure);
  ASSERT_GT(hi, lo);

  render::RenderOptions options;
  options.width = 640, options.height = 480;
  options.field = "CPRESS";
  options.bands = 8;
  options.field_faces = render::FieldFaces::Only;
  options.view.name = "-z";
  options.samples = 1;  // exact colours: multisampling would blend them along the edges
  const render::RenderJob job(model(), *registry_, &increment(), options);
  EXPECT_DOUBLE_EQ(job.colors().min, lo);
  EXPECT_DOUBLE_EQ(job.colors().max, hi);
  render::OsmesaRenderer renderer(options.width, options.height);
  const render::Frame frame = job.frame(1.0);
  const render::Image image = renderer.render(frame);
  ASSERT_EQ(frame.overlay.legend_labels.size(), 9u);
  // The legend prints as many digits as the band width needs: half a unit of the last digit.
  const render::NumberFormat format = render::number_format(job.colors());
  EXPECT_NEAR(read_number(image, frame.overlay.legend_labels.front()), hi, format.resolution(hi));
  EXPECT_NEAR(read_number(image, frame.overlay.legend_labels.back()), lo, format.resolution(lo));

  std::set<Colour> bands;
  for (int i = 0; i < 8; ++i) bands.insert(bytes(job.colors().band_color(i)));
  std::set<Colour> seen;
  for (const auto& [colour, count] : colours_in(image, frame.overlay.model, 10)) {
    seen.insert(colour);
    EXPECT_TRUE(bands.count(colour)) << "colour " << colour[0] << "," << colour[1] << ","
                                     << colour[2] << " is no band colour (" << count << " px)";
  }
  EXPECT_TRUE(seen.count(bytes(job.colors().band_color(0))));
  EXPECT_TRUE(seen.count(bytes(job.colors().band_color(7))));
}

// The faces without contact output (the block's sides and top) are neutral grey by default and
// gone with only_field_faces.
TEST_F(ContactRender, OtherFacesAreNeutralGreyOrHidden) {
  render::RenderOptions options;
  options.width = 640, options.height = 480;
  options.field = "CPRESS";
  options.layers = {"SLAB", "BLOCK"};
  options.hidden_layers = {"SLAB"};
  options.view.elevation = -75;  // iso, turned to look from below
  options.samples = 1;           // multisampled edges would blend ink and paper into greys
  const auto grey_pixels = [](const Rendered& r) {
    int count = 0;
    const render::PixelRect& m = r.overlay.model;
    for (int y = m.y; y < m.y + m.height; ++y)
      for (int x = m.x; x < m.x + m.width; ++x) {
        const auto* p = r.image.pixel(x, y);
        count += p[0] == p[1] && p[1] == p[2] && p[0] > 40 && p[0] < 250;
      }
    return count;
  };
  EXPECT_GT(grey_pixels(render(options)), 5000);
  options.field_faces = render::FieldFaces::Only;
  options.undeformed_outline = false;
  EXPECT_EQ(grey_pixels(render(options)), 0);
}

// Every contact field evaluates at exactly the slave nodes, with the values of the results.
TEST_F(ContactRender, ContactFieldsTakeTheResultsValues) {
  const IncrementResult& inc = increment();
  for (const char* name : {"CPRESS", "CSHEAR", "CSHEAR.1", "CSLIP", "CSLIP.2", "CGAP", "CSTATUS"}) {
    const render::ScalarField f =
        render::evaluate_field(model(), inc, name, render::Averaging::MethodII);
    EXPECT_EQ(f.location, render::FieldLocation::Node) << name;
    EXPECT_FALSE(f.uses_averaging) << name;
    ASSERT_EQ(f.defined.size(), model().coords.size()) << name;
    EXPECT_EQ(std::count(f.defined.begin(), f.defined.end(), 1), 25) << name;
    for (const ContactNodeResult& c : inc.contact) {
      ASSERT_TRUE(f.defined_at(c.node)) << name;
      const std::string n = name;
      const double expected = n == "CPRESS"     ? c.pressure
                              : n == "CSHEAR"   ? std::hypot(c.shear[0], c.shear[1])
                              : n == "CSHEAR.1" ? c.shear[0]
                              : n == "CSLIP"    ? std::hypot(c.slip[0], c.slip[1])
                              : n == "CSLIP.2"  ? c.slip[1]
                              : n == "CGAP"     ? c.gap
                                                : static_cast<double>(static_cast<int>(c.status));
      EXPECT_NEAR(f.values[c.node], expected, 1e-12 * std::abs(expected)) << name;
    }
  }
}

TEST_F(ContactRender, AbsentOrUnknownContactDataIsAnErrorNamingWhatExists) {
  PluginLibraries libraries;
  const ElementRegistry registry = make_test_registry(libraries);
  const TestScene box = make_scene("box", registry);  // no contact
  try {
    render::evaluate_field(box.model, box.increment, "CPRESS", render::Averaging::MethodII);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("holds no contact output"), std::string::npos) << m;
    EXPECT_NE(m.find("no *CONTACT PAIR"), std::string::npos) << m;
    EXPECT_NE(m.find("it holds: U, RF, S.* (averaging none, I, II, centroid)"), std::string::npos)
        << m;
  }
  try {
    render::evaluate_field(model(), increment(), "CSTATUS.x", render::Averaging::MethodII);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("contact fields: CPRESS, CSHEAR"), std::string::npos) << m;
  }
  // The slave surface hidden: nothing to colour.
  render::RenderOptions options;
  options.field = "CPRESS";
  options.layers = {"SLAB", "BLOCK"};
  options.hidden_layers = {"BLOCK"};
  EXPECT_THROW(render::RenderJob(model(), *registry_, &increment(), options), InputError);
}

// `styk render RESULTS --field CPRESS` (the command body) on a results file written from the
// solved model: the contact output goes through the file.
TEST_F(ContactRender, RenderCommandDrawsContactPressureFromAResultsFile) {
  const std::filesystem::path dir =
      std::filesystem::path(STYK_BINARY_DIR) / "tests/images/cli" / "contact";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  setenv("STYK_PLUGIN_PATH", STYK_PLUGIN_BUILD_DIR, 1);
  Results results;
  results.increments.push_back(increment());
  const std::string path = (dir / "contact.styk.h5").string();
  write_results_file(path, model(), results);
  cli::RenderArgs args;
  args.input = path;
  args.field = "CPRESS";
  args.size = "320x240";
  args.layers = "slab,block";
  args.hide_layers = "slab";
  args.output = (dir / "cpress.png").string();
  EXPECT_EQ(cli::render_command(args), 0);
  const render::Image image = render::read_png(args.output);
  EXPECT_EQ(image.width, 320);
  args.field = "CSTATUS";
  args.output = (dir / "cstatus.png").string();
  EXPECT_EQ(cli::render_command(args), 0);
  EXPECT_TRUE(std::filesystem::exists(args.output));
}

}  // namespace
}  // namespace styk::render_test
