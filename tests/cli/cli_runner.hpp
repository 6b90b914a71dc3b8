// Runs the `styk` program (or any command) from a test and captures its exit code and output.
#pragma once

#include <string>

namespace styk::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs `command` through /bin/sh in `workdir`; stdout and stderr are captured separately.
CommandResult run_command(const std::string& command, const std::string& workdir);

// Path of the built `styk` executable.
std::string styk_executable();

// A fresh, empty scratch directory for a test under the build tree.
std::string scratch_dir(const std::string& name);

std::string read_file(const std::string& path);

}  // namespace styk::testing
