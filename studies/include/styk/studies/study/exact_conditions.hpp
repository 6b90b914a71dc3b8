// Boundary conditions taken from an exact solution, so that a refinement series solves exactly
// the problem whose answer is known: the exact displacements prescribed on some faces, the exact
// tractions sigma . n (as consistent nodal forces) applied on others.
#pragma once

#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/mesher/mesh.hpp"
#include "styk/studies/study/exact_solution.hpp"

namespace styk::studies {

// Prescribes u = exact(x) in x, y and z at every node of `faces` (model-level *BOUNDARY), each
// node once. The region of a node is the section of the first face's element holding it.
void prescribe_exact_displacements(Model& model, const ElementRegistry& registry,
                                   const std::vector<mesher::FaceRef>& faces,
                                   const ExactSolution& exact);

// The consistent nodal forces f_a = integral of N_a sigma(x) n dA of the exact traction over
// `faces` (outward normal n), summed per node and direction.
std::vector<ConcentratedLoad> exact_traction_loads(const Model& model,
                                                   const ElementRegistry& registry,
                                                   const std::vector<mesher::FaceRef>& faces,
                                                   const ExactSolution& exact);

}  // namespace styk::studies
