// Shells in the renderer (docs/render.md "Shells"): drawn as surfaces with their thickness, the
// faces offset along the director by t (+-1/2 - offset), the fibres moved by the nodal rotations,
// stress and strain fields on the chosen fibre. The model is a cantilever plate of S4 shells,
// 10 x 2 in the x-y plane, t = 0.5, E = 210000, nu = 0.3, 5 x 2 elements, under a pure end moment
// of m = 1 per unit width about +y (*CLOAD dof 5 at the tip nodes: 0.5, 1, 0.5), supported so that
// the plate may curve anticlastically (root line: u1 and the rotation about y; the root's middle
// node also u2, u3 and the rotations about x and z). Pure bending of a plate (Timoshenko and
// Woinowsky-Krieger, "Theory of Plates and Shells", §2, with the anticlastic curvature free):
// sigma11 = 12 m z / t^3, so +-6 m / t^2 = +-24 at the top and bottom fibre and 0 at the middle,
// uniform over the plate, which the S4 element (MITC4) represents exactly; the curvature
// 12 m / (E t^3) is uniform too, so the deflection grows as x^2 from the root.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "../support/test_scratch.hpp"
#include "image_models.hpp"
#include "pixel_probe.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/results_file.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::render_test {
namespace {

using render::Frame;
using render::Image;

constexpr double kLength = 10.0, kWidth = 2.0, kThickness = 0.5;
constexpr double kMoment = 1.0;                                             // per unit width
constexpr double kFibreStress = 6.0 * kMoment / (kThickness * kThickness);  // 24

// The plate deck: nodes (i, j) on a 6 x 3 grid, id j * 6 + i + 1. `offset`: the section's OFFSET;
// `triangles`: each cell split into two STRI3 along its diagonal instead of one S4.
std::string plate_deck(double offset, bool triangles = false) {
  std::ostringstream out;
  out.precision(17);
  out << "*NODE, NSET=NALL\n";
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 5; ++i)
      out << j * 6 + i + 1 << ", " << kLength * i / 5 << ", " << kWidth * j / 2 << ", 0\n";
  out << "*ELEMENT, TYPE=" << (triangles ? "STRI3" : "S4") << ", ELSET=PLATE\n";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 5; ++i) {
      const int a = j * 6 + i + 1, id = j * 5 + i + 1;
      if (triangles)
        out << 2 * id - 1 << ", " << a << ", " << a + 1 << ", " << a + 7 << "\n"
            << 2 * id << ", " << a << ", " << a + 7 << ", " << a + 6 << "\n";
      else
        out << id << ", " << a << ", " << a + 1 << ", " << a + 7 << ", " << a + 6 << "\n";
    }
  out << "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
      << "*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL" << (offset != 0 ? ", OFFSET=" : "");
  if (offset != 0) out << offset;
  out << "\n"
      << kThickness << "\n*BOUNDARY\n1, 1, 1\n1, 5, 5\n7, 1, 1\n7, 2, 6\n13, 1, 1\n13, 5, 5\n"
      << "*STEP\n*STATIC\n*CLOAD\n6, 5, " << 0.5 * kMoment << "\n12, 5, " << kMoment << "\n18, 5, "
      << 0.5 * kMoment << "\n*END STEP\n";
  return out.str();
}

class ShellRender : public ::testing::Test {
 protected:
  void load(double offset, bool solve, bool triangles = false) {
    const std::string deck =
        (test::test_scratch_dir("shell_render") / (triangles ? "tri.inp" : "plate.inp")).string();
    std::ofstream(deck) << plate_deck(offset, triangles);
    registry_ = make_test_registry(libraries_);
    model_ = read_inp(deck, registry_);
    if (!solve) return;
    Results results = run_static_analysis(model_, registry_, SolveOptions{}, nullptr, nullptr);
    increment_ = std::move(results.increments.back());
  }

  render::RenderJob job(const render::RenderOptions& o) const {
    return render::RenderJob(model_, registry_, increment_.U.empty() ? nullptr : &increment_, o);
  }

