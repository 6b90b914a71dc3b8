// Consistent pressure loads and equivalent nodal areas (SPEC eq. 2.9) of C3D8 and C3D20 faces.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "element_fixtures.hpp"
#include "styk/elements/c3d20.hpp"
#include "styk/elements/c3d8.hpp"

namespace styk {
namespace {

using test::distorted_geometry;
using test::reference_geometry;

Eigen::Vector3d outward_normal(const FaceDef& face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  n(face.axis) = face.value;
  return n;
}

// elements-ref/README.md section 6: A_i for unit pressure on a reference-cube face (area 4):
// C3D8 corners 1; C3D20 corners -1/3, mid-edges 4/3. Exact values, tolerance 1e-14.
double expected_area(const TElement& e, int local) {
  if (e.node_count() == 8) return 1.0;
  return local < 8 ? -1.0 / 3.0 : 4.0 / 3.0;
}

TEST(HexFaceLoads, ReferenceCubeConsistentLoadsAndNodalAreas) {
  C3D8 c3d8;
  C3D20 c3d20;
  const double p = 2.5;
  for (const TElement* e :
       {static_cast<const TElement*>(&c3d8), static_cast<const TElement*>(&c3d20)}) {
    const ElementGeometry g = reference_geometry(*e);
    for (int face = 0; face < 6; ++face) {
      const FaceDef& fd = e->faces()[face];
      const Eigen::Vector3d n = outward_normal(fd);
      Eigen::VectorXd f, area;
      e->pressure_load(g, face, p, f);
      e->nodal_areas(g, face, area);
      ASSERT_EQ(f.size(), 3 * e->node_count());
      ASSERT_EQ(area.size(), e->node_count());
      Eigen::VectorXd expected = Eigen::VectorXd::Zero(e->node_count());
      for (int node : fd.nodes) expected(node) = expected_area(*e, node);
      for (int i = 0; i < e->node_count(); ++i) {
        EXPECT_NEAR(area(i), expected(i), 1e-14)
            << e->name() << " S" << face + 1 << " node " << i + 1;
        // Positive pressure pushes into the element: f_i = -p A_i n_outward.
        const Eigen::Vector3d fi = f.segment<3>(3 * i);
        EXPECT_LT((fi + p * expected(i) * n).cwiseAbs().maxCoeff(), 1e-14)
            << e->name() << " S" << face + 1 << " node " << i + 1;
      }
      EXPECT_NEAR(area.sum(), 4.0, 1e-14);
    }
  }
}

// Vector area of the face's boundary curve, 1/2 closed-integral of x cross dx, in the order of
// the face node list (corner k, mid-edge k, corner k+1). Edges are straight (C3D8) or quadratic
// (C3D20); the integrand is then of degree <= 3, exact with 2 Gauss points. By Stokes' theorem it
// equals integral n dA over any surface spanned by the curve, an independent check of the face
// quadrature. Abaqus lists turn the normal into the element, so this is the inward vector area.
Eigen::Vector3d boundary_vector_area(const TElement& e, const ElementGeometry& g, int face) {
  const std::vector<int>& nodes = e.faces()[face].nodes;
  const bool quadratic = nodes.size() == 8;
  const double gp = 1.0 / std::sqrt(3.0);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d a = g.X.row(nodes[k]), b = g.X.row(nodes[(k + 1) % 4]);
    const Eigen::Vector3d m =
        quadratic ? Eigen::Vector3d(g.X.row(nodes[4 + k])) : Eigen::Vector3d(0.5 * (a + b));
    for (double s : {-gp, gp}) {
      const Eigen::Vector3d x = 0.5 * s * (s - 1) * a + (1 - s * s) * m + 0.5 * s * (s + 1) * b;
      const Eigen::Vector3d dx = (s - 0.5) * a - 2 * s * m + (s + 0.5) * b;
      total += 0.5 * x.cross(dx);  // Gauss weight 1
    }
  }
  return total;
}

// Brief: on a distorted (non-planar, curved for C3D20) face the consistent loads sum to
// p * (vector area) pushing inward; compared with the boundary integral to 1e-12.
TEST(HexFaceLoads, SumOnDistortedFaceEqualsPressureTimesVectorArea) {
  C3D8 c3d8;
  C3D20 c3d20;
  const double p = -1.7;  // suction works the same way
  for (const TElement* e :
       {static_cast<const TElement*>(&c3d8), static_cast<const TElement*>(&c3d20)}) {
    for (unsigned seed : {4u, 5u}) {
      const ElementGeometry g = distorted_geometry(*e, seed, 0.2);
      for (int face = 0; face < 6; ++face) {
        Eigen::VectorXd f;
        e->pressure_load(g, face, p, f);
        Eigen::Vector3d total = Eigen::Vector3d::Zero();
        for (int i = 0; i < e->node_count(); ++i) total += f.segment<3>(3 * i);
        const Eigen::Vector3d expected = p * boundary_vector_area(*e, g, face);
        EXPECT_LT((total - expected).cwiseAbs().maxCoeff(), 1e-12)
            << e->name() << " seed " << seed << " S" << face + 1;
      }
    }
  }
}

// A planar but distorted face (S1 kept on z = -1, in-plane shape random): the nodal areas sum to
// the face area |vector area| (the integrand |n| is then polynomial, so the rule is exact), to
// 1e-12, and the loads of a positive pressure all point in +z (into the element) for C3D8.
TEST(HexFaceLoads, NodalAreasSumToAreaOfPlanarDistortedFace) {
  C3D8 c3d8;
  C3D20 c3d20;
  for (const TElement* e :
       {static_cast<const TElement*>(&c3d8), static_cast<const TElement*>(&c3d20)}) {
    ElementGeometry g = distorted_geometry(*e, 8, 0.2);
    for (int node : e->faces()[0].nodes) g.X(node, 2) = -1.0;
    Eigen::VectorXd area, f;
    e->nodal_areas(g, 0, area);
    EXPECT_NEAR(area.sum(), boundary_vector_area(*e, g, 0).norm(), 1e-12) << e->name();
    e->pressure_load(g, 0, 1.0, f);
    for (int i = 0; i < e->node_count(); ++i) {
      EXPECT_NEAR(f(3 * i + 2), area(i), 1e-12) << e->name();  // planar: f_i = A_i * (+z)
      EXPECT_NEAR(f(3 * i), 0.0, 1e-14);
      EXPECT_NEAR(f(3 * i + 1), 0.0, 1e-14);
    }
  }
}

TEST(HexFaceLoads, UnknownFaceIsAnInputError) {
  C3D8 e;
  const ElementGeometry g = reference_geometry(e, 3);
  Eigen::VectorXd f;
  EXPECT_THROW(e.pressure_load(g, 6, 1.0, f), InputError);
  EXPECT_THROW(e.nodal_areas(g, -1, f), InputError);
}

}  // namespace
}  // namespace styk
