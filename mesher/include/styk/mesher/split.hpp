// Brick meshes split into tetrahedra or wedges, so that every element family has refinement series
// on the same geometry (issue 15 item 3). The bricks are the mesher's C3D8/C3D20; the target
// type's layout (corners, mid-edge nodes, faces) comes from its own TElement in the registry.
//
// Conformity: every cut brick face is cut by a rule that depends on the face alone, so both
// bricks sharing it cut it alike and neighbouring pieces meet face to face: the diagonal through
// the corner of smallest node index for tetrahedra, the diagonal closer to a fixed direction in
// space for wedges (so the two cut faces of a brick get parallel diagonals whatever the node
// numbering).
// - Tetrahedra: a brick whose two opposite faces are cut along parallel diagonals (always the case
//   in a structured block) is cut through them into two wedges and each wedge into 3 tetrahedra
//   (6 per brick); any other brick gets a node at its centre and 12 tetrahedra, two on each face.
// - Wedges: each brick is cut along the diagonals of its two faces normal to `axis` (0 = xi,
//   1 = eta, 2 = zeta) into 2 wedges whose triangles lie in those faces; the two diagonals must be
//   parallel (std::invalid_argument naming the brick otherwise).
// Nodes a piece has beyond its corners (C3D10, C3D15: mid-edge nodes) reuse the brick's mid-edge
// node on a brick edge and are otherwise placed on a C3D20 brick's geometry (its shape functions),
// or for a C3D8 brick (no curved geometry) at the midpoint of the edge's corners, and are shared
// by every piece on that edge. Element sets list the pieces in place of their brick;
// surfaces list the piece faces lying in the brick faces they named. Element indices change
// (pieces replace their brick in order); node indices only grow.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

// Splits the C3D8/C3D20 bricks `bricks` (empty: every brick of the mesh) into tetrahedra of
// `type` (a registered type with 4 corners, e.g. C3D4 or C3D10). Returns how many bricks needed a
// centre node (12 pieces). std::invalid_argument for a listed element that is no brick.
int split_to_tetrahedra(Mesh& mesh, const ElementRegistry& registry, const std::string& type,
                        const std::vector<int>& bricks = {});

// Splits the bricks `bricks` (empty: every brick) into 2 wedges of `type` (6 corners, e.g. C3D6
// or C3D15) whose axis is the bricks' natural `axis`.
void split_to_wedges(Mesh& mesh, const ElementRegistry& registry, const std::string& type,
                     int axis = 2, const std::vector<int>& bricks = {});

}  // namespace styk::mesher
