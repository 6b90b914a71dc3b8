// The view saved with the deck (issue 7: "layers ... shown/hidden, coloured" and the element filter
// survive a save and an open; session/view_state.hpp). A 4 x 4 x 4 C3D8 box on [0, 4]^3 with a user
// layer, a hidden and recoloured layer and a filter is saved, reopened and compared; the solver's
// reader takes the same deck unchanged; bad view lines are dropped with file:line warnings.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "box_model.hpp"
#include "session/document.hpp"
#include "session/layer_edits.hpp"
#include "session/validation.hpp"
#include "session/view_state.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"

namespace styk::gui {
namespace {

using test::box_model;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class GuiViewStateTest : public ::testing::Test {
 protected:
  GuiViewStateTest() : doc(registry) {
    register_builtin_elements(registry);
    doc.apply(make_replace_model("box", Model{}, box_model()));
    // A deck opens only with sections and a step.
    doc.apply(material_command(doc.model(), {"STEEL", 210000.0, 0.3}));
    doc.apply(section_command(doc.model(), {"BOX", "STEEL"}));
    doc.apply(step_command(doc.model(), {"LOAD", 1.0, 1.0}));
  }
  ~GuiViewStateTest() override { std::remove(path.c_str()); }
  void write(const std::string& text) {
    std::ofstream out(path);
    out << text;
  }
  ElementRegistry registry;
  Document doc;
  // One file per test and process: ctest runs the cases in parallel, other build trees too.
  const std::string path = ::testing::TempDir() + "styk_view_state_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                           std::to_string(::getpid()) + ".inp";
};

TEST_F(GuiViewStateTest, LayersAndFilterComeBackAfterSaveAndOpen) {
  // The bottom slab (ids 1-16) as a user layer, hidden; the part layer recoloured; a filter.
  add_layer_from_filter(doc, "Slab", make_element_filter(doc.model(), "1-16", {}));
  doc.layers().set_visible("SLAB", false);
  doc.layers().set_color("BOX", render::Rgb{0.8f, 0.2f, 0.0666667f});
  doc.set_filter(make_element_filter(doc.model(), "1-40, 60", {"C3D8"}));
  doc.save_inp(path);

  const std::string text = read_text(path);
  EXPECT_NE(text.find("**STYK LAYER, NAME=SLAB, USER=YES, VISIBLE=NO, COLOR="), std::string::npos);
  EXPECT_NE(text.find("**STYK LAYER, NAME=BOX, USER=NO, VISIBLE=YES, COLOR=CC3311"),
            std::string::npos);
  EXPECT_NE(text.find("**STYK FILTER, IDS=1-40 60, TYPES=C3D8"), std::string::npos);

  Document reopened(registry);
  reopened.open_inp(path);
  EXPECT_TRUE(reopened.open_warnings().empty());
  ASSERT_EQ(reopened.layers().user_layers(), std::vector<std::string>{"SLAB"});
  const auto& layers = reopened.layers().layers();
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[0].name, "SLAB");
  EXPECT_EQ(layers[0].elements.size(), 16u);
  EXPECT_FALSE(layers[0].visible);
  EXPECT_EQ(layers[1].name, "BOX");
  EXPECT_EQ(layers[1].elements.size(), 48u);  // the slab's 16 are claimed by the user layer
  EXPECT_TRUE(layers[1].visible);
  // 8-bit colour: within half a step of 1/255.
  EXPECT_NEAR(layers[1].color.r, 0.8f, 0.5f / 255);
  EXPECT_NEAR(layers[1].color.g, 0.2f, 0.5f / 255);
  EXPECT_NEAR(layers[1].color.b, 0.0666667f, 0.5f / 255);
  EXPECT_EQ(format_id_ranges(reopened.filter().ranges), "1-40, 60");
  EXPECT_EQ(reopened.filter().types, std::vector<std::string>{"C3D8"});
  EXPECT_FALSE(reopened.is_modified());

  // The solver reads the same deck: the view lines are comments.
  const Model solver_model = read_inp(path, registry);
  EXPECT_EQ(solver_model.element_count(), 64);
  EXPECT_NE(solver_model.find_elset("SLAB"), nullptr);

  // Saved again unchanged: the same text after the header line, which names the source (the view
  // does not drift through a round trip).
  reopened.save_inp(path);
  const auto body = [](const std::string& deck) { return deck.substr(deck.find('\n')); };
  EXPECT_EQ(body(read_text(path)), body(text));
}

TEST_F(GuiViewStateTest, ADeckWithoutViewLinesOpensWithDefaults) {
  doc.save_inp(path);
  // The default view still writes the part layer's style, and no filter line.
  EXPECT_EQ(read_text(path).find("**STYK FILTER"), std::string::npos);
  Document reopened(registry);
  reopened.open_inp(path);
  EXPECT_TRUE(reopened.open_warnings().empty());
  EXPECT_FALSE(reopened.filter().active());
  EXPECT_TRUE(reopened.layers().user_layers().empty());
  ASSERT_EQ(reopened.layers().layers().size(), 1u);
  EXPECT_TRUE(reopened.layers().layers()[0].visible);
}

TEST_F(GuiViewStateTest, BadViewLinesAreDroppedWithTheirLine) {
  doc.save_inp(path);
  std::string text = read_text(path);
  // Appended after the saved view lines, so these are the deck's last six lines.
  int first = 1;
  for (char c : text) first += c == '\n';
  text +=
      "**STYK LAYER, NAME=NOPE, USER=YES, VISIBLE=NO, COLOR=FF0000\n"  // no such set
      "**STYK LAYER, NAME=BOX, VISIBLE=MAYBE, COLOR=FF0000\n"          // not YES/NO
      "**styk layer, name=box, color=12345\n"                          // 5 digits
      "**STYK CAMERA, AZIMUTH=30\n"                                    // unknown line
      "**STYK LAYER, NAME=BOX, VISIBLE=NO, COLOR=00FF00\n"             // fine
      "**STYK FILTER, TYPES=C3D20\n";                                  // type not in model
  write(text);
  Document reopened(registry);
  reopened.open_inp(path);
  const std::vector<std::string>& warnings = reopened.open_warnings();
  ASSERT_EQ(warnings.size(), 5u);
  const auto expect = [&](std::size_t i, int line, const std::string& words) {
    EXPECT_EQ(warnings[i].rfind(path + ":" + std::to_string(line) + ": ", 0), 0u) << warnings[i];
    EXPECT_NE(warnings[i].find(words), std::string::npos) << warnings[i];
  };
  // Parse problems first (in line order), then what the model cannot take.
  expect(0, first + 1, "VISIBLE=MAYBE is neither YES nor NO");
  expect(1, first + 2, "COLOR=12345 is not six hex digits");
  expect(2, first + 3, "unknown view line \"CAMERA\"");
  expect(3, first, "user layer NOPE has no element set");
  expect(4, first + 5, "filter dropped");
  // The good line still applies; nothing else changed.
  EXPECT_FALSE(reopened.layers().layer("BOX").visible);
  EXPECT_NEAR(reopened.layers().layer("BOX").color.g, 1.0f, 1e-6f);
  EXPECT_FALSE(reopened.filter().active());
  EXPECT_TRUE(reopened.layers().user_layers().empty());
}

TEST_F(GuiViewStateTest, NewModelDropsTheFilter) {
  doc.set_filter(make_element_filter(doc.model(), "1-8", {}));
  doc.new_model();
  EXPECT_FALSE(doc.filter().active());
}

}  // namespace
}  // namespace styk::gui
