// Validation of a Model for analysis and the per-element lookups the solver needs: the
// formulation and material of every element, and which nodes are active (used by an element).
// Only active nodes carry degrees of freedom: active dof of active node a, direction d (0..2) is
// 3a + d.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::solver_detail {

struct PreparedModel {
  std::vector<const TElement*> formulation;  // per element
  std::vector<const Material*> material;     // per element
  std::vector<int> active_of_node;           // model node index -> active index, -1 if unused
  std::vector<int> node_of_active;           // active index -> model node index
  std::vector<int> ip_offset;                // integration points (full rule) per element, CSR

  int active_nodes() const { return static_cast<int>(node_of_active.size()); }
  int active_dofs() const { return 3 * active_nodes(); }
};

// Throws InputError at the offending deck line for: an element without section, an unknown
// element type or wrong node count, a section without material, a material without E and nu.
PreparedModel prepare_model(const Model& model, const ElementRegistry& registry);

// "node 17 (uy)" for an active dof.
std::string describe_dof(const Model& model, const PreparedModel& prepared, int active_dof);

}  // namespace styk::solver_detail
