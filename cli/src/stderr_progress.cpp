#include "stderr_progress.hpp"

#include <fmt/core.h>

namespace styk::cli {

void StderrProgress::begin(const std::string& phase) {
  if (!quiet_) fmt::print(stderr, "styk: {} ...\n", phase);
}

void StderrProgress::end(const std::string& phase, double seconds) {
  if (!quiet_) fmt::print(stderr, "styk: {} done in {:.3f} s\n", phase, seconds);
}

void StderrProgress::info(const std::string& message) {
  if (!quiet_) fmt::print(stderr, "styk:   {}\n", message);
}

void StderrProgress::warning(const std::string& message) {
  fmt::print(stderr, "styk:   warning: {}\n", message);
}

}  // namespace styk::cli