  // S.11 in pure bending: the legend spans +24 / 0 / -24 on the top / middle / bottom fibre
  // (1e-6 of 24).
  void expect_pure_bending_fibres() const {
    const struct {
      render::ShellFibre fibre;
      double expected;
    } cases[] = {{render::ShellFibre::Top, kFibreStress},
                 {render::ShellFibre::Middle, 0.0},
                 {render::ShellFibre::Bottom, -kFibreStress}};
    for (const auto& c : cases) {
      render::RenderOptions o;
      o.width = 320, o.height = 240;
      o.field = "S.11";
      o.shell_fibre = c.fibre;
      const render::RenderJob j = job(o);
      const double tolerance = 1e-6 * kFibreStress;
      EXPECT_NEAR(j.colors().min, c.expected, tolerance) << render::shell_fibre_name(c.fibre);
      EXPECT_NEAR(j.colors().max, c.expected, tolerance) << render::shell_fibre_name(c.fibre);
    }
  }

  // U.z over the deformed plate seen from -y (640 x 480, automatic scale): the pixels near the
  // root (node 0) must be of the highest bands and those near the tip (node 5) of the lowest,
  // where the scaled deflection puts them. Returns the frame and the deformation scale.
  std::pair<Frame, double> expect_deflection_bands() const {
    render::RenderOptions o;
    o.width = 640, o.height = 480;
    o.field = "U.z";
    o.view.name = "-y";
    o.deform.kind = render::DeformSpec::Kind::Auto;
    o.samples = 1;
    const render::RenderJob j = job(o);
    Frame frame = j.frame();
    render::OsmesaRenderer renderer(o.width, o.height);
    const Image image = renderer.render(frame);
    const double s = j.deformation_scale();
    EXPECT_GT(s, 0.0);
    const auto deformed = [&](int node, double dx) {
      const Vec3& x = model_.coords[node];
      const Vec3& u = increment_.U[node];
      return Vec3{x[0] + s * u[0] + dx, x[1], x[2] + s * u[2]};
    };
    const int root = band_at(image, pixel_of(frame, deformed(0, 0.5)), frame.colors);
    const int tip = band_at(image, pixel_of(frame, deformed(5, -0.3)), frame.colors);
    EXPECT_GE(tip, 0);
    EXPECT_LE(tip, 1);
    EXPECT_GE(root, 10);
    return {std::move(frame), s};
  }

  PluginLibraries libraries_;
  ElementRegistry registry_;
  Model model_;
  IncrementResult increment_;
};

// The 10 shells are drawn as a slab t thick: the undeformed bounds run from z = -t/2 to +t/2
// (no offset) or from -t to 0 (OFFSET=0.5: the nodes on the top face), the whole plate in x and y.
TEST_F(ShellRender, ShellsAreDrawnWithTheirThickness) {
  for (const double offset : {0.0, 0.5}) {
    load(offset, false);
    render::RenderOptions o;
    o.width = 320, o.height = 240;
    o.deform.kind = render::DeformSpec::Kind::None;
    const render::RenderJob j = job(o);
    ASSERT_EQ(j.skin().layers().size(), 1u);
    EXPECT_EQ(j.skin().layers()[0].shells.size(), 10u);
    EXPECT_TRUE(j.skin().layers()[0].faces.empty());
    const Frame frame = j.frame();
    const Vec3& origin = frame.geometry.origin;
    EXPECT_NEAR(frame.geometry.lower[2] + origin[2], -kThickness * (0.5 + offset), 1e-6) << offset;
    EXPECT_NEAR(frame.geometry.upper[2] + origin[2], kThickness * (0.5 - offset), 1e-6) << offset;
    EXPECT_NEAR(frame.geometry.lower[0] + origin[0], 0.0, 1e-6);
    EXPECT_NEAR(frame.geometry.upper[0] + origin[0], kLength, 1e-6);
    EXPECT_NEAR(frame.geometry.upper[1] + origin[1], kWidth, 1e-6);
    // Side walls on the free edges (14 element edges of the outline, 4 segments each: 2
    // triangles per segment) besides the top and bottom grids (10 elements x 2 faces x 4 x 4
    // cells x 2 triangles).
    EXPECT_EQ(frame.geometry.triangles.size() / 3, std::size_t(10 * 2 * 16 * 2 + 14 * 4 * 2));
  }
}

