// Names shared by the results-file writer and reader (the schema is documented in
// docs/results.md; change both together and bump kSchemaVersion).
#pragma once

#include <string>

namespace styk::io::schema {

inline constexpr const char* kFormat = "styk-results";
inline constexpr int kSchemaVersion = 1;

inline std::string step_group(int step) { return "step_" + std::to_string(step); }
inline std::string increment_group(int increment) {
  return "increment_" + std::to_string(increment);
}

}  // namespace styk::io::schema
