// The GUI solves by running `styk solve DECK -o DIR --progress json` as a child process (so
// Cancel really stops the solver, which cannot be interrupted inside a phase). This file is the
// protocol: the arguments, and how the JSON lines on its stderr (core/progress_protocol.hpp,
// docs/cli.md "Progress protocol") become progress, log, warnings, errors and the results path.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "styk/core/diagnostics.hpp"

namespace styk::gui {

std::vector<std::string> solve_arguments(const std::string& deck, const std::string& output_dir);

struct SolveLine {
  enum class Kind {
    PhaseBegin,  // {"event":"begin","phase":"assemble"}
    PhaseEnd,    // {"event":"end","phase":"assemble","seconds":0.017}
    Info,        // {"event":"info","message":"pattern: 1863 dofs, ..."}
    Warning,     // {"event":"warning","message":"..."} (locking, hourglassing, distortion)
    Error,       // {"event":"error","exit_code":1,"kind":"input","file":...,"line":12,...}
    Done,        // {"event":"done","results":"DIR/MODEL.styk.h5",...}
    Other,       // anything else: a line that is no event of this protocol version, kept as text
  };
  Kind kind = Kind::Other;
  std::string phase;     // PhaseBegin / PhaseEnd
  double seconds = 0.0;  // PhaseEnd
  std::string text;      // the message (Info, Warning, Error), else the line itself
  SourceLoc where;       // Error: the deck line it points to (line 0: the deck as a whole)
  int exit_code = 0;     // Error
  std::string results;   // Done: the results file
};

SolveLine parse_solve_line(const std::string& line);

// Progress 0..100 when `phase` begins: the solver's phases in the order they run.
int phase_progress(const std::string& phase);

}  // namespace styk::gui
