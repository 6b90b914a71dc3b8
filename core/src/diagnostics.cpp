#include "styk/core/diagnostics.hpp"

namespace styk {

std::string SourceLoc::str() const {
  if (file.empty()) return line > 0 ? "line " + std::to_string(line) : std::string();
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

namespace {
std::string compose(const SourceLoc& where, const std::string& message) {
  const std::string place = where.str();
  return place.empty() ? message : place + ": " + message;
}
}  // namespace

InputError::InputError(SourceLoc where, const std::string& message)
    : std::runtime_error(compose(where, message)), where_(std::move(where)), message_(message) {}

}  // namespace styk
