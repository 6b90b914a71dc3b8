// C3D27: 27-node triquadratic Lagrange hexahedron, full integration 3x3x3 Gauss (reduced 2x2x2).
//
// Node numbering (1-based): corners 1-8 and mid-edge nodes 9-20 as C3D20; face centres 21-26 on
// faces S1..S6 in face order, 21 (0,0,-1), 22 (0,0,+1), 23 (0,-1,0), 24 (+1,0,0), 25 (0,+1,0),
// 26 (-1,0,0); the centre 27 (0,0,0). Each face lists its 9 nodes: 4 corners, 4 mid-edges (as
// C3D20), then the face centre. Complete to degree 2 (and the full biquadratic on each face), so
// it is more accurate than C3D20 per element, and its 9-node faces carry all-positive corner
// loads (1/36, 1/9 and 4/9 of the face load), unlike C3D20's negative corners.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class C3D27 : public TElement {
 public:
  C3D27();

  std::string name() const override { return "C3D27"; }
  // The mesher makes C3D27 from C3D20: face centres and the element centre on the C3D20
  // geometry, a face centre shared by the two elements on the face.
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D20", -1};
  }
  std::string description() const override;
  int node_count() const override { return 27; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;

  IntegrationRule rule(RuleKind kind) const override;
  // On a biquadratic face N_i (x,s x x,t) has degree <= 2 + 1 + 2 = 5 per direction: 3 points.
  int face_rule_order() const override { return 3; }
  // Exported as the quadratic hexahedron of its first 20 nodes (values at the face and body
  // centres stay in the point data).
  VtkCell vtk_cell() const override { return vtk_first_nodes(vtk::kQuadraticHexahedron, 20); }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
