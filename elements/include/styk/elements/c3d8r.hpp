// C3D8R: 8-node linear hexahedron, reduced integration (1 point) with Flanagan-Belytschko
// stiffness hourglass control.
//
// The one point uses the uniform (mean) gradient operator of Flanagan-Belytschko,
// B_bar = (1/V) integral of dN/dx dV, weighted with the exact volume V (both from a 2x2x2 rule,
// exact for the trilinear map), instead of dN/dx at the centre: on a hexahedron that is not a
// parallelepiped only B_bar makes the element pass the patch test (SPEC section 3.1.8).
//
// One Gauss point leaves 12 zero-energy (hourglass) modes on a single element (elements-ref
// section 7). The control adds K_hg = c * sum_alpha gamma_alpha gamma_alpha^T (on each of the
// three displacement components), with the Flanagan-Belytschko (1981) hourglass vectors
//   gamma_alpha = h_alpha - B_bar (X^T h_alpha),   h = (xi eta, eta zeta, zeta xi, xi eta zeta)
// evaluated at the nodes, which are orthogonal to every affine nodal field (so rigid motions and
// the patch test are untouched), and the FB stiffness scaling
//   c = kappa * (lambda + 2 mu) * (b : b) / (8 V),   b = V B_bar,  kappa = 0.005 (kDefault).
// `C3D8R0` is the same element without control (kappa = 0), registered only to show the
// hourglassing of SPEC section 2.1 ("method fails"); never use it for real work.
#pragma once

#include <string>

#include "styk/elements/c3d8.hpp"

namespace styk {

class C3D8R : public C3D8 {
 public:
  static constexpr double kDefaultHourglassStiffness = 0.005;

  // hourglass_stiffness = kappa above; 0 gives the uncontrolled C3D8R0.
  explicit C3D8R(double hourglass_stiffness = kDefaultHourglassStiffness);

  std::string name() const override { return kappa_ > 0.0 ? "C3D8R" : "C3D8R0"; }
  // The mesher renames C3D8 elements as they are (the same nodes, another formulation).
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D8", -1};
  }
  std::string description() const override;
  // The element's rule is the 1-point rule for both kinds (the name fixes it).
  IntegrationRule rule(RuleKind kind) const override;
  void add_stabilisation(const ElementGeometry& g, const Matrix6d& D, const ElementOptions& options,
                         Eigen::MatrixXd& K) const override;
  // The uniform gradient B_bar as dNdx and V/8 as the measure of the single point (weight 8).
  double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                       const Eigen::Ref<const Eigen::MatrixXd>& dN,
                       Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const override;

 private:
  // V and B_bar = (1/V) integral of dN/dx dV over the element; checks every Jacobian.
  double uniform_gradient(const ElementGeometry& g, Eigen::Ref<Eigen::MatrixXd> b_bar) const;

  double kappa_;
};

}  // namespace styk
