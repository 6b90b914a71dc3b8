// Scalar invariants of a symmetric tensor stored as Tensor6 (11, 22, 33, 12, 13, 23), the values
// every consumer derives from stored stresses on the fly (SPEC §5: "stresses ... with Mises").
// The results file stores components only; renderer, report and GUI call these.
#pragma once

#include <array>

#include "styk/core/results.hpp"

namespace styk {

// von Mises equivalent of a stress tensor (tensor shear components):
// sqrt(1/2 [(s11-s22)^2 + (s22-s33)^2 + (s33-s11)^2] + 3 (s12^2 + s13^2 + s23^2)).
double mises(const Tensor6& s);

// Principal values (eigenvalues) of the symmetric tensor, largest first. The tensor must hold
// tensor shear components (stresses, or strains as Styk stores them: eps_12, not gamma_12).
std::array<double, 3> principal_values(const Tensor6& s);

}  // namespace styk
