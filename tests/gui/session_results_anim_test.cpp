// Results navigation and animation (issue 7) on results made up from the coordinates, so every
// expected value is known exactly: increment labels of a multi-step analysis, the fields an
// increment holds (contact fields only with contact output), one node's value over the load
// history, the animation's deformation fractions with one camera for every frame, and the APNG
// writer read back chunk by chunk.
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "session/animation.hpp"
#include "session/apng.hpp"
#include "session/document.hpp"
#include "session/results_navigation.hpp"
#include "session/scene.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/render/image.hpp"

namespace styk::gui {
namespace {

const std::string kCantilever = std::string(STYK_SOURCE_DIR) + "/samples/cantilever-c3d20.inp";

// Two steps of two increments; the displacement grows with the total time t: U = t (x/10, 0, -x^2
// /100); increments 3 and 4 carry contact output at node 0 with pressure 10 t.
Results history(const Model& m) {
  Results results;
  const double times[4] = {0.5, 1.0, 1.3, 1.6};
  for (int k = 0; k < 4; ++k) {
    IncrementResult inc;
    inc.step = k < 2 ? 1 : 2;
    inc.increment = k % 2 + 1;
    inc.total_time = times[k];
    inc.step_time = k < 2 ? times[k] : times[k] - 1.0;
    for (const Vec3& x : m.coords) {
      const double t = times[k];
      inc.U.push_back({t * x[0] / 10, 0, -t * x[0] * x[0] / 100});
      inc.RF.push_back({0, 0, 0});
      inc.S_nodal_II.push_back({t * x[0], 0, 0, 0, 0, 0});
    }
    if (k >= 2) {
      ContactNodeResult c;
      c.node = 0;
      c.status = ContactStatus::Stick;
      c.pressure = 10 * times[k];
      inc.contact.push_back(c);
    }
    results.increments.push_back(inc);
  }
  return results;
}

class ResultsTest : public ::testing::Test {
 protected:
  ResultsTest() : doc(registry) {
    register_builtin_elements(registry);
    doc.open_inp(kCantilever);
    doc.attach_results(history(doc.model()), "");
  }
  ElementRegistry registry;
  Document doc;
};

TEST_F(ResultsTest, IncrementLabelsNameStepIncrementAndTime) {
  IncrementResult inc;
  inc.step = 2;
  inc.increment = 3;
  inc.total_time = 0.6;
  EXPECT_EQ(increment_label(inc), "step 2, increment 3, time 0.6");
  const std::vector<std::string> labels = increment_labels(*doc.results());
  ASSERT_EQ(labels.size(), 4u);
  EXPECT_EQ(labels[0], "step 1, increment 1, time 0.5");
  EXPECT_EQ(labels[3], "step 2, increment 2, time 1.6");
}

TEST_F(ResultsTest, FieldsFollowWhatTheIncrementHolds) {
  const auto& incs = doc.results()->increments;
  const auto has = [](const std::vector<std::string>& v, const std::string& name) {
    return std::find(v.begin(), v.end(), name) != v.end();
  };
  const std::vector<std::string> first = available_fields(doc.model(), incs[0]);
  EXPECT_TRUE(has(first, "U.mag"));
  EXPECT_TRUE(has(first, "S.mises"));
  EXPECT_FALSE(has(first, "E.11"));  // no strain stored
  EXPECT_FALSE(has(first, "CPRESS"));
  const std::vector<std::string> last = available_fields(doc.model(), incs[3]);
  EXPECT_TRUE(has(last, "CPRESS"));
  EXPECT_TRUE(has(last, "CSTATUS"));
}

TEST_F(ResultsTest, NodeHistoryFollowsTheLoad) {
  const Model& m = doc.model();
  int tip = 0;  // the node of largest x
  for (int n = 0; n < m.node_count(); ++n)
    if (m.coords[n][0] > m.coords[tip][0]) tip = n;
  const double x = m.coords[tip][0];
  const auto uz = node_history(m, *doc.results(), tip, "U.z", render::Averaging::MethodII);
  ASSERT_EQ(uz.size(), 4u);
  const double times[4] = {0.5, 1.0, 1.3, 1.6};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(uz[k].increment, k);
    EXPECT_DOUBLE_EQ(uz[k].time, times[k]);
    EXPECT_NEAR(uz[k].value, -times[k] * x * x / 100, 1e-12);
  }
  // CPRESS exists in increments 3 and 4 only, at node 0: 10 t.
  const auto p = node_history(m, *doc.results(), 0, "CPRESS", render::Averaging::MethodII);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].increment, 2);
  EXPECT_DOUBLE_EQ(p[0].value, 13.0);
  EXPECT_DOUBLE_EQ(p[1].value, 16.0);
  EXPECT_TRUE(node_history(m, *doc.results(), 1, "CPRESS", render::Averaging::MethodII).empty());
  EXPECT_THROW(node_history(m, *doc.results(), 0, "NOPE", render::Averaging::MethodII), InputError);
  EXPECT_THROW(node_history(m, *doc.results(), -1, "U.z", render::Averaging::MethodII), InputError);
  EXPECT_THROW(node_history(m, *doc.results(), 0, "E.11", render::Averaging::MethodII), InputError);
}

