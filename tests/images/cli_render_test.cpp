// The body of `styk render` (cli/src/command_render.cpp), called directly: a results file and a
// deck in, PNG files out; bad options are InputErrors that list what exists (exit code 1).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "image_models.hpp"
#include "render_args.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/results_file.hpp"
#include "styk/mesher/cantilever.hpp"
#include "styk/render/image.hpp"

namespace styk::render_test {
namespace {

namespace fs = std::filesystem;

class RenderCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(STYK_BINARY_DIR) / "tests/images/cli" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    setenv("STYK_PLUGIN_PATH", STYK_PLUGIN_BUILD_DIR, 1);
    PluginLibraries libraries;
    const ElementRegistry registry = make_test_registry(libraries);
    TestScene scene = make_scene("box", registry);
    Results results;
    scene.increment.step = 1, scene.increment.increment = 1;
    results.increments.push_back(scene.increment);
    IncrementResult second = scene.increment;
    second.increment = 2;
    results.increments.push_back(second);
    write_results_file(results_path(), scene.model, results);
    // A complete deck (material, section, step) for the mesh-only path: the reader validates it.
    mesher::CantileverSpec cantilever;
    cantilever.box.size = {4.0, 1.0, 1.0};
    cantilever.box.divisions = {4, 2, 2};
    std::ofstream deck(deck_path());
    write_inp(mesher::make_cantilever(cantilever), deck);
  }
  std::string results_path() const { return (dir_ / "box.styk.h5").string(); }
  std::string deck_path() const { return (dir_ / "box.inp").string(); }
  std::string error_of(const cli::RenderArgs& args) const {
    try {
      cli::render_command(args);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  fs::path dir_;
};

TEST_F(RenderCommand, ResultsFileToPng) {
  cli::RenderArgs args;
  args.input = results_path();
  args.field = "S.mises";
  args.averaging = "II";
  args.layers = "left,right";
  args.size = "400x300";
  args.output = (dir_ / "mises.png").string();
  EXPECT_EQ(cli::render_command(args), 0);
  const render::Image image = render::read_png(args.output);
  EXPECT_EQ(image.width, 400);
  EXPECT_EQ(image.height, 300);
}

TEST_F(RenderCommand, DeckMeshOnlyWithDefaultOutputName) {
  cli::RenderArgs args;
  args.input = deck_path();
  args.size = "320x240";
  args.mode = "hidden";
  EXPECT_EQ(cli::render_command(args), 0);
  EXPECT_TRUE(fs::exists(dir_ / "box.png"));
}

TEST_F(RenderCommand, AnimationWritesAPngSequence) {
  cli::RenderArgs args;
  args.input = results_path();
  args.size = "160x120";
  args.animate = 3;
  args.output = (dir_ / "anim.png").string();
  EXPECT_EQ(cli::render_command(args), 0);
  for (const char* name : {"anim_0000.png", "anim_0001.png", "anim_0002.png"})
    EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  EXPECT_FALSE(fs::exists(dir_ / "anim_0003.png"));
}

TEST_F(RenderCommand, UnknownFieldStepOrLayerListsWhatExists) {
  cli::RenderArgs args;
  args.input = results_path();
  args.size = "160x120";
  args.output = (dir_ / "x.png").string();
  args.field = "S.vonmises";
  const std::string field = error_of(args);
  EXPECT_NE(field.find("box.styk.h5"), std::string::npos) << field;
  EXPECT_NE(field.find("S.mises"), std::string::npos) << field;
  args.field = "S.mises";
  args.step = 3;
  const std::string step = error_of(args);
  EXPECT_NE(step.find("available: 1/1 1/2"), std::string::npos) << step;
  args.step = 0;
  args.layers = "shaft,sleeve";
  const std::string layer = error_of(args);
  EXPECT_NE(layer.find("element sets: EALL, LEFT, RIGHT"), std::string::npos) << layer;
  args.layers = "";
  args.size = "big";
  EXPECT_NE(error_of(args).find("WIDTHxHEIGHT"), std::string::npos);
  args.size = "160x120";
  args.input = deck_path();
  args.field = "U";
  EXPECT_NE(error_of(args).find("mesh only"), std::string::npos);
}

}  // namespace
}  // namespace styk::render_test
