// Planar elements in the renderer (docs/render.md "Planar elements"): a CPS4/CPE8 element's faces
// are its edges, so its skin is the element's own area (drawn_faces), and a plane mesh is drawn as
// a filled surface with contours, not as bare lines. The deck is samples/spec-6.1-electric-plate-
// cps4.inp (SPEC §6.1: 812 CPS4 on a 1 x 1 plate in the x-y plane); the results are synthetic,
// U = displacement_at(x) (image_models.hpp), so U.x = 0.01 x rises left to right.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>

#include "image_models.hpp"
#include "styk/inp/reader.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {
namespace {

const std::string kDeck =
    std::string(STYK_SOURCE_DIR) + "/samples/spec-6.1-electric-plate-cps4.inp";

class PlanarElements : public ::testing::Test {
 protected:
  PlanarElements() : registry_(make_test_registry(libraries_)), model_(read_inp(kDeck, registry_)) {
    increment_.step = 1, increment_.increment = 1;
    for (const Vec3& x : model_.coords) increment_.U.push_back(displacement_at(x));
  }
  render::Image render(const render::RenderOptions& o) const {
    const render::RenderJob job(model_, registry_, &increment_, o);
    render::OsmesaRenderer renderer(o.width, o.height);
    return renderer.render(job.frame(1.0));
  }
  static render::RenderOptions from_above() {
    render::RenderOptions o;
    o.width = 400, o.height = 300;
    o.view.name = "+z";
    o.deform = render::parse_deform("none");
    return o;
  }
  // The pixels of the middle row inside the model area that are not background.
  static std::vector<std::array<int, 3>> middle_row(const render::Image& image) {
    std::vector<std::array<int, 3>> row;
    const int y = image.height / 2;
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] == 255 && p[1] == 255 && p[2] == 255) continue;  // the white background
      row.push_back({p[0], p[1], p[2]});
    }
    return row;
  }

  PluginLibraries libraries_;
  ElementRegistry registry_;
  Model model_;
  IncrementResult increment_;
};

TEST_F(PlanarElements, APlanarElementsSkinIsItsOwnArea) {
  for (const char* planar : {"CPS4", "CPE4", "CPS8", "CPE8"}) {
    const TElement& element = *registry_.find(planar);
    EXPECT_TRUE(render::is_planar_element(element)) << planar;
    const std::vector<FaceDef> faces = render::drawn_faces(element);
    // The 4 edges stay as empty placeholders (their S1..S4 indices), the area comes last.
    ASSERT_EQ(faces.size(), element.faces().size() + 1) << planar;
    EXPECT_TRUE(faces[0].nodes.empty());
    EXPECT_EQ(faces.back().nodes.size(), std::size_t(element.node_count()));
  }
  for (const char* other : {"C3D8", "C3D20", "T3D2"})
    EXPECT_FALSE(render::is_planar_element(*registry_.find(other))) << other;
  // Every element of the plate is one drawn face, its area.
  render::RenderOptions o = from_above();
  const render::RenderJob job(model_, registry_, nullptr, o);
  ASSERT_EQ(job.skin().layers().size(), 1u);
  const auto& faces = job.skin().layers()[0].faces;
  EXPECT_EQ(faces.size(), 812u);
  std::set<int> elements;
  for (const render::SkinFace& f : faces) {
    EXPECT_EQ(f.face, 4);  // after the 4 edges
    elements.insert(f.element);
  }
  EXPECT_EQ(elements.size(), 812u);
}

TEST_F(PlanarElements, ThePlateIsFilledAndCarriesTheContour) {
  // Mesh only, seen from above: the middle row is plate from edge to edge (the outline and the
  // shaded fill), not background between mesh lines as when only the edges were drawn.
  const render::Image plain = render(from_above());
  const auto plate = middle_row(plain);
  ASSERT_GT(plate.size(), 200u);  // the 1 x 1 plate fills most of the 400 px width
  std::set<std::array<int, 3>> plain_colours(plate.begin(), plate.end());
  EXPECT_LE(plain_colours.size(), 3u);  // fill and outline

  // U.x = 0.01 x in 12 bands: the row runs through the bands from left to right.
  render::RenderOptions o = from_above();
  o.field = "U.x";
  const auto contour = middle_row(render(o));
  ASSERT_GT(contour.size(), 200u);
  std::vector<std::array<int, 3>> changes{contour.front()};
  for (const auto& c : contour)
    if (c != changes.back()) changes.push_back(c);
  std::set<std::array<int, 3>> bands(changes.begin(), changes.end());
  EXPECT_GE(bands.size(), 12u);  // every band (the slit's outline may add a colour)
  EXPECT_NE(contour.front(), contour.back());
}

}  // namespace
}  // namespace styk::render_test
