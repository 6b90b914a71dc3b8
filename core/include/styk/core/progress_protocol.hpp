// The machine-readable progress of `styk solve --progress json` (docs/cli.md "Progress
// protocol"): one JSON object per line on stderr, each carrying the protocol version under
// kVersionKey and an "event" (begin, end, info, warning, error, done). The writer is the command
// line (cli/src/json_progress.cpp), the reader the desktop program's solve runner
// (gui/app/session/solve_protocol.cpp); a reader ignores lines of another version.
#pragma once

namespace styk::progress_protocol {

constexpr int kVersion = 1;
constexpr const char* kVersionKey = "styk_progress";

}  // namespace styk::progress_protocol
