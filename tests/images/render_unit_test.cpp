// Unit tests of the renderer's CPU side: skin extraction, fields, colour scale, font, camera and
// the option errors.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "image_models.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/mesher/box_mesh.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/field.hpp"
#include "styk/render/font.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/render_job.hpp"
#include "styk/render/skin.hpp"

namespace styk::render_test {
namespace {

class RenderUnit : public ::testing::Test {
 protected:
  RenderUnit() : registry_(make_test_registry(libraries_)) {}
  PluginLibraries libraries_;
  ElementRegistry registry_;
};

Model box(const std::string& type, std::array<int, 3> divisions) {
  Model model;
  mesher::BoxSpec spec;
  spec.type = type;
  spec.size = {1.0 * divisions[0], 1.0 * divisions[1], 1.0 * divisions[2]};
  spec.divisions = divisions;
  mesher::BoxMesh mesh(spec, model);
  return model;
}

std::vector<int> all_elements(const Model& model) {
  std::vector<int> out(model.elements.size());
  for (std::size_t e = 0; e < out.size(); ++e) out[e] = static_cast<int>(e);
  return out;
}

// An n1 x n2 x n3 block has 2 (n1 n2 + n2 n3 + n1 n3) boundary faces, every one on the box
// boundary (all its corners on one side of the box).
TEST_F(RenderUnit, SkinOfABlockIsItsBoundary) {
  for (const std::string type : {"C3D8", "C3D20"}) {
    const Model model = box(type, {3, 4, 5});
    const auto formulations = render::element_formulations(model, registry_);
    const auto skin = render::extract_skin(model, formulations, all_elements(model));
    EXPECT_EQ(skin.size(), 2u * (3 * 4 + 4 * 5 + 3 * 5)) << type;
    const std::array<double, 3> size{3, 4, 5};
    for (const render::SkinFace& f : skin) {
      const FaceDef& face = formulations[f.element]->faces()[f.face];
      bool on_side = false;
      for (int axis = 0; axis < 3 && !on_side; ++axis)
        for (double side : {0.0, size[axis]}) {
          bool all = true;
          for (int k = 0; k < 4; ++k)
            all = all && model.coords[model.element_nodes(f.element)[face.nodes[k]]][axis] == side;
          on_side = on_side || all;
        }
      EXPECT_TRUE(on_side) << "element " << f.element << " face " << f.face;
    }
  }
}

TEST_F(RenderUnit, SkinOfASubsetAndOfOneElement) {
  const Model model = box("C3D20", {4, 2, 2});
  const auto formulations = render::element_formulations(model, registry_);
  std::vector<int> half;
  for (int e = 0; e < model.element_count(); ++e)
    if (model.coords[model.element_nodes(e)[0]][0] < 2.0) half.push_back(e);
  EXPECT_EQ(render::extract_skin(model, formulations, half).size(), 2u * (2 * 2 + 2 * 2 + 2 * 2));
  EXPECT_EQ(render::extract_skin(model, formulations, {5}).size(), 6u);
  EXPECT_TRUE(render::extract_skin(model, formulations, {}).empty());
}

// The plug-in elements' faces come from TElement::faces(): a 2 x 2 x 1 patch of C3D21 / C3D28
// has 2 (4 + 2 + 2) = 16 skin faces; the 9- and 16-node S1 faces are found like any other.
TEST_F(RenderUnit, SkinOfPluginElements) {
  for (const char* name : {"c3d21", "c3d28"}) {
    const TestScene scene = make_scene(name, registry_);
    const auto formulations = render::element_formulations(scene.model, registry_);
    const auto skin = render::extract_skin(scene.model, formulations, all_elements(scene.model));
    EXPECT_EQ(skin.size(), 16u) << name;
    int bottom = 0;
    for (const render::SkinFace& f : skin) bottom += f.face == 0;
    EXPECT_EQ(bottom, 4) << name;  // every element's S1 is on the bottom of the ring
  }
}

// Quadratic and cubic faces are subdivided 4 and 6 times per direction when a field varies over
// them (the rule of face_shape.hpp); an 8-node C3D20 face of a straight box without a field is
// drawn as 2 triangles.
TEST_F(RenderUnit, CurvedFacesAreSubdividedByDegree) {
  const TestScene straight = make_scene("box_mesh", registry_);
  render::SkinModel plain(straight.model, registry_, {render::whole_model_layer(straight.model)},
                          {});
  const render::FrameGeometry flat = render::build_geometry(plain, {});
  EXPECT_EQ(flat.triangles.size() / 3, 2 * plain.face_count());

  const TestScene ring = make_scene("c3d28", registry_);
  render::SkinModel curved(ring.model, registry_, {render::whole_model_layer(ring.model)}, {});
  // Without a field only the faces that are curved as placed are subdivided: 4 S1 faces with
  // cubic arcs (6 x 6), 4 top faces with quadratic arcs (4 x 4), 4 cylinder sides with a cubic
  // bottom edge (6 x 6); the 4 flat radial end faces stay 1 x 1.
  const render::FrameGeometry g = render::build_geometry(curved, {});
  EXPECT_EQ(g.triangles.size() / 3, 2u * (4 * 36 + 4 * 16 + 4 * 36 + 4 * 1));
  // With a field varying over them every higher-order face is subdivided.
  const render::ScalarField field =
      render::evaluate_field(ring.model, ring.increment, "U.mag", render::Averaging::None);
  const render::ColorScale colors;
  render::GeometryRequest request;
  request.field = &field;
  request.colors = &colors;
  EXPECT_EQ(render::build_geometry(curved, request).triangles.size() / 3,
            2u * (4 * 36 + 4 * 16 + 8 * 36));
}

TEST(Fields, MisesAndPrincipalValues) {
  Model model;
  model.add_node(1, {0, 0, 0}, {});
  IncrementResult inc;
  inc.S_nodal_II = {Tensor6{0, 0, 0, 10, 0, 0}};  // pure shear tau = 10
  const auto mises = render::evaluate_field(model, inc, "S.mises", render::Averaging::MethodII);
  EXPECT_NEAR(mises.values[0], std::sqrt(3.0) * 10, 1e-12);
  EXPECT_NEAR(render::evaluate_field(model, inc, "S.p1", render::Averaging::MethodII).values[0], 10,
              1e-12);
  EXPECT_NEAR(render::evaluate_field(model, inc, "S.p3", render::Averaging::MethodII).values[0],
              -10, 1e-12);
  EXPECT_NEAR(render::evaluate_field(model, inc, "s.TRESCA", render::Averaging::MethodII).values[0],
              20, 1e-12);
  inc.S_nodal_II = {Tensor6{-50, 0, 0, 0, 0, 0}};  // uniaxial: Mises = |sigma|
  EXPECT_NEAR(render::evaluate_field(model, inc, "S.mises", render::Averaging::MethodII).values[0],
              50, 1e-12);
}

TEST(Fields, MissingDataNamesWhatExists) {
  Model model;
  model.add_node(1, {0, 0, 0}, {});
  IncrementResult inc;
  inc.S_nodal_I = {Tensor6{1, 2, 3, 0, 0, 0}};
  try {
    render::evaluate_field(model, inc, "S.mises", render::Averaging::MethodII);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("S_nodal_II"), std::string::npos) << m;
    EXPECT_NE(m.find("averaging I (S_nodal_I)"), std::string::npos) << m;
  }
  try {
    render::evaluate_field(model, inc, "S.vonmises", render::Averaging::MethodI);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("S.mises"), std::string::npos) << e.what();
  }
  try {
    render::evaluate_field(model, inc, "CPRESS", render::Averaging::MethodI);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds no contact output"), std::string::npos) << e.what();
  }
  EXPECT_THROW(render::evaluate_field(model, inc, "U", render::Averaging::None), InputError);
}

