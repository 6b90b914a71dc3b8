// Test doubles for the element registry: the reader needs only an element type's name and node
// count, so these fakes keep the reader tests independent of the element library.
#pragma once

#include "styk/core/element_registry.hpp"

namespace styk::test {

// A registry holding fake C3D8 (8 nodes) and C3D20 (20 nodes) types, fake 2-node beams B21,
// B31 and B31R (reduced only) and a fake 4-node shell S4.
ElementRegistry fake_registry();
// fake_registry() plus a fake six-node wedge C3D6 with five faces (S1..S5).
ElementRegistry fake_registry_with_wedge();

}  // namespace styk::test