// Analytic truth (pure bending of a plate, file comment): S.11 is +24 on the top fibre, -24 on
// the bottom fibre and 0 on the middle one; the legend's range is the range on the chosen fibre
// (tolerance 1e-6 of 24: the S4 element is exact in pure bending, what remains is round-off).
TEST_F(ShellRender, TheLegendRangeIsTheFieldOnTheChosenFibre) {
  load(0.0, true);
  expect_pure_bending_fibres();
}

// A field over the deformed shells, seen from -y: under the moment about +y the tip goes down,
// U.z = -(curvature) x^2 / 2, so the pixels near the tip (where the scaled deflection puts it)
// are of the lowest band and those near the root of the highest. The fibres turn with the nodes:
// the slab's far end (largest x) is the top face's tip corner X + s u + (t/2) R(s theta) e3 and
// its lowest point the bottom face's, R the finite rotation by the scaled nodal rotation (1e-5:
// float vertices); without the turn the end would lie (t/2) sin(s theta_y) = 0.05 nearer.
TEST_F(ShellRender, FieldsAreDrawnOnTheDeformedShells) {
  load(0.0, true);
  const auto [frame, s] = expect_deflection_bands();
  ASSERT_GT(s, 0.0);
  double far_end = -1e300, lowest = 1e300;
  for (const int node : {5, 11, 17}) {  // the tip nodes
    const Vec3& x = model_.coords[node];
    const Vec3& u = increment_.U[node];
    const Vec3& r = increment_.UR[node];
    const Eigen::Vector3d theta(s * r[0], s * r[1], s * r[2]);
    const Eigen::Vector3d fibre =
        Eigen::AngleAxisd(theta.norm(), theta.normalized()) * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d mid(x[0] + s * u[0], x[1] + s * u[1], x[2] + s * u[2]);
    far_end = std::max(far_end, (mid + 0.5 * kThickness * fibre).x());
    lowest = std::min(lowest, (mid - 0.5 * kThickness * fibre).z());
  }
  const Vec3& origin = frame.geometry.origin;
  EXPECT_NEAR(frame.geometry.upper[0] + origin[0], far_end, 1e-5 * kLength);
  EXPECT_NEAR(frame.geometry.lower[2] + origin[2], lowest, 1e-5 * kLength);
  EXPECT_GT(0.5 * kThickness * std::sin(s * increment_.UR[5][1]), 0.04);
}

// A results file alone draws the shells' thickness (/model/shell_sections, docs/results.md):
// written and read back, the section keeps thickness 0.5 and offset 0.5, and the drawn slab runs
// from z = -t to 0 as from the deck; S.11 on the top fibre is +24 from the file as from memory.
TEST_F(ShellRender, AResultsFileKeepsTheShellSections) {
  load(0.5, true);
  const std::string path = (test::test_scratch_dir("shell_render") / "plate.styk.h5").string();
  Results results;
  results.increments.push_back(increment_);
  write_results_file(path, model_, results);
  const ResultsFileContents file = read_results_file(path);
  ASSERT_EQ(file.model.sections.size(), 1u);
  ASSERT_TRUE(file.model.sections[0].shell.has_value());
  EXPECT_DOUBLE_EQ(*file.model.sections[0].thickness, kThickness);
  EXPECT_DOUBLE_EQ(file.model.sections[0].shell->offset, 0.5);
  render::RenderOptions o;
  o.width = 320, o.height = 240;
  o.field = "S.11";
  const render::RenderJob j(file.model, registry_, &file.results.increments.back(), o);
  const Frame frame = j.frame();
  EXPECT_NEAR(frame.geometry.lower[2] + frame.geometry.origin[2], -kThickness, 1e-6);
  EXPECT_NEAR(frame.geometry.upper[2] + frame.geometry.origin[2], 0.0, 1e-6);
  EXPECT_NEAR(j.colors().min, kFibreStress, 1e-6 * kFibreStress);
  EXPECT_NEAR(j.colors().max, kFibreStress, 1e-6 * kFibreStress);
}

