// Image regression: every line of cases.txt is rendered headless (OSMesa, llvmpipe) and compared
// with its committed baseline under a tolerance. On a mismatch the actual picture and a
// difference picture are written to <build>/tests/images/output/ for a look.
// STYK_UPDATE_BASELINES=1 rewrites the baselines instead (then look at every one of them).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "case_options.hpp"
#include "image_compare.hpp"
#include "image_models.hpp"
#include "styk/render/osmesa_renderer.hpp"

namespace styk::render_test {
namespace {

constexpr int kWidth = 480;
constexpr int kHeight = 360;
constexpr int kChannelThreshold = 24;  // of 255
constexpr double kAllowedFraction = 0.005;

const std::string kSource = STYK_SOURCE_DIR "/tests/images";
const std::string kOutput = STYK_BINARY_DIR "/tests/images/output";

class ImageRegression : public ::testing::TestWithParam<ImageCase> {};

TEST_P(ImageRegression, MatchesBaseline) {
  const ImageCase& c = GetParam();
  PluginLibraries libraries;
  const ElementRegistry registry = make_test_registry(libraries);
  const TestScene scene = make_scene(c.scene, registry);
  const render::RenderJob job(scene.model, registry, scene.has_results ? &scene.increment : nullptr,
                              options_for(c, kWidth, kHeight));
  render::OsmesaRenderer renderer(kWidth, kHeight);
  const render::Image actual = renderer.render(job.frame(1.0));

  const std::string baseline = kSource + "/baselines/" + c.name + ".png";
  const char* update = std::getenv("STYK_UPDATE_BASELINES");
  if (update && std::string(update) == "1") {
    // Updating is never a pass: the run that writes baselines fails, so it cannot stand in for a
    // comparison (rerun without STYK_UPDATE_BASELINES to compare).
    render::write_png(baseline, actual);
    FAIL() << "baseline written (STYK_UPDATE_BASELINES=1): " << baseline;
  }
  ASSERT_TRUE(std::filesystem::exists(baseline)) << "no baseline " << baseline;
  const CompareResult result =
      compare_images(actual, render::read_png(baseline), kChannelThreshold);
  const bool pass = result.same_size && result.fraction <= kAllowedFraction;
  if (!pass) {
    std::filesystem::create_directories(kOutput);
    render::write_png(kOutput + "/" + c.name + ".actual.png", actual);
    if (result.same_size)
      render::write_png(kOutput + "/" + c.name + ".diff.png", result.difference);
  }
  EXPECT_TRUE(result.same_size) << c.name << ": baseline has another size";
  EXPECT_LE(result.fraction, kAllowedFraction)
      << c.name << ": " << result.differing << " pixels differ; see " << kOutput << "/" << c.name
      << ".actual.png and .diff.png";
}

std::vector<ImageCase> all_cases() {
  try {
    return read_cases(kSource + "/cases.txt");
  } catch (const std::exception&) {
    return {};  // reported by ManifestIsReadable
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, ImageRegression, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<ImageCase>& param) {
                           return param.param.name;
                         });

TEST(ImageManifest, IsReadableAndCoversEveryDisplayMode) {
  const std::vector<ImageCase> cases = read_cases(kSource + "/cases.txt");
  ASSERT_GE(cases.size(), 15u);
  for (const char* mode : {"points", "wireframe", "hidden", "shaded", "shaded-edges"}) {
    bool found = false;
    for (const ImageCase& c : cases)
      for (const std::string& o : c.options) found = found || o == std::string("mode=") + mode;
    EXPECT_TRUE(found) << "no image case for display mode " << mode;
  }
}

}  // namespace
}  // namespace styk::render_test
