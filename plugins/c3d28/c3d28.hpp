// C3D28: the thesis' 28-node contact hexahedron. Its bottom face S1 (zeta = -1) is the bicubic
// 16-node Lagrange face on the 4x4 Gauss-Lobatto-Legendre grid (equivalent nodal areas 1/36,
// 5/36, 25/36: products of the GLL weights, all positive, SPEC section 2.2); the top face S2 is
// the 8-node serendipity face of C3D20, so a C3D28 layer couples to C3D20 through its top.
// The shape functions are not printed in the thesis: they are derived in elements-ref/README.md
// section 4 (minimal space P28 = S20 + (1 - zeta) Q3(xi, eta), no interior bubble). Quadratically
// complete. Side faces conform only with another C3D28 (4 nodes on the bottom edge).
//
// Integration: full 4x4x3 Gauss (the B^T B integrand has degree 6, 6, 4); the 3x3x3 rule of
// C3D20/C3D21 must NOT be used as the full rule: it leaves 4 spurious zero-energy modes on a
// single element (10 zero eigenvalues). It is offered as the reduced rule for completeness.
//
// Node numbering (1-based; a = 1/sqrt(5)): 1-8 corners as C3D20; 9-12 vertical mid-edges
// (-1,-1,0) (1,-1,0) (1,1,0) (-1,1,0); 13-16 top mid-edges as C3D20; bottom (zeta = -1) edge
// nodes 17 (-a,-1) 18 (a,-1) 19 (1,-a) 20 (1,a) 21 (a,1) 22 (-a,1) 23 (-1,a) 24 (-1,-a) and
// interior nodes 25 (-a,-a) 26 (a,-a) 27 (a,a) 28 (-a,a).
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk::plugins {

class C3D28 : public TElement {
 public:
  C3D28();

  std::string name() const override { return "C3D28"; }
  std::string description() const override;
  int node_count() const override { return 28; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;

  IntegrationRule rule(RuleKind kind) const override;
  // Traces are cubic in the in-plane directions of S1 and the side faces: 4 points per direction
  // integrate the pressure integrand on such (possibly curved) faces to high accuracy and exactly
  // on flat ones.
  int face_rule_order() const override { return 4; }
  // Made from a C3D20 layer whose contact face becomes S1 (its side faces conform only with
  // another C3D28, so the mesher closes the layer; elements-ref section 4).
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D20", 0};
  }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk::plugins
