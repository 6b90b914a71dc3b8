// Element conversion (issue "Mesher"): the thesis' contact hexahedra from ordinary meshes.
// Node layouts follow elements-ref/README.md. Converted elements keep their index; new nodes are
// appended (shared between neighbours), nodes no element uses any more are removed, so node
// indices change: build node sets after converting.
#pragma once

#include <string>
#include <vector>

#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

// C3D8 -> C3D14: a node at the centre of every face (shared by the two elements on it).
// `elements` empty = every C3D8 of the mesh. Throws std::invalid_argument for a non-C3D8.
void convert_to_c3d14(Mesh& mesh, const std::vector<int>& elements = {});

// C3D20 -> C3D20R (reduced integration): a change of name only.
void convert_to_c3d20r(Mesh& mesh, const std::vector<int>& elements = {});

// C3D20 -> C3D27 (triquadratic Lagrange): a node at the centre of every face (shared by the two
// elements on it, in face order S1..S6) and one at the element centre, all placed on the C3D20
// geometry, so curved faces stay curved. `elements` empty = every C3D20 of the mesh. Throws
// std::invalid_argument for a non-C3D20.
void convert_to_c3d27(Mesh& mesh, const std::vector<int>& elements = {});

// Every C3D20 with a face on `surface` becomes C3D21 with that face as its S1 (zeta = -1): the
// element is renumbered (a proper rotation of the reference cube, so the Jacobian keeps its sign)
// and gets the face-centre node on the C3D20 geometry. The surface (and every other surface
// naming these elements) is updated to the new face numbers. Throws std::invalid_argument for a
// missing surface, a non-C3D20 element or an element with two faces on the surface.
void convert_layer_to_c3d21(Mesh& mesh, const std::string& surface);

// As convert_layer_to_c3d21, to C3D28: the face's mid-edge nodes are replaced by the GLL nodes at
// +-1/sqrt(5) and four interior face nodes are added, all on the C3D20 geometry. A C3D28 side face
// conforms only with a C3D28 whose bottom edge is the same (elements-ref section 4), so the
// layer is closed: a C3D20 sharing a side face with the layer joins it with its free face along
// the shared bottom edge (and is added to the surface). Returns the elements converted; throws
// std::invalid_argument naming the element when the layer cannot be closed.
std::vector<int> convert_layer_to_c3d28(Mesh& mesh, const std::string& surface);

}  // namespace styk::mesher
