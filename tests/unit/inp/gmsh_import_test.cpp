// Gmsh import (styk import): the hand-written fixtures of tests/inputs/gmsh, laid out from the MSH
// format's description (versions 2.2 and 4.1) and its node-numbering figures. Every element's
// node order is checked geometrically: each node must sit where the element's own shape functions
// put its natural point (for straight-edged elements, the point the corners' linear map gives),
// and the Jacobian must be positive at every integration point with the volume exact (1e-12).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "styk/core/element.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/gmsh/gmsh_import.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

std::string fixture(const std::string& name) {
  return std::string(STYK_SOURCE_DIR) + "/tests/inputs/gmsh/" + name;
}

// The element's volume by its own full rule; fails the test on a Jacobian that is not positive.
double element_volume(const Model& model, int e) {
  const Element& element = model.elements[e];
  const TElement& type = *test::shared_builtin_registry().find(element.type);
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
    EXPECT_GT(det, 0.0) << element.type << " element " << element.id << " point " << p;
    volume += det * rule.weights[p];
  }
  return volume;
}

// Every node of a straight-edged element where the linear element of its family puts the node's
// natural point: a node from the wrong edge or face lands elsewhere.
void expect_nodes_at_natural_points(const Model& model, int e, const std::string& linear_type) {
  const Element& element = model.elements[e];
  const TElement& type = *test::shared_builtin_registry().find(element.type);
  const TElement& linear = *test::shared_builtin_registry().find(linear_type);
  const int corners = linear.node_count();
  Eigen::VectorXd N(corners);
  Eigen::MatrixXd dN(corners, 3);
  for (int a = 0; a < type.node_count(); ++a) {
    linear.der(type.natural_nodes()[a], N, dN);
    for (int d = 0; d < 3; ++d) {
      double expected = 0.0;
      for (int c = 0; c < corners; ++c)
        expected += N(c) * model.coords[model.element_nodes(e)[c]][d];
      EXPECT_NEAR(model.coords[model.element_nodes(e)[a]][d], expected, 1e-12)
          << element.type << " element " << element.id << " node " << a + 1 << " axis " << d;
    }
  }
}

std::vector<Id> ids_of(const Model& model, const NodeSet& set) {
  std::vector<Id> ids;
  for (int n : set.nodes) ids.push_back(model.node_ids[n]);
  return ids;
}

TEST(GmshImport, Tet10FromMsh41WithPhysicalGroupsOfEveryDimension) {
  GmshImportSummary summary;
  const Model model = import_gmsh(fixture("tet10_v41.msh"), {}, &summary);
  EXPECT_EQ(summary.format, "4.1");
  EXPECT_EQ(summary.dimension, 3);
  EXPECT_EQ(summary.lower_dimension_elements, 2);  // the point and the 6-node triangle
  ASSERT_EQ(model.element_count(), 1);
  EXPECT_EQ(model.elements[0].type, "C3D10");
  EXPECT_NEAR(element_volume(model, 0), 1.0 / 6.0, 1e-12);
  expect_nodes_at_natural_points(model, 0, "C3D4");
  ASSERT_TRUE(model.find_elset("BODY"));
  EXPECT_EQ(model.find_elset("BODY")->elements.size(), 1u);
  EXPECT_EQ(ids_of(model, *model.find_nset("BASE")), (std::vector<Id>{1, 2, 3, 5, 6, 7}));
  EXPECT_EQ(ids_of(model, *model.find_nset("TIP")), (std::vector<Id>{4}));
  EXPECT_EQ(model.find_nset("BODY")->nodes.size(), 10u);
  EXPECT_EQ(model.find_nset("NALL")->nodes.size(), 10u);
  EXPECT_EQ(model.find_elset("EALL")->elements.size(), 1u);
  EXPECT_FALSE(model.find_elset("BASE"));  // a lower dimension gives a node set only
}

