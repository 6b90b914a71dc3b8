// Assembly of blocks into parts: coincident nodes become one.
#pragma once

#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

// Merges nodes closer than relative_tolerance x mesh.size() (bounding-box diagonal) into the
// first of them, with a hash grid (expected O(n)). Elements, node sets and interfaces follow the
// renumbering; node order is otherwise kept. Returns the number of nodes removed.
// Throws std::invalid_argument when a merge would collapse two nodes of one element.
int merge_coincident_nodes(Mesh& mesh, double relative_tolerance = 1e-8);

}  // namespace styk::mesher
