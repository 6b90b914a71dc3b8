// Axisymmetric ring elements CAX4, CAX4R, CAX8, CAX8R (CalculiX conventions): the element is the
// section of a ring in the r-z plane, with r = x and z = y (x >= 0), revolved about the y axis.
//
// - Strains: B has the rows 11 = e_rr (du_r/dr), 22 = e_zz (du_z/dz), 33 = e_hoop (u_r / r) and
//   12 = g_rz; 13 and 23 stay 0, uz has no stiffness (active_dofs() = ux, uy).
// - Everything is integrated over the whole ring: dV = 2 pi r dA and a pressure acts on
//   2 pi r ds, so nodal forces, concentrated loads and reactions are totals around the
//   circumference, as in CalculiX (a *CLOAD of F on a node is F spread over its circle; checked
//   against ccx, which expands the element into a 2 degree segment and scales back).
// - The section needs no data line (no thickness); D is the 3D law (33 = hoop).
// - Faces are the edges P1..P4 as for plane elements.
// - CAX4R: one point and a Flanagan-Belytschko-type hourglass stiffness on ur and uz (the 2D
//   counterpart of C3D8R's, kappa = 0.005), which vanishes on every affine field.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class AxisymmetricElement : public TElement {
 public:
  ElementForm form() const override { return ElementForm::Axisymmetric; }
  DofSet active_dofs() const override { return {true, true, false, false, false, false}; }

  double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                       const Eigen::Ref<const Eigen::MatrixXd>& dN,
                       Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const override;
  void strain_operator(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                       const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
                       Eigen::Ref<Eigen::MatrixXd> B) const override;
  void face_quadrature(const ElementGeometry& g, const FaceDef& face, std::vector<Vec3>& points,
                       std::vector<Eigen::Vector3d>& weighted_normals) const override;
};

// CAX4 (2x2 Gauss) and CAX4R (1 point + hourglass control).
class CAX4 : public AxisymmetricElement {
 public:
  explicit CAX4(bool reduced);
  std::string name() const override { return reduced_ ? "CAX4R" : "CAX4"; }
  std::string description() const override;
  int node_count() const override { return 4; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return edges_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  // N_i linear times the radius (linear) along a straight edge: 2 points are exact.
  int face_rule_order() const override { return 2; }
  void add_stabilisation(const ElementGeometry& g, const Matrix6d& D, const ElementOptions& options,
                         Eigen::MatrixXd& K) const override;

 private:
  bool reduced_;
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> edges_;
};

// CAX8 (3x3 Gauss) and CAX8R (2x2).
class CAX8 : public AxisymmetricElement {
 public:
  explicit CAX8(bool reduced);
  std::string name() const override { return reduced_ ? "CAX8R" : "CAX8"; }
  std::string description() const override;
  int node_count() const override { return 8; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return edges_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  // N_i quadratic x radius quadratic x edge length linear on a curved edge: 3 points.
  int face_rule_order() const override { return 3; }
  VtkCell vtk_cell() const override { return vtk_first_nodes(vtk::kQuadraticQuad, 8); }

 private:
  bool reduced_;
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> edges_;
};

}  // namespace styk
