// Exit codes of the `styk` program (DESIGN.md "Files and interfaces").
#pragma once

#include <functional>

namespace styk::cli {

enum ExitCode : int {
  kOk = 0,
  kBadInput = 1,        // InputError: "file:line: message"
  kNotConverged = 2,    // NotConvergedError
  kInternalError = 3,   // anything else: a bug in Styk
  kUnverifiable = 4,    // `styk check`: a results file written before checksums, otherwise sound
  kResourceLimit = 5,   // ResourceLimitError or std::bad_alloc: the model does not fit in memory
  kRunEnvironment = 6,  // a distributed run could not start (no MPI runner) or a rank died
};

// How a failure is told on stderr: one line for people ("file:line: message", "not converged:
// ...") or one JSON line of the progress protocol (json_progress.hpp).
enum class ErrorOutput { Text, JsonLines };

// Runs a command, turning the exception types of Styk into exit codes and one message on stderr.
int run_reporting_errors(const std::function<int()>& command,
                         ErrorOutput output = ErrorOutput::Text);

}  // namespace styk::cli
