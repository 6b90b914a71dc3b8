// C3D20: 20-node serendipity hexahedron (Abaqus node numbering). Full integration 3x3x3 Gauss;
// reduced 2x2x2 (the C3D20R rule; 6 spurious modes on a single element, elements-ref section 7).
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class C3D20 : public TElement {
 public:
  C3D20();

  std::string name() const override { return "C3D20"; }
  std::string description() const override;
  int node_count() const override { return 20; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;

  IntegrationRule rule(RuleKind kind) const override;
  // On any 20-node face the pressure integrand N_i (x,s x x,t) has degree <= 5 per direction,
  // so 3 Gauss points integrate consistent pressure loads exactly.
  int face_rule_order() const override { return 3; }
  VtkCell vtk_cell() const override { return vtk_first_nodes(vtk::kQuadraticHexahedron, 20); }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
