// Meshes made by the gmsh program (Debian's gmsh, installed by scripts/install-deps.sh --test)
// imported: every element type Styk maps, in both file versions. The check is geometric and
// independent of the mapping tables: each element's Jacobian is positive at every integration
// point of its own rule, the volumes add up to the box's (1e-12 relative), and every node sits
// where the linear element of its family puts its natural point (the box's elements are
// straight-edged; 1e-9 of the box size, gmsh writes 16 digits).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <fstream>
#include <ostream>
#include <string>

#include "cli_runner.hpp"
#include "styk/core/element.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/gmsh/gmsh_import.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

using testing::run_command;
using testing::scratch_dir;

struct Case {
  const char* name;
  const char* mesh_options;  // .geo lines before the extrusion
  const char* layers;        // extrusion: "Layers{2}; Recombine;" or "" (a free volume: tetrahedra)
  int order;
  const char* format;  // msh22 | msh41
  const char* styk_type;
  const char* linear_type;
};

// The box 2 x 1 x 1: a rectangle extruded along z.
std::string geo(const Case& c) {
  return std::string(
             "h = 0.5;\n"
             "Point(1) = {0, 0, 0, h}; Point(2) = {2, 0, 0, h};\n"
             "Point(3) = {2, 1, 0, h}; Point(4) = {0, 1, 0, h};\n"
             "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
             "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n") +
         c.mesh_options + "out[] = Extrude {0, 0, 1} { Surface{1}; " + c.layers +
         " };\nPhysical Volume(\"body\") = {out[1]};\n"
         "Physical Surface(\"xmin\") = {out[5]};\n"
         "Mesh.ElementOrder = " +
         std::to_string(c.order) + ";\n";
}

double check_element(const Model& model, int e, const std::string& linear_type) {
  const Element& element = model.elements[e];
  const TElement& type = *test::shared_builtin_registry().find(element.type);
  const TElement& linear = *test::shared_builtin_registry().find(linear_type);
  const int n = type.node_count();
  Eigen::MatrixXd x(n, 3);
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) x(a, d) = model.coords[model.element_nodes(e)[a]][d];
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  const IntegrationRule rule = type.rule(RuleKind::Full);
  double volume = 0.0;
  for (int p = 0; p < rule.size(); ++p) {
    type.der(rule.points[p], N, dN);
    const double det = (x.transpose() * dN).determinant();
    EXPECT_GT(det, 0.0) << element.type << " " << element.id;
    volume += det * rule.weights[p];
  }
  const int corners = linear.node_count();
  Eigen::VectorXd Nl(corners);
  Eigen::MatrixXd dNl(corners, 3);
  for (int a = 0; a < n; ++a) {
    linear.der(type.natural_nodes()[a], Nl, dNl);
    const Eigen::RowVector3d expected = Nl.transpose() * x.topRows(corners);
    EXPECT_LT((x.row(a) - expected).norm(), 1e-9)
        << element.type << " " << element.id << " node " << a + 1;
  }
  return volume;
}

// gtest prints a parameter that fails by this (not its bytes).
void PrintTo(const Case& c, std::ostream* out) { *out << c.name; }

class GmshGenerated : public ::testing::TestWithParam<Case> {};

TEST_P(GmshGenerated, EveryElementIsValidAndTheVolumesMakeTheBox) {
  const Case& c = GetParam();
  const std::string dir = scratch_dir(std::string("gmsh_generated_") + c.name);
  std::ofstream(dir + "/box.geo") << geo(c);
  const auto made =
      run_command(std::string("gmsh -v 2 -3 box.geo -format ") + c.format + " -o box.msh", dir);
  ASSERT_EQ(made.exit_code, 0) << "gmsh failed (is Debian's gmsh installed?)\n" << made.err;
  GmshImportSummary summary;
  const Model model = import_gmsh(dir + "/box.msh", {}, &summary);
  EXPECT_EQ(summary.element_types, std::vector<std::string>{c.styk_type});
  EXPECT_EQ(summary.format, std::string(c.format) == "msh22" ? "2.2" : "4.1");
  ASSERT_GT(model.element_count(), 3);
  double volume = 0.0;
  for (int e = 0; e < model.element_count(); ++e) volume += check_element(model, e, c.linear_type);
  EXPECT_NEAR(volume, 2.0, 2e-12);
  ASSERT_TRUE(model.find_nset("XMIN"));
  for (int n : model.find_nset("XMIN")->nodes) EXPECT_NEAR(model.coords[n][0], 0.0, 1e-12);
  EXPECT_EQ(model.find_elset("BODY")->elements.size(),
            static_cast<std::size_t>(model.element_count()));
}

constexpr const char* kHexes = "Transfinite Surface{1}; Recombine Surface{1};\n";
constexpr const char* kLayers = "Layers{2}; Recombine;";
constexpr const char* kIncomplete = "Mesh.SecondOrderIncomplete = 1;\n";

INSTANTIATE_TEST_SUITE_P(
    Types, GmshGenerated,
    ::testing::Values(Case{"tet4", "", "", 1, "msh41", "C3D4", "C3D4"},
                      Case{"tet10", "", "", 2, "msh22", "C3D10", "C3D4"},
                      Case{"tet10_v41", "", "", 2, "msh41", "C3D10", "C3D4"},
                      Case{"hex8", kHexes, kLayers, 1, "msh22", "C3D8", "C3D8"},
                      Case{"hex20",
                           "Transfinite Surface{1}; Recombine Surface{1};\n"
                           "Mesh.SecondOrderIncomplete = 1;\n",
                           kLayers, 2, "msh41", "C3D20", "C3D8"},
                      Case{"hex27", kHexes, kLayers, 2, "msh41", "C3D27", "C3D8"},
                      Case{"prism6", "", kLayers, 1, "msh41", "C3D6", "C3D6"},
                      Case{"prism15", kIncomplete, kLayers, 2, "msh22", "C3D15", "C3D6"}),
    [](const ::testing::TestParamInfo<Case>& param_info) {
      return std::string(param_info.param.name);
    });

}  // namespace
}  // namespace styk
