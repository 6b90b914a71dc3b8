// Interface generation: split a part into two bodies along the faces between an element set and
// the rest, with coincident node pairs (the thesis' zero-thickness interface, SPEC §3.2).
#pragma once

#include <string>

#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

// Elements of element set `body_a` keep their nodes; every node they share with the other
// elements gets a coincident copy used by the other elements. Records the pairs (a node, b node)
// and the two facing surfaces NAME_A (faces of body A) and NAME_B in mesh.surfaces, and appends
// the Interface to mesh.interfaces. Throws std::invalid_argument when the set is missing, empty,
// the whole mesh, or touches the rest at no face.
const Interface& split_interface(Mesh& mesh, const std::string& body_a, const std::string& name);

}  // namespace styk::mesher
