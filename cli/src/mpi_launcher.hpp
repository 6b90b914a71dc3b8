// `styk solve --ranks N`: starts the MPI runner (mpirun, or the program STYK_MPIRUN names) with N
// copies of this program solving the same deck, waits for it, and turns a failed start or a dead
// rank into one clear message, removing any half-written results.
#pragma once

#include "commands.hpp"

namespace styk::cli {

int launch_ranks(const SolveArgs& args);

}  // namespace styk::cli
