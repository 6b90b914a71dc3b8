// Mortar rows (docs/contact.md "Mortar contact"): the dual basis of slave faces (Wohlmuth 2000:
// biorthogonal to the shape functions), the segment integration against a shifted master face
// checked against the hand integral, and which pairs are paired by mortar: TYPE=MORTAR always
// (refused where the dual basis does not exist), SURFACE TO SURFACE where it exists, node to
// surface otherwise (logged).
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "mortar_constraints.hpp"
#include "styk/contact/constraints.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/face_param.hpp"
#include "styk/core/model.hpp"
#include "support/element_registries.hpp"

namespace styk::contact {
namespace {

// The element of `type` with its nodes at lo + (xi + 1) / 2 * size (a box), or bent onto a
// cylinder when `bend` (xi -> angle over 22.5°, eta -> z, zeta -> radius 1.5 ... 2).
PlacedFace box_face(const ElementRegistry& registry, const std::string& type, int face, bool bend) {
  PlacedFace f;
  f.element = registry.find(type);
  EXPECT_NE(f.element, nullptr) << type;
  f.face = face;
  const std::vector<Vec3>& xi = f.element->natural_nodes();
  f.geometry.X.resize(static_cast<int>(xi.size()), 3);
  for (std::size_t k = 0; k < xi.size(); ++k) {
    Eigen::Vector3d x(0.5 * (xi[k][0] + 1.0), 0.5 * (xi[k][1] + 1.0), 0.5 * (xi[k][2] + 1.0));
    if (bend) {
      const double theta = 0.3 + x[0] * 3.14159265358979323846 / 8.0, r = 1.5 + 0.5 * x[2];
      x = Eigen::Vector3d(r * std::cos(theta), r * std::sin(theta), x[1]);
    }
    f.geometry.X.row(k) = x.transpose();
  }
  f.geometry.id = 7;
  return f;
}

MortarFace mortar_face(PlacedFace placed) {
  MortarFace f;
  f.placed = std::move(placed);
  f.local = f.placed.element->faces()[f.placed.face].nodes;
  f.nodes = f.local;
  return f;
}

// integral phi_a N_b dA = delta_ab D_a, checked with a 5 x 5 rule (the basis is built with 6 x 6):
// to 1e-12 on a flat bilinear face and a linear triangle (both rules exact there), to 1e-7 on the
// curved faces of a cylinder sector (S2 of C3D8 and of C3D27, 9 nodes), whose area element is not
// polynomial (the two rules differ by 3.1e-8 on the C3D27 face); and sum_a D_a is the face area.
TEST(MortarDualBasis, IsBiorthogonalToTheShapeFunctions) {
  const ElementRegistry registry = test::builtin_registry();
  struct Case {
    const char* type;
    int face;
    bool bend;
  };
  for (const Case c : {Case{"C3D8", 0, false}, Case{"C3D27", 1, true}, Case{"C3D8", 1, true},
                       Case{"C3D4", 0, false}}) {
    SCOPED_TRACE(std::string(c.type) + " S" + std::to_string(c.face + 1));
    const MortarFace f = mortar_face(box_face(registry, c.type, c.face, c.bend));
    ASSERT_TRUE(admits_dual_basis(f));
    const DualBasis dual = dual_basis(f, {});
    const FaceDef& def = f.placed.element->faces()[f.placed.face];
    const bool triangle = def.axis < 0 && FaceParam(*f.placed.element, def).triangle();
    const FaceRule rule = face_rule(triangle, 5);
    const int n = static_cast<int>(f.local.size());
    Eigen::MatrixXd product = Eigen::MatrixXd::Zero(n, n);
    double area = 0.0;
    for (std::size_t g = 0; g < rule.points.size(); ++g) {
      Eigen::Vector3d x, xp, xq;
      face_map(f.placed, rule.points[g][0], rule.points[g][1], x, xp, xq);
      const double dA = rule.weights[g] * xp.cross(xq).norm();
      const Eigen::VectorXd N = face_shape_values(f, rule.points[g][0], rule.points[g][1]);
      product += dA * (dual.coefficients * N) * N.transpose();
      area += dA;
    }
    const double scale = dual.nodal_integrals.maxCoeff();
    const double tolerance = c.bend ? 1e-7 : 1e-12;
    const double error =
        (product - Eigen::MatrixXd(dual.nodal_integrals.asDiagonal())).norm() / scale;
    EXPECT_LT(error, tolerance);
    EXPECT_NEAR(dual.nodal_integrals.sum(), area, tolerance * area);
    ::testing::Test::RecordProperty(
        std::string("biorthogonality_") + c.type + (c.bend ? "_curved" : "_flat"),
        std::to_string(error * 1e9) + "e-9");
  }
}

// The 8-node serendipity face has corner integrals -A/12: no dual basis on N itself (refused, with
// the element named); the transformed basis (Popp et al. 2012, corner share 1/5) has integrals A/20
// at the corners and A/5 at the mid-edge nodes (the unit face: 1/20 and 1/5, to 1e-14) and is
// biorthogonal to its dual basis like any other.
TEST(MortarDualBasis, SerendipityFaceNeedsTheTransformedBasis) {
  const ElementRegistry registry = test::builtin_registry();
  MortarFace f = mortar_face(box_face(registry, "C3D20", 0, false));
  EXPECT_FALSE(admits_dual_basis(f));
  try {
    dual_basis(f, {"deck.inp", 12});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face S1 of slave element 7 has a node whose integral of "
                                         "N dA is not positive"),
              std::string::npos)
        << e.what();
  }
  f.basis = slave_basis_transform(f);
  ASSERT_TRUE(admits_dual_basis(f));
  const DualBasis dual = dual_basis(f, {});
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(dual.nodal_integrals[a], a < 4 ? 0.05 : 0.2, 1e-14);
  // Each mid-edge node shares 1/5 with the two corners of its edge and keeps 3/5.
  for (int m = 4; m < 8; ++m) {
    EXPECT_NEAR(f.basis(m, m), 0.6, 1e-15);
    EXPECT_NEAR(f.basis.col(m).sum(), 1.0, 1e-15);
  }
}

