// A small contact model solved through the solver for the contact render tests: a block pressed
// onto a slab and pushed sideways, so its contact surface shows all three states (open where the
// overturning moment lifts the trailing edge, slip near the edges, stick inside).
#pragma once

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::render_test {

// SLAB: C3D8 8 x 8 x 2 over [0,4] x [0,4] x [-1,0], bottom held. BLOCK: C3D8 4 x 4 x 4 over
// [1,3] x [1,3] x [0,2] (matching the slab's nodes at z = 0), held only by the contact:
// *CONTACT PAIR BLOCK_BOTTOM (slave) on SLAB_TOP, Coulomb mu = 0.3. E = 1000, nu = 0.3 both.
// Load: pressure 1 on the block's top and a total force of 1 in +x spread over its top nodes.
Model contact_block_model();

// Solves it (run_static_analysis) and returns the last increment.
IncrementResult solve_contact_block(const Model& model, const ElementRegistry& registry);

// SPEC §3.2.2: two concentric cylinders (Lamé), plane strain, quarter model, built by the mesher's
// `cylinders` builder with C3D21 contact layers (96 elements); analytic contact pressure 3.294.
Model cylinders_model(const ElementRegistry& registry);
// Solves a model (run_static_analysis) and returns its last increment.
IncrementResult solve_model(const Model& model, const ElementRegistry& registry);

}  // namespace styk::render_test
