// The GUI solves by running `styk solve DECK -o DIR` as a child process (so Cancel really stops
// the solver, which cannot be interrupted inside a phase). This file is the protocol: the
// arguments, and how its stderr progress lines, error lines and stdout summary are read.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "styk/core/diagnostics.hpp"

namespace styk::gui {

std::vector<std::string> solve_arguments(const std::string& deck, const std::string& output_dir);

struct SolveLine {
  enum class Kind {
    PhaseBegin,  // "styk: assemble ..."
    PhaseEnd,    // "styk: assemble done in 0.017 s"
    Info,        // "styk:   pattern: 1863 dofs, ..."
    Warning,     // "styk:   warning: ..." (locking, hourglassing, distortion; text without it)
    Error,       // "deck.inp:12: message", "not converged: ...", "internal error: ..."
    Other,
  };
  Kind kind = Kind::Other;
  std::string phase;       // PhaseBegin / PhaseEnd
  double seconds = 0.0;    // PhaseEnd
  std::string text;        // the line without the "styk:" prefix
  SourceLoc where;         // Error: the deck line it points to (line 0 when none)
};

SolveLine parse_solve_line(const std::string& line);

// Progress 0..100 when `phase` begins: the solver's phases in the order they run.
int phase_progress(const std::string& phase);

// "results: PATH" of the summary on stdout; empty when absent.
std::string results_path_from_summary(const std::string& stdout_text);

}  // namespace styk::gui