// ERR (the stress error estimate, one value per element) is drawn as an element field; an
// increment without it names what it holds, and ERR takes no component suffix.
TEST(Fields, StressErrorEstimatePerElement) {
  Model model;
  model.add_node(1, {0, 0, 0}, {});
  model.add_node(2, {1, 0, 0}, {});
  model.add_element(7, "T3D2", {1, 2}, {});
  model.add_element(8, "T3D2", {2, 1}, {});
  IncrementResult inc;
  inc.step = 1;
  inc.increment = 1;
  inc.S_nodal_I = {Tensor6{}, Tensor6{}};
  inc.ERR = {3.5, 12.25};
  const render::ScalarField err =
      render::evaluate_field(model, inc, "err", render::Averaging::None);
  EXPECT_EQ(err.location, render::FieldLocation::Element);
  EXPECT_EQ(err.values, inc.ERR);
  EXPECT_THROW(render::evaluate_field(model, inc, "ERR.x", render::Averaging::None), InputError);
  inc.ERR.clear();
  try {
    render::evaluate_field(model, inc, "ERR", render::Averaging::None);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("holds no ERR"), std::string::npos) << m;
    EXPECT_NE(m.find("it holds: S.* (averaging I)"), std::string::npos) << m;
  }
}

TEST(ColorScale, BandColoursAreDistinct) {
  render::ColorScale scale;
  scale.bands = render::kMaxBands;
  std::set<std::array<int, 3>> colours;
  for (int i = 0; i < scale.bands; ++i) {
    const render::Rgb c = scale.band_color(i);
    colours.insert({render::to_byte(c.r), render::to_byte(c.g), render::to_byte(c.b)});
  }
  EXPECT_EQ(colours.size(), static_cast<std::size_t>(render::kMaxBands));
  scale.min = -1, scale.max = 3, scale.bands = 4;
  EXPECT_EQ(scale.limits(), (std::vector<double>{-1, 0, 1, 2, 3}));
  EXPECT_EQ(render::format_legend_value(-123.456), "-1.235E+02");
}