// A slave cube [0,1]^2 x [1.1, 2.1] (type `slave_type`) above a C3D8 master
// [0.25, 1.25] x [0, 1] x [0, 1]: a gap of 0.1, the master shifted by a quarter in x.
Model shifted_pair(const ElementRegistry& registry, const std::string& slave_type,
                   ContactPair::Type type) {
  Model model;
  model.source = "shifted.inp";
  auto hex = [&](Id first_id, Id element_id, const std::string& element_type,
                 const Eigen::Vector3d& lo) {
    std::vector<int> nodes;
    const std::vector<Vec3>& xi = registry.find(element_type)->natural_nodes();
    for (std::size_t k = 0; k < xi.size(); ++k)
      nodes.push_back(
          model.add_node(first_id + static_cast<Id>(k),
                         {lo[0] + 0.5 * (xi[k][0] + 1.0), lo[1] + 0.5 * (xi[k][1] + 1.0),
                          lo[2] + 0.5 * (xi[k][2] + 1.0)},
                         {}));
    return model.add_element(element_id, element_type, nodes, {});
  };
  const int master = hex(1, 1, "C3D8", {0.25, 0.0, 0.0});
  const int slave = hex(101, 2, slave_type, {0.0, 0.0, 1.1});
  // The top face of the master and the bottom face of the slave (S2 and S1 of the bricks).
  Surface top{"MASTER_TOP", Surface::Kind::ElementFaces, {{master, 2}}, {}, {}};
  Surface bottom{"SLAVE_BOTTOM", Surface::Kind::ElementFaces, {{slave, 1}}, {}, {}};
  model.surfaces[top.name] = top;
  model.surfaces[bottom.name] = bottom;
  SurfaceInteraction smooth;
  smooth.name = "SMOOTH";
  model.surface_interactions["SMOOTH"] = smooth;
  ContactPair pair;
  pair.slave = bottom.name;
  pair.master = top.name;
  pair.interaction = "SMOOTH";
  pair.type = type;
  pair.where = {"shifted.inp", 40};
  model.contact_pairs.push_back(pair);
  return model;
}

// The bilinear slave face's dual functions are products of phi_1(x) = 2 - 3x, phi_2(x) = 3x - 1
// (and the same in y). The master covers x in [0.25, 1]:
// - the slave nodes at x = 0: integral of phi_1 over the cover 0.09375 of D-share 0.5, less than
//   half: not constrained (the note of node-to-surface);
// - the slave nodes at x = 1: M against the master's x = 0.25 node = integral_{1/4}^{1}
//   (3x - 1)(1.25 - x) dx = 0.3046875, against its x = 1.25 node 0.3515625: weights 13/28 and
//   15/28 (node-to-surface: 1/4 and 3/4), y matching; area 1/4, gap0 0.1, normal -z.
void expect_mortar_weights(const std::vector<ContactConstraint>& constraints, const Model& model) {
  ASSERT_EQ(constraints.size(), 2u);
  for (const ContactConstraint& c : constraints) {
    const Vec3& xs = model.coords[c.slave];
    EXPECT_EQ(xs[0], 1.0);
    EXPECT_FALSE(c.node_to_node);
    EXPECT_NEAR(c.gap0, 0.1, 1e-14);
    EXPECT_LT((c.normal + Eigen::Vector3d::UnitZ()).norm(), 1e-15);
    EXPECT_NEAR(c.area, 0.25, 1e-15);
    ASSERT_EQ(c.master.size(), 2u);
    for (const MasterTerm& t : c.master) {
      const Vec3& xm = model.coords[t.node];
      EXPECT_EQ(xm[1], xs[1]);
      EXPECT_NEAR(t.weight, xm[0] == 0.25 ? 13.0 / 28.0 : 15.0 / 28.0, 1e-14);
    }
  }
}

