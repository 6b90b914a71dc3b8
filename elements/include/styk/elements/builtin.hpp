// The element formulations built into Styk. They register through the same ElementRegistry API as
// the plug-ins, so adding a type is a new class plus one line in register_builtin_elements(), or a
// plug-in, never an edit of core/.
#pragma once

#include "styk/core/element_registry.hpp"

namespace styk {

// Registers every built-in element type (C3D8, C3D8R, C3D8R0, C3D8I, C3D20, C3D20R, C3D27, CPS4,
// CPE4, CPS8, CPE8, T3D2, and the beams B21, B22, B31, B31R, B32, B32R) with source "built-in".
// Throws std::invalid_argument if one of the names is already registered.
void register_builtin_elements(ElementRegistry& registry);

}  // namespace styk
