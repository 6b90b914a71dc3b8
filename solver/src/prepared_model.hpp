// Validation of a Model for analysis and the per-element lookups the solver needs: the
// formulation and material of every element, and which nodes are active (used by an element).
// Only active nodes carry degrees of freedom: active dof of active node a, direction d (0..2) is
// 3a + d. A dof of an active node that no element stiffens (uz of a node used only by plane
// elements, TElement::active_displacements()) is inactive: step_conditions prescribes it to zero,
// which removes it from the factorised system, and refuses loads or nonzero values on it.
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
  std::vector<char> stiffened;               // per active dof: 1 if some element stiffens it
  // Per active node: 1 if it belongs to an axisymmetric element (ElementForm::Axisymmetric). A
  // ring cannot translate radially (x), so the rigid-motion checks count x as held there.
  std::vector<char> ring_node;

  int active_nodes() const { return static_cast<int>(node_of_active.size()); }
  int active_dofs() const { return 3 * active_nodes(); }
  bool inactive_dof(int dof) const { return stiffened[dof] == 0; }
};

// Throws InputError at the offending deck line for: an element without section, an unknown
// element type or wrong node count, a section without material, a material without E and nu, a
// section without the area its truss elements need (TElement::section_measure()).
PreparedModel prepare_model(const Model& model, const ElementRegistry& registry);

// The section datum of element e for ElementGeometry::cross_section: the section's thickness or
// area, 1 when it gives none (CalculiX's default thickness of plane elements).
double cross_section_of(const Model& model, int e);

// "node 17 (uy)" for an active dof.
std::string describe_dof(const Model& model, const PreparedModel& prepared, int active_dof);

}  // namespace styk::solver_detail
