// `styk mesh`: run a parametric builder of a SPEC.md model and write its deck (mesher/builders).
#pragma once

#include <string>
#include <vector>

namespace styk::cli {

struct MeshArgs {
  std::string builder;              // e.g. "twisted-beam"; empty with --list
  std::string output;               // the .inp to write
  bool list = false;                // --list: the builders, their SPEC sections and parameters
  std::vector<std::string> params;  // the remaining arguments: --name value or --name=value
};

// Exit codes as every command (exit_codes.hpp): bad builder, parameter or value -> InputError.
int mesh_command(const MeshArgs& args);

}  // namespace styk::cli
