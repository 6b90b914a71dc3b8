// Reissner-Mindlin shells of the degenerated (curved) type: S4, S4R (4 nodes), S8, S8R
// (8-node serendipity) and S9, S9R (9-node Lagrange; S9 and S9R are Styk's names, CalculiX has no
// 9-node shell). The section is a *SHELL SECTION (thickness t, optional OFFSET, section points).
//
// Geometry: x(xi, eta, zeta) = sum N_a(xi, eta) [X_a + z(zeta) V_a], z = t (zeta / 2 - offset),
// with V_a the unit nodal normal: ElementGeometry::nodal_normals when the model resolved them
// (averaged over the elements sharing the node, or given by *NORMAL: shell_normals.hpp), else the
// normal of the element's own mid-surface interpolation at node a. Displacements: u = sum N_a [u_a
// + z(zeta) theta_a x V_a] with the nodal translations u_a and small global rotations theta_a (dofs
// 1-6). Strains: the covariant components of the 3D field, turned into the lamina axes (e1, e2 in
// the surface, e3 normal; e1 is the projection of the global x axis, or of z when x is within 0.1
// degree of the normal, as in Abaqus), with sigma33 = 0 and the transverse shear factor 5/6.
//
// Integration in the surface: S8, S9 3x3 Gauss; S8R, S9R 2x2 (the reduced rule); RuleKind::
// Reduced of S8 / S9 is the 2x2 rule too (diagnostics, SPEC §7.3 Tab 7.1b). S4 and S4R both use
// 2x2 Gauss with the assumed transverse shear strains of Bathe and Dvorkin (MITC4: the covariant
// shear strains tied at the edge midpoints), which removes shear locking without hourglass modes;
// S4R is accepted as the CalculiX/Abaqus name of the same element (no one-point rule).
// Through the thickness: Simpson's rule with the section's point count (default 5, odd).
//
// Drilling rotations (theta . e3) carry no displacement; a penalty ties them to the in-plane
// rotation of the membrane, alpha G t (theta . e3 - (du2/dx1 - du1/dx2) / 2)^2 integrated with
// the full in-plane rule (alpha = 1e-3). It vanishes on rigid motions and on the patch tests'
// states, so flat and curved shells keep exactly their six rigid modes.
//
// Output points (rule()): per surface Gauss point the bottom (zeta = -1), middle and top fibre,
// in that order; S and E there are global tensor components (sigma33 = 0 in the lamina axes).
// Section forces per surface point (section_resultants): SF = (N11, N22, N12, Q13, Q23) (Abaqus'
// SF1-SF5 for shells: membrane forces, then the transverse shear forces, integrals of sigma13 and
// sigma23 over the thickness; the results keep SF1-SF3 only) and SM = (M11, M22, M12) per unit
// length in the lamina axes,
// M = integral of sigma z dz with z along e3 from the mid-surface.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

enum class ShellType { S4, S4R, S8, S8R, S9, S9R };

class Shell : public TElement {
 public:
  explicit Shell(ShellType type);

  std::string name() const override;
  std::string description() const override;
  int node_count() const override { return static_cast<int>(nodes_.size()); }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  // A shell's only distributed load is its pressure (*DLOAD label P = face 1); it has no faces
  // for contact surfaces.
  const std::vector<FaceDef>& faces() const override { return faces_; }
  int distributed_load_labels() const override { return 1; }
  int node_dofs() const override { return kMaxNodeDofs; }
  DofSet active_dofs() const override { return {true, true, true, true, true, true}; }
  SectionMeasure section_measure() const override { return SectionMeasure::Shell; }
  ElementForm form() const override { return ElementForm::Shell; }
  // Its reference surface; S9's centre node stays in the point data.
  VtkCell vtk_cell() const override {
    return node_count() == 4 ? vtk_first_nodes(vtk::kQuad, 4)
                             : vtk_first_nodes(vtk::kQuadraticQuad, 8);
  }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  int face_rule_order() const override { return 3; }
  // Mid-surface area measure |g1 x g2| times the thickness; dNdx the surface gradient.
  double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& /*N*/,
                       const Eigen::Ref<const Eigen::MatrixXd>& dN,
                       Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const override;

  int section_stations(RuleKind kind) const override;
  void section_resultants(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                          const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& forces,
                          Eigen::MatrixXd& moments) const override;

  using TElement::eigenstrain_load;
  using TElement::internal_force;
  using TElement::stiffness;
  using TElement::strains_stresses;
  void stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                 Eigen::MatrixXd& K, const ElementOptions& options = {}) const override;
  // Shells take no temperature change and no initial stress (refused naming the element).
  void eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                        Eigen::VectorXd& f, const ElementOptions& options = {},
                        const Eigen::MatrixXd* initial_stress = nullptr) const override;
  // P (face 0): pressure on the reference surface, a positive value pushing along the shell
  // normal (g1 x g2, the node order's right-hand normal), as CalculiX applies its shells' P.
  void pressure_load(const ElementGeometry& g, int face, double p,
                     Eigen::VectorXd& f) const override;
  // GRAV / CENTRIF: density times thickness per unit area, on the translations.
  void body_load(const ElementGeometry& g, double density, RuleKind kind,
                 const BodyAcceleration& acceleration, Eigen::VectorXd& f) const override;
  void strains_stresses(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                        const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& strain,
                        Eigen::MatrixXd& stress, const ElementOptions& options = {},
                        const Eigen::MatrixXd* initial_stress = nullptr) const override;

  // Surface Gauss points per direction of rule `kind` (stiffness and output).
  int surface_order(RuleKind kind) const;
  // Whether the transverse shear strains are the assumed (MITC4) ones.
  bool assumed_shear() const { return node_count() == 4; }

 private:
  ShellType type_;
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
