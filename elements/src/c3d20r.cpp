#include "styk/elements/c3d20r.hpp"

namespace styk {

std::string C3D20R::description() const {
  return "20-node quadratic (serendipity) hexahedron, reduced integration (2x2x2 Gauss)";
}

IntegrationRule C3D20R::rule(RuleKind) const { return gauss_rule(2, 2, 2); }

}  // namespace styk
