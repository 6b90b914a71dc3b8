// The static solve the mesher's calibrating builders receive (mesher::StaticSolve): the studies
// layer is where building meets solving, so this is where the two are joined.
#pragma once

#include "styk/core/element_registry.hpp"
#include "styk/mesher/builders.hpp"

namespace styk::studies {

// A StaticSolve running every step of the model with the default solve options (the registry must
// outlive it). Solver errors propagate as thrown by run_static_analysis.
mesher::StaticSolve static_solve(const ElementRegistry& registry);

}  // namespace styk::studies
