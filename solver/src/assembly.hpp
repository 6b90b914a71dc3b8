// Assembly of the global stiffness (element matrices from TElement::stiffness scattered into the
// node-graph pattern, in parallel over element colours) and of the external load vector.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "element_states.hpp"
#include "prepared_model.hpp"
#include "step_conditions.hpp"
#include "stiffness_matrix.hpp"

namespace styk::solver_detail {

// Fills `geometry` (coordinates, id, deck line, section, the shells' resolved nodal normals) for
// element e, reusing its storage.
void element_geometry(const Model& model, const PreparedModel& prepared, int e,
                      ElementGeometry& geometry);
// The same without nodal normals, for the scalar-field (heat, electric) analyses, which have no
// shells.
void element_geometry_without_normals(const Model& model, int e, ElementGeometry& geometry);

// Overwrites K's values with the assembled stiffness (full integration) of the elements in the
// material state `states` and marks it pristine. With `owned` (per element) only the elements it
// marks are assembled: a rank's part of a distributed stiffness.
void assemble_stiffness(const Model& model, const PreparedModel& prepared,
                        const ElementStates& states, StiffnessMatrix& K, int threads,
                        const std::vector<char>* owned = nullptr);

// External forces on all active dofs: concentrated loads plus consistent pressure loads.
std::vector<double> assemble_loads(const Model& model, const PreparedModel& prepared,
                                   const StepConditions& conditions);

}  // namespace styk::solver_detail
