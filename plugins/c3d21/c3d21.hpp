// C3D21: the thesis' 21-node contact hexahedron = C3D20 + a node at the centre of the bottom face
// S1 (zeta = -1), whose trace becomes the 9-node biquadratic Lagrange face with positive
// equivalent nodal areas 1/9, 4/9, 16/9 (Simpson weights, SPEC section 2.2); the other five faces
// keep the C3D20 traces, so C3D21 conforms with C3D20 on S2-S6. Misprints of the printed N5-N8
// corrected (elements-ref/README.md section 3). Complete quadratic.
// Full integration 3x3x3 Gauss (as in the thesis); reduced 2x2x2 has 9 spurious modes on a single
// element (15 zero eigenvalues, elements-ref section 7).
//
// Node numbering (1-based): 1-20 as C3D20 (Abaqus), 21 = (0, 0, -1).
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk::plugins {

class C3D21 : public TElement {
 public:
  C3D21();

  std::string name() const override { return "C3D21"; }
  std::string description() const override;
  int node_count() const override { return 21; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;

  IntegrationRule rule(RuleKind kind) const override;
  // Face traces have degree <= 2 per direction: as for C3D20, 3 points integrate the pressure
  // integrand N_i (x,s x x,t) exactly on any such face.
  int face_rule_order() const override { return 3; }
  // Exported as the quadratic hexahedron of its C3D20 nodes (the S1 centre stays in the point
  // data); made from a C3D20 layer whose contact face becomes S1.
  VtkCell vtk_cell() const override { return vtk_first_nodes(vtk::kQuadraticHexahedron, 20); }
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D20", 0};
  }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk::plugins
