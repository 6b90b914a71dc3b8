// Consistent pressure loads and equivalent nodal areas (SPEC section 2.2, eq. 2.9) of the
// plug-in elements on the reference cube: elements-ref/README.md section 6.
#include <gtest/gtest.h>

#include "plugin_fixtures.hpp"

namespace styk {
namespace {

using test::reference_geometry;

class FaceLoads : public test::PluginElementTest {};

// A_i of a node on S1 (bottom) or S2 (top) per elements-ref section 6 (unit pressure, face area
// 4), by node role (1-based node numbers of section 1).
double expected_area(const std::string& element, int face, int one_based) {
  const bool corner = one_based <= 8;
  if (element == "C3D14") return corner ? 5.0 / 9.0 : 16.0 / 9.0;
  if (face == 1) return corner ? -1.0 / 3.0 : 4.0 / 3.0;  // C3D21/C3D28 top = C3D20 face
  if (element == "C3D21") return corner ? 1.0 / 9.0 : (one_based == 21 ? 16.0 / 9.0 : 4.0 / 9.0);
  if (corner) return 1.0 / 36.0;  // C3D28 bottom: GLL weight products
  return one_based <= 24 ? 5.0 / 36.0 : 25.0 / 36.0;
}

// elements-ref section 6: bottom and top A_i exact (C3D14 5/9, 16/9; C3D21 bottom 1/9, 4/9,
// 16/9, top -1/3, 4/3; C3D28 bottom 1/36, 5/36, 25/36, top -1/3, 4/3); zero off the face; the
// pressure load is f_i = -p A_i n_outward. Tolerance 1e-14.
TEST_P(FaceLoads, BottomAndTopFacesOfReferenceCube) {
  const TElement& e = element();
  const ElementGeometry g = reference_geometry(e);
  const double p = 2.5;
  for (int face : {0, 1}) {
    const FaceDef& fd = e.faces()[face];
    Eigen::VectorXd area, f;
    e.nodal_areas(g, face, area);
    e.pressure_load(g, face, p, f);
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(e.node_count());
    for (int node : fd.nodes) expected(node) = expected_area(e.name(), face, node + 1);
    for (int i = 0; i < e.node_count(); ++i) {
      EXPECT_NEAR(area(i), expected(i), 1e-14) << e.name() << " S" << face + 1 << " node " << i + 1;
      EXPECT_NEAR(f(3 * i), 0.0, 1e-14);
      EXPECT_NEAR(f(3 * i + 1), 0.0, 1e-14);
      EXPECT_NEAR(f(3 * i + 2), -p * expected(i) * fd.value, 1e-14)
          << e.name() << " S" << face + 1 << " node " << i + 1;
    }
    EXPECT_NEAR(area.sum(), 4.0, 1e-14);
  }
}

// The "physical contact condition" (SPEC section 2.2): every node of the contact face has a
// positive equivalent area, also on a distorted element (C3D14: every face; C3D21/C3D28: S1).
TEST_P(FaceLoads, ContactFacesHavePositiveNodalAreasWhenDistorted) {
  const TElement& e = element();
  const ElementGeometry g = test::distorted_geometry(e, 23, 0.05);
  const int faces = e.name() == "C3D14" ? 6 : 1;
  for (int face = 0; face < faces; ++face) {
    Eigen::VectorXd area;
    e.nodal_areas(g, face, area);
    for (int node : e.faces()[face].nodes)
      EXPECT_GT(area(node), 0.0) << e.name() << " S" << face + 1 << " node " << node + 1;
  }
}

// Side faces S3..S6 of C3D21 keep the C3D20 trace (elements-ref section 3): corners -1/3,
// mid-edges 4/3, node 21 zero; every face of every element sums to 4. Tolerance 1e-14.
TEST_P(FaceLoads, SideFacesSumToFaceArea) {
  const TElement& e = element();
  const ElementGeometry g = reference_geometry(e);
  for (int face = 2; face < 6; ++face) {
    Eigen::VectorXd area;
    e.nodal_areas(g, face, area);
    EXPECT_NEAR(area.sum(), 4.0, 1e-14) << e.name() << " S" << face + 1;
    for (int node : e.faces()[face].nodes) {
      if (e.name() == "C3D21") {
        EXPECT_NEAR(area(node), node < 8 ? -1.0 / 3.0 : 4.0 / 3.0, 1e-14);
      }
      if (e.name() == "C3D14") {
        EXPECT_NEAR(area(node), node < 8 ? 5.0 / 9.0 : 16.0 / 9.0, 1e-14);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ContactHexahedra, FaceLoads,
                         ::testing::ValuesIn(test::contact_hexahedra()), test::element_name);

}  // namespace
}  // namespace styk
