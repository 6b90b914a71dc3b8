// The wedges (triangular prisms) C3D6 (linear, 2 points) and C3D15 (quadratic, 9 points), with
// CalculiX's node numbering, faces and integration rules, so a ccx deck runs unchanged.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class C3D6 : public TElement {
 public:
  C3D6();
  std::string name() const override { return "C3D6"; }
  std::string description() const override;
  int node_count() const override { return 6; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  // Full: the triangle's centroid x 2 Gauss points in zeta (CalculiX's); reduced: 1 point.
  IntegrationRule rule(RuleKind kind) const override;
  int face_rule_order() const override { return 2; }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

class C3D15 : public TElement {
 public:
  C3D15();
  std::string name() const override { return "C3D15"; }
  std::string description() const override;
  int node_count() const override { return 15; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  // Full: 3 triangle points x 3 Gauss points in zeta (CalculiX's 9); reduced: 3 x 2.
  IntegrationRule rule(RuleKind kind) const override;
  int face_rule_order() const override { return 3; }
  // VTK's base triangle turns the other way round: corners 1, 3, 2, 4, 6, 5 and their edges.
  VtkCell vtk_cell() const override {
    return {vtk::kQuadraticWedge, {0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13}};
  }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
