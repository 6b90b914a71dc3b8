// The element types a mesh block or a revolve is meshed with: the mesher's bricks (C3D20, C3D8)
// and every registered type that converts from one of them (TElement::conversion(): C3D21, C3D28
// on a contact layer, C3D14 and C3D20R whole), so a plug-in's type is offered and converted like a
// built-in one, with no list of type names here.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::gui {

// C3D20, C3D8, then the types converting from them, alphabetical.
std::vector<std::string> brick_types(const ElementRegistry& registry);
// The list as words for messages: "C3D20, C3D8, C3D14, C3D20R, C3D21 or C3D28".
std::string brick_type_list(const ElementRegistry& registry);
// The brick (C3D8 or C3D20) a type is meshed with before it is converted.
std::string brick_of(const ElementRegistry& registry, const std::string& type);
// Whether the type converts the layer of one side (it has a contact face), so a side is needed.
bool needs_layer_side(const ElementRegistry& registry, const std::string& type);
// Converts a brick mesh to `type` (nothing for a brick itself): the layer of `layer_surface`, or
// every element. std::invalid_argument from the mesher when it cannot.
void convert_bricks(mesher::Mesh& mesh, const ElementRegistry& registry, const std::string& type,
                    const std::string& layer_surface);

}  // namespace styk::gui