// The fitted orthographic camera puts every corner of the box inside the viewport and touches
// the 5 % margin on the tighter axis.
TEST(Camera, FitKeepsTheBoxInside) {
  for (const char* view : {"iso", "+x", "-y", "+z"}) {
    render::ViewSpec spec;
    spec.name = view;
    const std::array<float, 3> lo{-2, -0.5f, -0.5f}, hi{2, 0.5f, 0.5f};
    const render::Camera camera = render::fit_camera(spec, lo, hi, 4.0 / 3.0);
    float extent = 0;
    for (int c = 0; c < 8; ++c) {
      const auto p = render::project(
          camera, {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]});
      EXPECT_LE(std::abs(p[0]), 1.0f);
      EXPECT_LE(std::abs(p[1]), 1.0f);
      EXPECT_LE(std::abs(p[2]), 1.0f);
      extent = std::max({extent, std::abs(p[0]), std::abs(p[1])});
    }
    EXPECT_NEAR(extent, 1.0 / 1.05, 1e-5) << view;
  }
}

TEST_F(RenderUnit, BadOptionsAreInputErrorsNamingTheChoices) {
  const TestScene scene = make_scene("box", registry_);
  const auto message = [&](render::RenderOptions o) {
    try {
      render::RenderJob job(scene.model, registry_, &scene.increment, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  render::RenderOptions o;
  o.layers = {"SHAFT"};
  EXPECT_NE(message(o).find("element sets: EALL, LEFT, RIGHT"), std::string::npos) << message(o);
  o = {};
  o.view.name = "top";
  EXPECT_NE(message(o).find("iso"), std::string::npos) << message(o);
  o = {};
  o.bands = 25;
  EXPECT_NE(message(o).find("2..24"), std::string::npos) << message(o);
  o = {};
  o.field = "S.mises";
  o.filter = render::parse_element_filter("1000-2000", "");
  EXPECT_NE(message(o).find("nothing to draw"), std::string::npos) << message(o);
  EXPECT_THROW(render::parse_element_filter("a-b", ""), InputError);
  EXPECT_THROW(render::parse_display_mode("solid"), InputError);
  EXPECT_THROW(render::parse_deform("-1"), InputError);
}

}  // namespace
}  // namespace styk::render_test
