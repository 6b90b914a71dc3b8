#include "msh_tokens.hpp"

#include <cerrno>
#include <cstdlib>

namespace styk::gmsh {

MshTokens::MshTokens(const std::string& path) : path_(path), in_(path) {
  if (!in_) throw InputError({path, 0}, "cannot open the mesh file");
}

void MshTokens::fail(const std::string& message) const { throw InputError(here(), message); }

bool MshTokens::fill() {
  std::string text;
  while (std::getline(in_, text)) {
    ++line_;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    current_.clear();
    current_.str(text);
    return true;
  }
  return false;
}

bool MshTokens::try_next(std::string& token) {
  while (!(current_ >> token)) {
    if (!fill()) return false;
  }
  return true;
}

std::string MshTokens::next(const char* what) {
  std::string token;
  if (!try_next(token)) fail(std::string("the file ends where ") + what + " was expected");
  return token;
}

long long MshTokens::next_integer(const char* what) {
  const std::string token = next(what);
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(token.c_str(), &end, 10);
  if (errno != 0 || end == token.c_str() || *end != '\0')
    fail(std::string(what) + " must be an integer, not '" + token + "'");
  return value;
}

double MshTokens::next_real(const char* what) {
  const std::string token = next(what);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(token.c_str(), &end);
  if (errno == ERANGE || end == token.c_str() || *end != '\0')
    fail(std::string(what) + " must be a number, not '" + token + "'");
  return value;
}

std::string MshTokens::rest_of_line() {
  std::string rest;
  std::getline(current_, rest);
  current_.clear();
  current_.str("");
  const auto first = rest.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = rest.find_last_not_of(" \t\r");
  return rest.substr(first, last - first + 1);
}

}  // namespace styk::gmsh
