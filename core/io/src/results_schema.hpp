// Names shared by the results-file writer and reader (the schema is documented in
// docs/results.md; change both together and bump kSchemaVersion).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/results.hpp"

namespace styk::io::schema {

inline constexpr const char* kFormat = "styk-results";
inline constexpr int kSchemaVersion = 1;

inline std::string step_group(int step) { return "step_" + std::to_string(step); }
inline std::string increment_group(int increment) {
  return "increment_" + std::to_string(increment);
}

// The recovered fields of an increment (SPEC §5), stored as (rows, 6) datasets of the increment
// group under these names. Optional: files written before they existed lack them (read as empty).
struct RecoveredField {
  enum class Per { ElementNode, Element, Node };  // rows: connectivity length, elements, nodes
  const char* name;
  Per per;
  std::vector<Tensor6> IncrementResult::*member;
};

using FieldPer = RecoveredField::Per;
inline constexpr std::array<RecoveredField, 8> kRecoveredFields = {{
    {"S_element_nodes", FieldPer::ElementNode, &IncrementResult::S_element_nodes},
    {"E_element_nodes", FieldPer::ElementNode, &IncrementResult::E_element_nodes},
    {"S_centroid", FieldPer::Element, &IncrementResult::S_centroid},
    {"E_centroid", FieldPer::Element, &IncrementResult::E_centroid},
    {"S_nodal_I", FieldPer::Node, &IncrementResult::S_nodal_I},
    {"S_nodal_II", FieldPer::Node, &IncrementResult::S_nodal_II},
    {"E_nodal_I", FieldPer::Node, &IncrementResult::E_nodal_I},
    {"E_nodal_II", FieldPer::Node, &IncrementResult::E_nodal_II},
}};

}  // namespace styk::io::schema