// The plate of STRI3 triangles (two per cell) is drawn as a slab like the S4 plate, each
// triangle's faces a grid over the triangle (4 x 4 cells of the collapsed square, 2 triangles
// each, the last row degenerate) and walls on its free edges: 20 triangles x 2 faces x 32 plus
// the 14 outline edges x 4 segments x 2. Undeformed bounds: the whole plate, z = +-t/2.
TEST_F(ShellRender, TriangularShellsAreDrawnWithTheirThickness) {
  load(0.0, false, true);
  render::RenderOptions o;
  o.width = 320, o.height = 240;
  o.deform.kind = render::DeformSpec::Kind::None;
  const render::RenderJob j = job(o);
  ASSERT_EQ(j.skin().layers().size(), 1u);
  EXPECT_EQ(j.skin().layers()[0].shells.size(), 20u);
  const Frame frame = j.frame();
  const Vec3& origin = frame.geometry.origin;
  EXPECT_NEAR(frame.geometry.lower[2] + origin[2], -0.5 * kThickness, 1e-6);
  EXPECT_NEAR(frame.geometry.upper[2] + origin[2], 0.5 * kThickness, 1e-6);
  EXPECT_NEAR(frame.geometry.lower[0] + origin[0], 0.0, 1e-6);
  EXPECT_NEAR(frame.geometry.upper[0] + origin[0], kLength, 1e-6);
  EXPECT_NEAR(frame.geometry.lower[1] + origin[1], 0.0, 1e-6);
  EXPECT_NEAR(frame.geometry.upper[1] + origin[1], kWidth, 1e-6);
  EXPECT_EQ(frame.geometry.triangles.size() / 3, std::size_t(20 * 2 * 16 * 2 + 14 * 4 * 2));
}

// Analytic truth (pure bending, file comment) on the DKT triangle, which represents a constant
// curvature exactly (docs/elements.md "STRI3"): the fibre stresses the renderer interpolates from
// the triangle's three surface points (a linear fit) are +24 / 0 / -24 on the top / middle /
// bottom fibre over the whole plate (1e-6 of 24), and the deflection drawn grows towards the tip.
TEST_F(ShellRender, TriangularShellsShowTheFieldOnTheChosenFibre) {
  load(0.0, true, true);
  expect_pure_bending_fibres();
  expect_deflection_bands();
}

}  // namespace
}  // namespace styk::render_test

