// Element conversion (issue "Mesher"; elements describe themselves, issue 15 item 9): a mesh of
// one type becomes another as the target type's TElement describes it (TElement::conversion(),
// element_description.hpp), so the thesis' contact hexahedra and any plug-in type convert without
// a table of type names here. Converted elements keep their index; new nodes are appended (shared
// between neighbours), nodes no element uses any more are removed, so node indices change: build
// node sets after converting.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

// Converts elements of the base type of `type` (its TElement::conversion()) to `type`:
// - a type with a contact face (C3D21, C3D28: S1): every element with a face on `surface` becomes
//   `type` with that face as its contact face. The element is renumbered by a proper rotation of
//   the reference cube (its Jacobian keeps its sign) and every surface naming it follows. When a
//   face of `type` other than the contact face carries nodes the base type's face does not
//   (C3D28's side faces), the layer is closed: a base element sharing such a face joins it with
//   the free face whose converted nodes meet the layer's, and is added to `surface`. The surface
//   then lists the contact faces of all converted elements.
// - a type without one (C3D14, C3D20R): the listed `elements`, or every element of the base type
//   when the list is empty, convert as they are.
// Nodes of `type` at natural points of base nodes reuse those nodes; the others are placed on the
// base element's geometry (its shape functions) and shared by neighbours that reach the same
// point through the same edge or face (two bodies split at an interface keep separate nodes).
// Returns the converted elements. Throws std::invalid_argument naming the problem: a type that
// is not registered or describes no conversion, a missing surface, an element of another type,
// an element with two faces on the surface, a layer that cannot be closed.
std::vector<int> convert_elements(Mesh& mesh, const ElementRegistry& registry,
                                  const std::string& type, const std::string& surface = "",
                                  const std::vector<int>& elements = {});

// The registered types that convert from `base` (their conversion() names it), alphabetical.
std::vector<std::string> conversions_from(const ElementRegistry& registry, const std::string& base);

// Whether `type` converts a layer towards a surface (it has a contact face) rather than whole
// elements; false for a type without a conversion.
bool converts_a_layer(const ElementRegistry& registry, const std::string& type);

}  // namespace styk::mesher
