// Whitespace-separated tokens of a .msh file with their line numbers, so that every complaint
// names file:line.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "styk/core/diagnostics.hpp"
#include "styk/core/model.hpp"

namespace styk::gmsh {

class MshTokens {
 public:
  explicit MshTokens(const std::string& path);

  // The next token; InputError at the end of the file, saying what was expected.
  std::string next(const char* what);
  // The next token as a number of the kind asked for; InputError naming `what` otherwise.
  long long next_integer(const char* what);
  double next_real(const char* what);
  // The rest of the current line (after the last token read), trimmed.
  std::string rest_of_line();
  // The next token if there is one (false at the end of the file).
  bool try_next(std::string& token);

  int line() const { return line_; }
  const std::string& path() const { return path_; }
  SourceLoc here() const { return {path_, line_}; }
  [[noreturn]] void fail(const std::string& message) const;

 private:
  bool fill();  // reads lines until one holds a token; false at the end of the file

  std::string path_;
  std::ifstream in_;
  std::istringstream current_;
  int line_ = 0;
};

}  // namespace styk::gmsh
