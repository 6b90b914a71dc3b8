// The plane quadrilaterals CPS4/CPE4 (bilinear, full 2x2 Gauss), CPS8/CPE8 (8-node serendipity,
// full 3x3 Gauss; the reduced rules are 1 and 2x2) and CPS8R/CPE8R (8-node, 2x2 Gauss: the name
// fixes the reduced rule, as in CalculiX). Plane stress or plane strain by constructor; the
// kinematics are PlaneElement's.
#pragma once

#include <string>
#include <vector>

#include "styk/elements/plane_element.hpp"

namespace styk {

class PlaneQuad4 : public PlaneElement {
 public:
  explicit PlaneQuad4(PlaneKind kind);

  std::string name() const override { return prefix() + "4"; }
  std::string description() const override;
  int node_count() const override { return 4; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return edges_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  // N_i |x,s| on a straight edge: linear, 2 points are exact.
  int face_rule_order() const override { return 2; }

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> edges_;
};

class PlaneQuad8 : public PlaneElement {
 public:
  explicit PlaneQuad8(PlaneKind kind, bool reduced = false);

  std::string name() const override { return prefix() + (reduced_ ? "8R" : "8"); }
  std::string description() const override;
  int node_count() const override { return 8; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return edges_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  // N_i (quadratic) times the area vector (linear on a curved edge): cubic, 2 points are exact.
  int face_rule_order() const override { return 2; }
  VtkCell vtk_cell() const override { return vtk_first_nodes(vtk::kQuadraticQuad, 8); }

 private:
  bool reduced_;
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> edges_;
};

}  // namespace styk
