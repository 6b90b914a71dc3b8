// C3D20R: the 20-node serendipity hexahedron integrated with 2x2x2 Gauss points (reduced).
// Cheaper than C3D20 and free of the mild locking of the 27-point rule in bending; a single element
// has 6 spurious zero-energy modes (12 zero eigenvalues, elements-ref section 7), which do not
// propagate in a mesh of two or more elements in each direction.
#pragma once

#include <string>

#include "styk/elements/c3d20.hpp"

namespace styk {

class C3D20R : public C3D20 {
 public:
  std::string name() const override { return "C3D20R"; }
  std::string description() const override;
  // The element's rule is 2x2x2 for both kinds (the name fixes it).
  IntegrationRule rule(RuleKind kind) const override;
  // The mesher renames C3D20 elements to C3D20R as they are.
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D20", -1};
  }
};

}  // namespace styk
