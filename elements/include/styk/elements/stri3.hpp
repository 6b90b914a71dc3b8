// STRI3: the flat 3-node thin (Kirchhoff) shell triangle of discrete-Kirchhoff type, Abaqus' name
// for its 3-node discrete-Kirchhoff thin shell. Bending: the DKT plate of Batoz, Bathe and Ho
// (1980): the rotations of the normal are quadratic, and the Kirchhoff constraint (no transverse
// shear) is imposed at the corners and along the sides, so the element has no shear strain and
// cannot lock however thin; it is meant for thin plates and shells (span / thickness above about
// 20), where it converges to the Kirchhoff solution. Membrane: the constant-strain triangle.
// Section: a *SHELL SECTION (thickness, OFFSET); the section points only place the output fibres.
// Drilling rotations: the penalty of the degenerated shells (shell.hpp), alpha G t (theta . e3 -
// in-plane rotation)^2, alpha = 1e-3, so the element keeps exactly its six rigid motions.
//
// The element is flat: its plane is that of its corners, its lamina axes (e1 the projection of
// global x, or of z when x is within 0.1 degree of the normal; e3 = (x2 - x1) x (x3 - x1)
// normalised) are the shells'. Six dofs per node (translations and global rotations).
// Integration: 3 points in the triangle (1/6, 1/6), (2/3, 1/6), (1/6, 2/3), exact for its
// stiffness; RuleKind::Reduced is the same rule (the name fixes it).
// Output points (rule()): per surface point the bottom, middle and top fibre, as the shells; the
// transverse shear stresses there are zero (Kirchhoff). Section forces per surface point: SF =
// (N11, N22, N12, Q13, Q23; the results keep the first three) and SM = (M11, M22, M12) per unit
// length in the lamina axes, M about the mid-surface; the transverse shear forces follow from the
// moments' equilibrium, Q13 = M11,1 + M12,2 and Q23 = M12,1 + M22,2 (constant over the element: the
// moments are linear).
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

class Stri3 : public TElement {
 public:
  Stri3();

  std::string name() const override { return "STRI3"; }
  std::string description() const override;
  int node_count() const override { return 3; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  int distributed_load_labels() const override { return 1; }
  int node_dofs() const override { return kMaxNodeDofs; }
  DofSet active_dofs() const override { return {true, true, true, true, true, true}; }
  SectionMeasure section_measure() const override { return SectionMeasure::Shell; }
  ElementForm form() const override { return ElementForm::Shell; }
  VtkCell vtk_cell() const override { return vtk_first_nodes(vtk::kTriangle, 3); }

  // Linear functions of the natural triangle xi, eta >= 0, xi + eta <= 1.
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  int face_rule_order() const override { return 2; }
  double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                       const Eigen::Ref<const Eigen::MatrixXd>& dN,
                       Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const override;

  int section_stations(RuleKind) const override { return 3; }
  void section_resultants(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                          const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& forces,
                          Eigen::MatrixXd& moments) const override;

  using TElement::eigenstrain_load;
  using TElement::internal_force;
  using TElement::stiffness;
  using TElement::strains_stresses;
  void stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                 Eigen::MatrixXd& K, const ElementOptions& options = {}) const override;
  // No temperature change and no initial stress (refused naming the element), as the shells.
  void eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                        Eigen::VectorXd& f, const ElementOptions& options = {},
                        const Eigen::MatrixXd* initial_stress = nullptr) const override;
  // P (face 0): a positive pressure pushes along (x2 - x1) x (x3 - x1), as on the shells; a
  // third of the force at each corner (translations only).
  void pressure_load(const ElementGeometry& g, int face, double p,
                     Eigen::VectorXd& f) const override;
  void body_load(const ElementGeometry& g, double density, RuleKind kind,
                 const BodyAcceleration& acceleration, Eigen::VectorXd& f) const override;
  void strains_stresses(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                        const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& strain,
                        Eigen::MatrixXd& stress, const ElementOptions& options = {},
                        const Eigen::MatrixXd* initial_stress = nullptr) const override;

 private:
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
