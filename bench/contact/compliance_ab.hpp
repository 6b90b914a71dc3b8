// Same-process timing of the contact compliance's two substitution paths (compliance_ab.cpp).
#pragma once

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::bench {

// Prints "name,dofs,columns,dense_s,restricted_1thread_s,restricted_2threads_s,speed-up 1,
// speed-up 2,max relative difference of S".
void compliance_ab(const char* name, const Model& model, const ElementRegistry& registry);

}  // namespace styk::bench
