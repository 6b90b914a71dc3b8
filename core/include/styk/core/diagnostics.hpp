// Typed errors shared by every module. User and input errors carry the place they point to, so
// every message can read "file:line: message" (STYLE practice 7).
#pragma once

#include <stdexcept>
#include <string>

namespace styk {

// A place in an input deck. line == 0 means "the whole file" (or no file at all).
struct SourceLoc {
  std::string file;
  int line = 0;

  std::string str() const;  // "file:line", "file", or "" when unknown
};

// Bad input: a deck, a command-line argument or a model that cannot be analysed as given.
// The CLI maps it to exit code 1.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLoc where, const std::string& message);
  const SourceLoc& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLoc where_;
  std::string message_;
};

// The analysis ran but did not converge (contact iteration, iterative solver). Exit code 2.
class NotConvergedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The model does not fit the machine (or the limit the user set): the message names what was
// needed and what was available, and what to do instead. Exit code 5.
class ResourceLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace styk
