// `styk verify`: the SPEC §3.1 element tests for every element family (mesher/verify), printed
// as Markdown tables, optionally written into the marked section of docs/verification.md.
#pragma once

#include <string>

namespace styk::cli {

struct VerifyArgs {
  bool list = false;       // --list: the cases, their SPEC sections, builders and parameters
  std::string case_name;   // --case NAME: one case, every family
  std::string table;       // --table 3.13: every case, the grade table and the value tables
  std::string write_path;  // --write FILE (with --table): replace the marked section of FILE
};

// Exit codes as every command (exit_codes.hpp): an unknown case or table, a missing file or
// marker -> InputError (1); a family that could not be solved is reported, and with --write
// nothing is written (1).
int verify_command(const VerifyArgs& args);

}  // namespace styk::cli
