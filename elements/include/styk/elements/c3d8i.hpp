// C3D8I: 8-node linear hexahedron with incompatible modes (Wilson et al. 1973, with the Taylor
// et al. 1976 correction), full 2x2x2 integration.
//
// Nine internal parameters a add the bubble displacements (1 - xi^2, 1 - eta^2, 1 - zeta^2) to each
// displacement component, which lets the element bend without parasitic shear (no shear locking,
// SPEC section 2.1). Their strain operator G uses the Jacobian at the element centre J0 and the
// factor det J0 / det J (Taylor's correction), so that the integral of G over the element is zero
// and the element passes the patch test also when distorted. The modes are condensed statically
// inside the element (TElement's incompatible-mode hook), and stresses are recovered with them.
#pragma once

#include <string>

#include "styk/elements/c3d8.hpp"

namespace styk {

class C3D8I : public C3D8 {
 public:
  std::string name() const override { return "C3D8I"; }
  // The mesher renames C3D8 elements as they are (the same nodes, another formulation).
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D8", -1};
  }
  std::string description() const override;
  int incompatible_mode_count() const override { return 9; }
  void incompatible_bee(const ElementGeometry& g, const Vec3& xi, double detJ,
                        Eigen::Ref<Eigen::MatrixXd> G) const override;
};

}  // namespace styk
