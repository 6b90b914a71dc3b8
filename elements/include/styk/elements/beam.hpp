// Shear-flexible (Timoshenko) beams: B31 (2 nodes) and B32 (3 nodes, node 2 in the middle) in
// space, B21 and B22 in the x-y plane, plus CalculiX's B31R and B32R names. Displacements u and
// rotations theta are interpolated independently with the same Lagrange functions (linear,
// quadratic); the section comes from a *BEAM SECTION (styk/core/beam_section.hpp).
//
// Kinematics (linearised Simo-Reissner rod; exact for straight and initially curved axes):
// at a point of the axis with unit tangent t and section axes n1, n2 (t = n1 x n2),
//   axial strain      eps    = t . u'
//   shear strains     gamma2 = n2 . u' + n1 . theta,   gamma1 = n1 . u' - n2 . theta
//   curvatures        kappa1 = n1 . theta',  kappa2 = n2 . theta',  twist phi' = t . theta'
// (' = d/ds along the axis), and the section forces
//   SF1 = E A (eps - alpha dT), SF2 = G A_s2 gamma2, SF3 = G A_s1 gamma1,
//   SM1 = E I11 kappa1, SM2 = E I22 kappa2, SM3 = G J phi'.
// The fibre stress at section point (x1, x2) is S11 = SF1 / A + SM1 x2 / I11 - SM2 x1 / I22 plus
// the torsional shear of the section (BeamSectionProperties::torsion_shear_per_torque).
//
// Integration along the axis (the *BEAM SECTION's INTEGRATION=): reduced (default, Abaqus' rule)
// 1 point for 2-node and 2 points for 3-node elements; full 2 and 3 points, exact for a straight
// element, which locks in shear when the element is slender (SPEC §7.3, Tab 7.1a). B31R and B32R
// are always reduced. All terms use the chosen rule: on a straight element only the shear terms
// differ between the two (the others are integrated exactly by both).
//
// Output points (rule()): per station (Gauss point along the axis) the four extreme fibres of the
// section, station by station, natural coordinates (xi, 0, 0); S and E there are the fibre
// stress and strain tensors in global components. Planar beams (B21, B22) have n1 = (0, 0, -1),
// carry ux, uy and rz and take only in-plane terms (their nodes must share one z).
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"

namespace styk {

enum class BeamType { B21, B22, B31, B31R, B32, B32R };

class Beam : public TElement {
 public:
  explicit Beam(BeamType type);

  std::string name() const override;
  std::string description() const override;
  int node_count() const override { return static_cast<int>(nodes_.size()); }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  // A beam has no faces: no pressures on faces, no contact surfaces.
  const std::vector<FaceDef>& faces() const override { return faces_; }
  int node_dofs() const override { return kMaxNodeDofs; }
  DofSet active_dofs() const override;
  SectionMeasure section_measure() const override { return SectionMeasure::Beam; }
  int distributed_load_labels() const override { return 2; }  // P1, P2
  // B22/B32: VTK's quadratic edge lists its ends before the middle node.
  VtkCell vtk_cell() const override {
    return node_count() == 3 ? VtkCell{vtk::kQuadraticEdge, {0, 2, 1}}
                             : VtkCell{vtk::kLine, {0, 1}};
  }

  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override;
  IntegrationRule rule(RuleKind kind) const override;
  int face_rule_order() const override { return 1; }
  // The length measure |dx/dxi| times the section area, as for a truss (distortion checks).
  double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& /*N*/,
                       const Eigen::Ref<const Eigen::MatrixXd>& dN,
                       Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const override;

  int section_stations(RuleKind kind) const override;
  void section_resultants(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                          const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& forces,
                          Eigen::MatrixXd& moments) const override;

  // The material must be constant and isotropic (prepare_model checks it); its temperatures
  // give the axial thermal strain alpha dT. Beams take no initial stress.
  using TElement::eigenstrain_load;
  using TElement::internal_force;
  using TElement::stiffness;
  using TElement::strains_stresses;
  void stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                 Eigen::MatrixXd& K, const ElementOptions& options = {}) const override;
  void eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                        Eigen::VectorXd& f, const ElementOptions& options = {},
                        const Eigen::MatrixXd* initial_stress = nullptr) const override;
  // P1 / P2: force per length along section axis 1 / 2 (B21, B22: P2 only).
  void pressure_load(const ElementGeometry& g, int face, double p,
                     Eigen::VectorXd& f) const override;
  // GRAV / CENTRIF: density times the section area per unit length, on the translations.
  void body_load(const ElementGeometry& g, double density, RuleKind kind,
                 const BodyAcceleration& acceleration, Eigen::VectorXd& f) const override;
  void strains_stresses(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                        const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& strain,
                        Eigen::MatrixXd& stress, const ElementOptions& options = {},
                        const Eigen::MatrixXd* initial_stress = nullptr) const override;

  bool planar() const { return planar_; }
  // Gauss points along the axis (the stations) of rule `kind`. Virtual so that a variant can
  // integrate otherwise (the tests' deliberately under-integrated beam).
  virtual void stations(RuleKind kind, std::vector<double>& xi, std::vector<double>& weights) const;

 private:
  BeamType type_;
  bool planar_;
  bool reduced_only_;
  std::vector<Vec3> nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace styk
