// T3D2: 2-node linear truss (bar) in 3D, axial stiffness only: K = EA/L [t t^T, -t t^T; ...]
// with t the unit bar direction. The cross-section area A is the first data line of the
// *SOLID SECTION (required, as in Abaqus/CalculiX). One integration point (the strain is
// constant). Results in the 6-component convention: S11 = axial stress, E11 = axial strain (both
// along the bar, not along x); the other components are reported as zero.
//
// Kinematics: the strain at a point is the axial derivative t . du/ds. point_measure() returns
// dNdx(a, :) = dN_a/ds t^T, so the axial strain is sum_a dNdx(a, :) u_a, B's first row, and
// D = E in the 11 entry only. A thermal strain alpha dT gives the axial force E A alpha dT.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class T3D2 : public TElement {
 public:
  T3D2();

  std::string name() const override { return "T3D2"; }
  std::string description() const override;
  int node_count() const override { return 2; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  // A truss has no faces: no pressure loads, no contact surfaces.
  const std::vector<FaceDef>& faces() const override { return faces_; }
  SectionMeasure section_measure() const override { return SectionMeasure::Area; }
  ElementForm form() const override { return ElementForm::Line; }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  int face_rule_order() const override { return 1; }

  void bee(const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
           Eigen::Ref<Eigen::MatrixXd> B) const override;
  void dee(const MaterialPoint& material, Matrix6d& D) const override;
  double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                       const Eigen::Ref<const Eigen::MatrixXd>& dN,
                       Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const override;

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
