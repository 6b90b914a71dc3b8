// The linear coarse space of a mesh of quadratic solids (C3D20, C3D20R, C3D27, C3D10, C3D15 and
// plug-ins with the same corners): the corner nodes of the elements, and for every other node
// the weights of the element's linear parent (trilinear brick, linear tetrahedron or wedge) at its
// natural point, so u_fine = P u_corners interpolates a linear field exactly. It is the first
// coarse level of the serial CG + GAMG solver (p-multigrid): GAMG then aggregates the corners'
// operator P^T K P, an 8-node-like stencil with a quarter of the nodes and a sixth of the
// non-zeros, instead of the quadratic matrix.
#pragma once

#include <optional>
#include <vector>

#include "prepared_model.hpp"
#include "styk/core/model.hpp"

namespace styk::solver_detail {

struct LinearCoarseSpace {
  int coarse_nodes = 0;
  std::vector<int> corner_node;  // coarse node -> active node
  // Per active node a, its weights on coarse nodes: entries ptr[a] .. ptr[a + 1] of (node, w).
  std::vector<int> ptr;
  std::vector<int> node;
  std::vector<double> weight;
};

// The coarse space, or nothing when the mesh has no quadratic solid, or has an element that is
// not a 3D solid with 8, 6 or 4 corners (beams, shells, planar elements: they keep plain GAMG).
std::optional<LinearCoarseSpace> linear_coarse_space(const Model& model,
                                                     const PreparedModel& prepared);

}  // namespace styk::solver_detail