TEST(MortarPairing, ShiftedFacesGetTheIntegratedWeights) {
  const ElementRegistry registry = test::builtin_registry();
  for (const ContactPair::Type type :
       {ContactPair::Type::Mortar, ContactPair::Type::SurfaceToSurface}) {
    const Model model = shifted_pair(registry, "C3D8", type);
    std::vector<std::string> notes;
    expect_mortar_weights(build_contact_constraints(model, registry, &notes), model);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0],
              "contact pair SLAVE_BOTTOM/MASTER_TOP: 2 slave nodes lie beyond the master surface "
              "and are not constrained");
  }
}

// A C3D20 slave (transformed basis): the corner nodes' rows are ordinary (area D^ = 1/20 of the
// unit face); a mid-edge node's row couples the two corners of its edge as slave-side terms
// (weights 1/5 each), the master weights add up to 3/5, and its area is integral N dA = 1/3, so
// force / area is the multiplier's pressure; the row is 3/5 of the node's gap (gap_scale, gap0
// 0.06 for the gap 0.1). SURFACE TO SURFACE gives the same rows.
TEST(MortarPairing, SerendipitySlaveRowsCoupleTheEdgeCorners) {
  const ElementRegistry registry = test::builtin_registry();
  for (const ContactPair::Type type :
       {ContactPair::Type::Mortar, ContactPair::Type::SurfaceToSurface}) {
    const Model model = shifted_pair(registry, "C3D20", type);
    std::vector<std::string> notes;
    const std::vector<ContactConstraint> constraints =
        build_contact_constraints(model, registry, &notes);
    ASSERT_FALSE(constraints.empty());
    int mid_rows = 0;
    for (const ContactConstraint& c : constraints) {
      double slave_side = 0.0, master = 0.0;
      int corners = 0;
      for (const MasterTerm& t : c.master) {
        if (t.slave_side) {
          EXPECT_NEAR(t.weight, 0.2, 1e-15);
          ++corners;
          slave_side += t.weight;
        } else {
          master += t.weight;
        }
      }
      const bool mid = corners > 0;
      mid_rows += mid ? 1 : 0;
      EXPECT_EQ(corners, mid ? 2 : 0);
      EXPECT_NEAR(master, mid ? 0.6 : 1.0, 1e-14);
      EXPECT_NEAR(c.area, mid ? 1.0 / 3.0 : 0.05, 1e-14);
      EXPECT_NEAR(c.gap_scale, mid ? 0.6 : 1.0, 1e-15);
      EXPECT_NEAR(c.gap0, 0.1 * c.gap_scale, 1e-14);
    }
    EXPECT_GT(mid_rows, 0);
  }
}

// SURFACE TO SURFACE on a node slave surface (the deck reader refuses it; a model built in code
// may have it) is paired node to surface, and the log says why.
TEST(MortarPairing, SurfaceToSurfaceWithoutSlaveFacesIsPairedNodeToSurface) {
  const ElementRegistry registry = test::builtin_registry();
  Model model = shifted_pair(registry, "C3D8", ContactPair::Type::SurfaceToSurface);
  Surface nodes{"SLAVE_NODES", Surface::Kind::Nodes, {}, {}, {}};
  for (int n = 8; n < 12; ++n) nodes.nodes.push_back(n);  // the slave cube's bottom corners
  model.surfaces[nodes.name] = nodes;
  model.contact_pairs[0].slave = nodes.name;
  std::vector<std::string> notes;
  build_contact_constraints(model, registry, &notes);
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes[0],
            "contact pair SLAVE_NODES/MASTER_TOP: TYPE=SURFACE TO SURFACE is paired node to "
            "surface (the slave surface is a node surface)");
}

}  // namespace
}  // namespace styk::contact
