// `styk solve --progress json`: the progress, warnings, errors and the final summary as JSON
// lines on stderr (core/progress_protocol.hpp, docs/cli.md "Progress protocol"), for programs
// that drive the solver (the desktop program) instead of prose meant for people.
#pragma once

#include <string>

#include "styk/solver/analysis.hpp"

namespace styk::cli {

class JsonLinesProgress : public ProgressSink {
 public:
  void begin(const std::string& phase) override;
  void end(const std::string& phase, double seconds) override;
  void info(const std::string& message) override;
  void warning(const std::string& message) override;
};

// The line of a failed run: the exit code, its kind (input, not_converged, internal,
// resource_limit), the deck location when there is one (line 0: the file as a whole) and the
// message without the location.
std::string json_error_line(int exit_code, const std::string& kind, const std::string& file,
                            int line, const std::string& message);

// The last line of a successful solve: where the results and the report went, DOFs, the linear
// solver and the number of steps.
std::string json_done_line(const std::string& results, const std::string& report, long long dofs,
                           const std::string& linear_solver, int steps);

}  // namespace styk::cli