TEST_F(ResultsTest, ScaleAnimationGrowsTheDeformationUnderOneCamera) {
  EXPECT_EQ(animation_fractions(5), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  EXPECT_THROW(animation_fractions(1), InputError);
  EXPECT_EQ(animation_frame_path("/tmp/a", "anim", 7), "/tmp/a/anim_0007.png");
  DisplaySettings settings;
  settings.field = "U.mag";
  settings.auto_scale = false;
  settings.scale = 20.0;
  SceneAnimation animation(doc, settings, AnimationKind::Scale, 4);
  ASSERT_EQ(animation.frame_count(), 4);
  Scene scene;
  const Model& m = doc.model();
  const int n = m.node_count() - 1;
  const Vec3& u = doc.results()->increments.back().U[n];
  render::Mat4 camera{};
  for (int k = 0; k < 4; ++k) {
    animation.show(scene, k);
    const double fraction = k / 3.0;
    EXPECT_DOUBLE_EQ(scene.deformation_scale(), 20.0);
    EXPECT_DOUBLE_EQ(scene.drawn_scale(), 20.0 * fraction);
    const Vec3 p = scene.placed(n);
    const Vec3& o = scene.last_frame().geometry.origin;
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(p[i], m.coords[n][i] - o[i] + 20.0 * fraction * u[i], 1e-9);
    const render::Mat4 view = scene.frame(400, 300, {}).camera.view;
    if (k > 0) {
      EXPECT_EQ(view, camera);  // the camera fits the whole motion: it never moves
    }
    camera = view;
  }
  EXPECT_EQ(animation.frame_label(3), "frame 4 of 4: deformation scale 20");
}

TEST_F(ResultsTest, IncrementAnimationHoldsScaleRangeAndCamera) {
  DisplaySettings settings;
  settings.field = "S.11";
  SceneAnimation animation(doc, settings, AnimationKind::Increments, 0);
  ASSERT_EQ(animation.frame_count(), 4);
  Scene scene;
  double scale = -1, lo = 0, hi = 0;
  render::Mat4 camera{};
  for (int k = 0; k < 4; ++k) {
    animation.show(scene, k);
    ASSERT_TRUE(scene.field());
    if (k == 0) scale = scene.deformation_scale(), lo = scene.colors().min, hi = scene.colors().max;
    EXPECT_DOUBLE_EQ(scene.deformation_scale(), scale);
    EXPECT_DOUBLE_EQ(scene.colors().min, lo);
    EXPECT_DOUBLE_EQ(scene.colors().max, hi);
    const render::Mat4 view = scene.frame(400, 300, {}).camera.view;
    if (k > 0) {
      EXPECT_EQ(view, camera);
    }
    camera = view;
  }
  // S.11 = t x: the range runs over every increment, up to the last one's 1.6 x_max.
  double x_max = 0;
  for (const Vec3& x : doc.model().coords) x_max = std::max(x_max, x[0]);
  EXPECT_NEAR(hi, 1.6 * x_max, 1e-9);
  EXPECT_EQ(animation.frame_label(2), "step 2, increment 1, time 1.3");
}

// Reads the chunks of a PNG file: type and data, checking each CRC.
std::vector<std::pair<std::string, std::vector<unsigned char>>> chunks(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), {});
  std::vector<std::pair<std::string, std::vector<unsigned char>>> result;
  std::size_t at = 8;
  const auto be32 = [&](std::size_t i) {
    return (std::uint32_t(bytes[i]) << 24) | (std::uint32_t(bytes[i + 1]) << 16) |
           (std::uint32_t(bytes[i + 2]) << 8) | bytes[i + 3];
  };
  while (at + 12 <= bytes.size()) {
    const std::uint32_t length = be32(at);
    const std::string type(bytes.begin() + at + 4, bytes.begin() + at + 8);
    std::vector<unsigned char> data(bytes.begin() + at + 8, bytes.begin() + at + 8 + length);
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), bytes.data() + at + 4, uInt(4 + length));
    EXPECT_EQ(crc, be32(at + 8 + length)) << type;
    result.emplace_back(type, std::move(data));
    at += 12 + length;
  }
  return result;
}

