// The solve that the builder dialog hands to a calibrating builder (mesher::StaticSolve, e.g. the
// bolted flange's preload): the window does not link the solver, so it runs `styk solve` on the
// model as a child process and reads its results file back. Synchronous (a builder waits for its
// calibration); the caller shows a busy cursor.
#pragma once

#include <QString>

#include "styk/mesher/builders.hpp"

namespace styk::gui {

// A StaticSolve running `styk_program solve` in a temporary directory. A failed solve throws
// InputError with the solver's first error line (or its exit status when it printed none).
mesher::StaticSolve child_process_solve(QString styk_program);

}  // namespace styk::gui
