// The tetrahedra C3D4 (linear, constant strain, 1 point) and C3D10 (quadratic, 4 points), with
// CalculiX's node numbering, faces and integration rules, so a ccx deck runs unchanged.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class C3D4 : public TElement {
 public:
  C3D4();
  std::string name() const override { return "C3D4"; }
  std::string description() const override;
  int node_count() const override { return 4; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  // One point: the strain is constant, both kinds are the same rule.
  IntegrationRule rule(RuleKind kind) const override;
  // N_i linear on a flat triangle: the 3-point (order 2) face rule is exact.
  int face_rule_order() const override { return 2; }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

class C3D10 : public TElement {
 public:
  C3D10();
  std::string name() const override { return "C3D10"; }
  std::string description() const override;
  int node_count() const override { return 10; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  // Full: the 4-point rule (CalculiX's); reduced: the centroid.
  IntegrationRule rule(RuleKind kind) const override;
  // N_i quadratic times the area vector of a curved (quadratic) face: order 3.
  int face_rule_order() const override { return 3; }
  VtkCell vtk_cell() const override { return vtk_first_nodes(vtk::kQuadraticTetra, 10); }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