TEST(Apng, FramesReadBackExactly) {
  std::vector<render::Image> frames;
  for (int k = 0; k < 3; ++k) {
    render::Image image(7, 5);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = std::uint8_t(i * (k + 3));
    frames.push_back(image);
  }
  const std::string path = ::testing::TempDir() + "styk-apng-test.png";
  write_apng(path, frames, 100);
  // An ordinary PNG reader sees the first frame.
  const render::Image first = render::read_png(path);
  EXPECT_EQ(first.rgba, frames[0].rgba);
  const auto list = chunks(path);
  ASSERT_GE(list.size(), 9u);
  EXPECT_EQ(list[0].first, "IHDR");
  EXPECT_EQ(list[1].first, "acTL");
  EXPECT_EQ(list[1].second[3], 3);  // frames
  EXPECT_EQ(list.back().first, "IEND");
  // Every frame: fcTL with the next sequence number, then its data; inflated, the rows (filter
  // byte 0 + RGBA) are the frame's pixels.
  std::uint32_t sequence = 0;
  int frame = 0;
  for (std::size_t i = 2; i + 1 < list.size(); i += 2, ++frame) {
    ASSERT_EQ(list[i].first, "fcTL");
    EXPECT_EQ(list[i].second[3], sequence++);
    EXPECT_EQ((list[i].second[20] << 8) | list[i].second[21], 100);  // delay 100/1000 s
    std::vector<unsigned char> data = list[i + 1].second;
    if (frame == 0) {
      ASSERT_EQ(list[i + 1].first, "IDAT");
    } else {
      ASSERT_EQ(list[i + 1].first, "fdAT");
      EXPECT_EQ(data[3], sequence++);
      data.erase(data.begin(), data.begin() + 4);
    }
    std::vector<unsigned char> raw(5 * (1 + 7 * 4));
    uLongf size = raw.size();
    ASSERT_EQ(uncompress(raw.data(), &size, data.data(), uLong(data.size())), Z_OK);
    ASSERT_EQ(size, raw.size());
    for (int y = 0; y < 5; ++y) {
      EXPECT_EQ(raw[y * 29], 0);
      EXPECT_TRUE(std::equal(raw.begin() + y * 29 + 1, raw.begin() + (y + 1) * 29,
                             frames[frame].rgba.begin() + y * 28));
    }
  }
  EXPECT_EQ(frame, 3);
  EXPECT_THROW(write_apng(path, {}, 100), std::invalid_argument);
  frames[1] = render::Image(3, 3);
  EXPECT_THROW(write_apng(path, frames, 100), std::invalid_argument);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace styk::gui
