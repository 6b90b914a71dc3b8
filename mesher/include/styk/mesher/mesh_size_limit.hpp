// The check a mesher runs before it allocates a block: a model indexes its nodes and elements with
// int and gives them 32-bit ids (docs/input.md "Ids"), and a block that needs more memory than the
// machine has would otherwise grow until the system kills the program. Both are refused at once,
// with the counts and what to do instead.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace styk::mesher {

// Throws ResourceLimitError when `nodes` or `elements` (grid points and elements of the block
// `what` describes, e.g. "the 2000000000 x 2 x 1 C3D8 block") exceed 2147483647, or when building
// them needs more than the machine's memory (about 100 bytes a node and 64 + 4 per element node
// for an element: coordinates, ids, index maps and connectivity).
void check_mesh_fits(std::uint64_t nodes, std::uint64_t elements, int nodes_per_element,
                     const std::string& what);

// check_mesh_fits for a structured block of divisions[0] x [1] x [2] hexahedra of `type` with
// `step` grid intervals along an element side (1: C3D8, 2: C3D20), before anything is allocated.
void check_block_fits(const std::array<int, 3>& divisions, int step, const std::string& type);

}  // namespace styk::mesher
