// Derived results that output requests ask for beyond displacements, stresses and strains: the
// energies and thermal strains (*EL PRINT ENER, ELSE, EVOL; *EL FILE ENER, THE), the stress error
// estimate (*EL FILE ERR, or S without NOE) and the section forces (*SECTION PRINT).
//
// The error estimate ERR of element e is the energy norm of the difference between the nodal
// averaged stress field (SPEC §5 method I, interpolated with the element's shape functions) and
// the element's own stresses, relative to the mean element energy norm of the solution
// (Zienkiewicz-Zhu):
//   e_e^2 = integral over e of (s* - s)^T C (s* - s) dV,  U_e^2 = integral of s^T C s dV,
//   ERR_e = 100 e_e / sqrt((sum U^2 + sum e^2) / N)      [%]
// with C the compliance of the element's 3D law at the point. Where the mesh resolves the stress,
// the averaged and the element fields agree and ERR is small; large values mark elements to
// refine.
#pragma once

#include "element_states.hpp"
#include "prepared_model.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

struct OutputNeeds {
  bool energies = false;         // ENER, ELSE, EVOL
  bool thermal_strains = false;  // THE
  bool error_estimate = false;   // ERR
};

// What the requests in effect in step `step` (0-based) need.
OutputNeeds output_needs(const Model& model, std::size_t step);

// Fills out.ERR from out.S and out.S_nodal_I (which must be filled).
void estimate_stress_errors(const Model& model, const PreparedModel& prepared,
                            const ElementStates& states, int threads, IncrementResult& out);

// Fills out.sections for the *SECTION PRINT requests in effect in step `step` from
// out.S_nodal_I (which must be filled).
void compute_section_forces(const Model& model, const PreparedModel& prepared, std::size_t step,
                            IncrementResult& out);

}  // namespace styk::solver_detail
