// Numbers in the pre-solve warnings (model_warnings, beam_warnings, shell_warnings).
#pragma once

#include <cstdio>
#include <string>

namespace styk::solver_detail {

// `value` printed with a printf pattern ("%g", "%.3g"): the warnings quote measured figures.
inline std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

}  // namespace styk::solver_detail