namespace styk::render_test {
namespace {

constexpr double kRadius = 10.0, kPanelLength = 4.0, kPanelThickness = 0.5;
constexpr int kFacets = 4;
double angle(int i) { return (-20.0 + 10.0 * i) * M_PI / 180.0; }

// A cylindrical panel (R = 10, 40 degrees in 4 flat S4 facets of 10 degrees, length 4, t = 0.5),
// nodes (i, j) with id j * 5 + i + 1 at angle(i); `model_extra` goes after the section.
std::string panel_deck(const std::string& name, const std::string& model_extra = "") {
  std::ostringstream deck;
  deck.precision(17);
  deck << "*NODE, NSET=NALL\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= kFacets; ++i)
      deck << j * 5 + i + 1 << ", " << kRadius * std::sin(angle(i)) << ", " << kPanelLength * j
           << ", " << kRadius * std::cos(angle(i)) << "\n";
  deck << "*ELEMENT, TYPE=S4, ELSET=PANEL\n";
  for (int i = 0; i < kFacets; ++i)
    deck << i + 1 << ", " << i + 1 << ", " << i + 6 << ", " << i + 7 << ", " << i + 2 << "\n";
  deck << "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*SHELL SECTION, ELSET=PANEL, "
       << "MATERIAL=STEEL\n"
       << kPanelThickness << "\n"
       << model_extra << "*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*END STEP\n";
  const std::string path = (test::test_scratch_dir("shell_render") / name).string();
  std::ofstream(path) << deck.str();
  return path;
}

// A curved shell is drawn with the normals the solver uses (docs/elements.md "Nodal normals of
// shells"): a cylindrical panel (R = 10, 40 degrees in 4 flat S4 facets of 10 degrees, length 4,
// t = 0.5) has, at each node shared by two facets, the average of their normals, which is the
// radius; the top and bottom faces along those shared edges therefore lie on the cylinders
// R +- t/2 (a facet's own normal, 5 degrees off the radius, would put them (t/2)(1 - cos 5 deg)
// = 9.5e-4 inside and 2.2e-3 rad round). Checked on every drawn vertex at a shared node's angle
// (float vertices: 1e-5).
TEST(ShellRenderNormals, CurvedShellsAreDrawnWithTheSolversNodalNormals) {
  PluginLibraries libraries;
  const ElementRegistry registry = make_test_registry(libraries);
  const Model model = read_inp(panel_deck("panel.inp"), registry);
  render::RenderOptions o;
  o.width = 320, o.height = 240;
  o.deform.kind = render::DeformSpec::Kind::None;
  const render::RenderJob j(model, registry, nullptr, o);
  const Frame frame = j.frame();
  const Vec3& origin = frame.geometry.origin;
  int checked = 0;
  for (const render::Vertex& v : frame.geometry.face_vertices) {
    const double x = v.position[0] + origin[0], z = v.position[2] + origin[2];
    const double phi = std::atan2(x, z), r = std::hypot(x, z);
    for (int i = 1; i < kFacets; ++i) {
      if (std::abs(phi - angle(i)) > 1e-6) continue;
      const double expected =
          r > kRadius ? kRadius + 0.5 * kPanelThickness : kRadius - 0.5 * kPanelThickness;
      EXPECT_NEAR(r, expected, 1e-5) << "vertex at " << phi * 180.0 / M_PI << " degrees";
      ++checked;
    }
  }
  // Both faces of both facets at each of the 3 shared edges, each edge a row of grid points.
  EXPECT_GE(checked, 3 * 2 * 2 * 2);
}

// The normals a deck gives (*NORMAL, or *NODE fields 5-7) travel in the results file
// (/model/shell_normals, docs/results.md), so a picture drawn from the file alone has the slabs
// the solver used: here node 3 (shared by facets 2 and 3) gets a normal tilted 10 degrees off the
// radius; written and read back, the normals are the same and every drawn vertex is where the
// deck's model puts it (float vertices: 1e-6), while without the group they would move by
// (t/2) sin 10 deg = 0.043 at that node.
TEST(ShellRenderNormals, AResultsFileKeepsTheGivenNormals) {
  PluginLibraries libraries;
  const ElementRegistry registry = make_test_registry(libraries);
  const double tilt = angle(2) + 10.0 * M_PI / 180.0;
  std::ostringstream normal;
  normal.precision(17);
  normal << "*NORMAL\nPANEL, 3, " << std::sin(tilt) << ", 0., " << std::cos(tilt) << "\n";
  Model model = read_inp(panel_deck("panel_given.inp", normal.str()), registry);
  ASSERT_EQ(model.normals.size(), 2u);
  Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  const std::string path =
      (test::test_scratch_dir("shell_render") / "panel_given.styk.h5").string();
  write_results_file(path, model, results);
  const ResultsFileContents file = read_results_file(path);
  ASSERT_EQ(file.model.normals.size(), model.normals.size());
  for (std::size_t k = 0; k < model.normals.size(); ++k) {
    EXPECT_EQ(file.model.normals[k].element, model.normals[k].element);
    EXPECT_EQ(file.model.normals[k].node, model.normals[k].node);
    EXPECT_EQ(file.model.normals[k].direction, model.normals[k].direction);
  }
  render::RenderOptions o;
  o.width = 320, o.height = 240;
  o.deform.kind = render::DeformSpec::Kind::None;
  const Frame from_deck = render::RenderJob(model, registry, nullptr, o).frame();
  const Frame from_file = render::RenderJob(file.model, registry, nullptr, o).frame();
  ASSERT_EQ(from_file.geometry.face_vertices.size(), from_deck.geometry.face_vertices.size());
  for (std::size_t v = 0; v < from_deck.geometry.face_vertices.size(); ++v)
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(from_file.geometry.face_vertices[v].position[d] + from_file.geometry.origin[d],
                  from_deck.geometry.face_vertices[v].position[d] + from_deck.geometry.origin[d],
                  1e-6)
          << v;
}

}  // namespace
}  // namespace styk::render_test
