// C3D14: the thesis' 14-node contact hexahedron (8 corners + 6 face centres), with the two
// misprints of the printed formulas corrected (elements-ref/README.md section 2).
//
// Every face carries a 5-node trace (bilinear + face bubble) whose equivalent nodal areas are all
// positive (corners 5/9, centre 16/9 on a 2x2 face: the "physical contact condition", SPEC
// section 2.2), so any face can be a contact face. Linearly but not quadratically complete.
// Full integration 3x3x3 Gauss; the 2x2x2 reduced rule is already stable (6 zero eigenvalues on a
// single element, elements-ref section 7).
//
// Node numbering (1-based, natural coordinates): 1-8 corners as C3D8; 9 (0,0,-1) on S1,
// 10 (0,0,+1) on S2, 11 (0,-1,0) on S3, 12 (0,+1,0) on S5, 13 (-1,0,0) on S6, 14 (+1,0,0) on S4
// (11-14 are not in Abaqus face order; they follow the thesis).
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk::plugins {

class C3D14 : public TElement {
 public:
  C3D14();

  std::string name() const override { return "C3D14"; }
  std::string description() const override;
  int node_count() const override { return 14; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;

  IntegrationRule rule(RuleKind kind) const override;
  // A face trace has degree <= 2 per direction; with a curved (C3D14-shaped) face the pressure
  // integrand N_i (x,s x x,t) reaches degree 5, which 3 Gauss points integrate exactly.
  int face_rule_order() const override { return 3; }
  // Made from C3D8 meshes: every brick gains its six face centres (shared between neighbours).
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D8", -1};
  }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk::plugins
