// Plane elements (CPS*: plane stress, CPE*: plane strain) in the x-y plane. What they share,
// whatever their node layout: the kinematics of a plane element in Styk's 3-dof-per-node world.
//
// - Geometry: the 2x2 Jacobian over (xi, eta) from the nodes' x, y (z is ignored); the volume
//   measure is det J2 x thickness, the thickness being the section's first data line
//   (ElementGeometry::cross_section; 1 when absent, as in CalculiX).
// - Strains: B has the rows 11, 22 and 12 only; eps33 = gamma13 = gamma23 = 0 in B, so uz has no
//   stiffness (active_dofs() = ux, uy) and the solver drops it.
// - Plane strain: the 3D D on that B, so S33 = nu (S11 + S22) (- E alpha dT) and E33 = 0.
//   Plane stress: D condensed for sigma33 = 0 (row and column 33 zero), so S33 = 0, and the
//   reported E33 = -nu/(1-nu) (E11 + E22) + (1+nu)/(1-nu) alpha dT (complete_strain()).
// - Faces are the edges P1..P4 (quad_edges()); a pressure acts on edge length x thickness.
#pragma once

#include <array>
#include <string>

#include "styk/core/element.hpp"

namespace styk {

enum class PlaneKind { Stress, Strain };

class PlaneElement : public TElement {
 public:
  explicit PlaneElement(PlaneKind kind) : kind_(kind) {}

  PlaneKind kind() const { return kind_; }

  DofSet active_dofs() const override { return {true, true, false, false, false, false}; }
  SectionMeasure section_measure() const override { return SectionMeasure::Thickness; }
  ElementForm form() const override { return ElementForm::Planar; }

  void bee(const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
           Eigen::Ref<Eigen::MatrixXd> B) const override;
  void dee(const MaterialPoint& material, Matrix6d& D) const override;

  double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                       const Eigen::Ref<const Eigen::MatrixXd>& dN,
                       Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const override;
  void face_quadrature(const ElementGeometry& g, const FaceDef& face, std::vector<Vec3>& points,
                       std::vector<Eigen::Vector3d>& weighted_normals) const override;
  void complete_strain(const MaterialPoint& material,
                       Eigen::Matrix<double, 6, 1>& engineering) const override;

 protected:
  // "CPS" or "CPE": the family prefix of the name.
  std::string prefix() const { return kind_ == PlaneKind::Stress ? "CPS" : "CPE"; }
  std::string kind_words() const {
    return kind_ == PlaneKind::Stress ? "plane stress" : "plane strain";
  }

 private:
  PlaneKind kind_;
};

}  // namespace styk