TEST(GmshImport, Hex20FromMsh22MergesTheRepeatsOfAnElementInTwoGroups) {
  GmshImportSummary summary;
  const Model model = import_gmsh(fixture("hex20_v22.msh"), {}, &summary);
  EXPECT_EQ(summary.format, "2.2");
  ASSERT_EQ(model.element_count(), 1);
  EXPECT_EQ(model.elements[0].type, "C3D20");
  EXPECT_NEAR(element_volume(model, 0), 1.0, 1e-12);
  expect_nodes_at_natural_points(model, 0, "C3D8");
  EXPECT_TRUE(model.find_elset("SOLID"));
  EXPECT_TRUE(model.find_elset("PHYSICAL3D_3"));  // an unnamed group
  // "Fixed face": the x = 0 face, its name made a set name.
  const NodeSet* fixed = model.find_nset("FIXED_FACE");
  ASSERT_TRUE(fixed);
  EXPECT_EQ(fixed->nodes.size(), 8u);
  for (int n : fixed->nodes) EXPECT_EQ(model.coords[n][0], 0.0);
}

TEST(GmshImport, Prism15AndHex27FromMsh41) {
  const Model model = import_gmsh(fixture("prism15_hex27_v41.msh"), {});
  ASSERT_EQ(model.element_count(), 2);
  EXPECT_EQ(model.elements[0].type, "C3D15");
  EXPECT_EQ(model.elements[1].type, "C3D27");
  EXPECT_NEAR(element_volume(model, 0), 0.5, 1e-12);
  EXPECT_NEAR(element_volume(model, 1), 1.0, 1e-12);
  expect_nodes_at_natural_points(model, 0, "C3D6");
  expect_nodes_at_natural_points(model, 1, "C3D8");
  EXPECT_EQ(model.find_elset("WEDGE")->elements, std::vector<int>{0});
  EXPECT_EQ(model.find_elset("BRICK")->elements, std::vector<int>{1});
}

TEST(GmshImport, LinearSolidsFromMsh22WithoutPhysicalGroups) {
  const Model model = import_gmsh(fixture("linear_solids_v22.msh"), {});
  ASSERT_EQ(model.element_count(), 3);
  const std::vector<std::string> types{"C3D8", "C3D6", "C3D4"};
  const std::vector<double> volumes{1.0, 0.5, 1.0 / 6.0};
  for (int e = 0; e < 3; ++e) {
    EXPECT_EQ(model.elements[e].type, types[e]);
    EXPECT_NEAR(element_volume(model, e), volumes[e], 1e-12);
  }
  EXPECT_EQ(model.elsets.size(), 1u);  // EALL only
}

TEST(GmshImport, SurfaceMeshNeedsToBeToldWhatItsElementsAre) {
  try {
    import_gmsh(fixture("surface_v41.msh"), {});
    FAIL() << "a surface mesh imported without --planar";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 67);  // the first quadrangle
    EXPECT_NE(std::string(e.what()).find("--planar"), std::string::npos) << e.what();
  }
  GmshImportOptions shells;
  shells.planar = PlanarElements::Shell;
  const Model model = import_gmsh(fixture("surface_v41.msh"), shells);
  std::vector<std::string> types;
  for (const Element& element : model.elements) types.push_back(element.type);
  EXPECT_EQ(types, (std::vector<std::string>{"S4", "S8", "S9", "STRI3"}));
  // Plane stress has no 9-node quadrangle (nor a triangle): refused by name at its line.
  GmshImportOptions plates;
  plates.planar = PlanarElements::PlaneStress;
  try {
    import_gmsh(fixture("surface_v41.msh"), plates);
    FAIL() << "a 9-node quadrangle imported as a plane-stress element";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 71);
    EXPECT_NE(std::string(e.what()).find("9-node quadrangle"), std::string::npos) << e.what();
  }
}

TEST(GmshImport, PyramidIsRefusedByNameAtItsLine) {
  try {
    import_gmsh(fixture("pyramid_v22.msh"), {});
    FAIL() << "a pyramid imported";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 15);
    EXPECT_NE(std::string(e.what()).find("5-node pyramid"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace styk
