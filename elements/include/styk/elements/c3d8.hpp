// C3D8: 8-node trilinear hexahedron. Full integration 2x2x2 Gauss; reduced 1-point (12 spurious
// zero-energy modes without stabilisation: C3D8R adds hourglass control, C3D8I incompatible
// modes). Fully integrated C3D8 locks in bending (shear locking, SPEC section 2.1).
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class C3D8 : public TElement {
 public:
  C3D8();

  std::string name() const override { return "C3D8"; }
  std::string description() const override;
  int node_count() const override { return 8; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;

  IntegrationRule rule(RuleKind kind) const override;
  // N_i (x,s x x,t) has degree <= 2 per direction on a bilinear face: 2 points are exact.
  int face_rule_order() const override { return 2; }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
