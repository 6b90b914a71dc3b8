// Consistent nodal forces of a uniform traction on a flat box face, for decks that must load a
// face in shear (the *DLOAD pressure labels P1..P6 act only along the normal).
#pragma once

#include <vector>

#include "styk/core/model.hpp"
#include "styk/mesher/box_mesh.hpp"

namespace styk::mesher {

// CLOAD entries (summed per node and dof, non-zero only) for a uniform traction on the face
// axis = side of `box` whose resultant is `total` (force components x, y, z). The per-face nodal
// weights are the integrals of the face shape functions: 1/4 each (4-node face), -1/12 at the
// corners and 1/3 at the mid-edges (8-node face), times the face area.
std::vector<ConcentratedLoad> uniform_traction_loads(const BoxMesh& box, int axis, int side,
                                                     const Vec3& total);

}  // namespace styk::mesher
