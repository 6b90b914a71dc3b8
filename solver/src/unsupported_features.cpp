#include "unsupported_features.hpp"

namespace styk::solver_detail {

void reject_unsupported_features(const Model& /*model*/) {
  // Both paths now apply *EQUATION, *TRANSFORM and step temperatures (model_constraints.hpp,
  // thermal_load.hpp; the contact driver since the shrink-fit and sector models). Nothing is
  // refused here at the moment; the hook stays for the next feature the contact path lacks.
}

}  // namespace styk::solver_detail
