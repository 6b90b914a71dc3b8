// Validation of a Model for analysis and the per-element lookups the solver needs: the
// formulation and material of every element, which nodes are active (used by an element), and the
// dof layout. Only active nodes carry degrees of freedom, as many as the element with the most
// dofs per node among their elements has (TElement::node_dofs()): 3 (ux, uy, uz) or 6 (ux, uy, uz,
// rx, ry, rz). Node a's dofs are dof_offset[a] .. dof_offset[a + 1] - 1, translations first;
// dof(a, c) is its component c (0..5), -1 when the node has no such dof. A dof of an active node
// that no element stiffens (uz of a node used only by plane elements, rx and ry of a node used
// only by planar beams: TElement::active_dofs()) is inactive: step_conditions prescribes it to
// zero, which removes it from the factorised system, and refuses loads or nonzero values on it.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/shell_normals.hpp"

namespace styk::solver_detail {

struct PreparedModel {
  std::vector<const TElement*> formulation;  // per element
  std::vector<const Material*> material;     // per element
  std::vector<int> active_of_node;           // model node index -> active index, -1 if unused
  std::vector<int> node_of_active;           // active index -> model node index
  std::vector<RuleKind> rule_kind;           // per element: the rule its section chose
  std::vector<int> ip_offset;                // output points per element (its rule), CSR
  std::vector<int> station_offset;           // section-resultant stations per element, CSR
  std::vector<char> stiffened;               // per active dof: 1 if some element stiffens it
  std::vector<int> dof_offset;               // per active node + 1: first dof (CSR)
  std::vector<int> node_of_dof;              // per active dof: its active node
  // Per active node: 1 if it belongs to an axisymmetric element (ElementForm::Axisymmetric). A
  // ring cannot translate radially (x), so the rigid-motion checks count x as held there.
  std::vector<char> ring_node;
  // The curved shells' nodal normals, resolved over the whole mesh (styk/core/shell_normals.hpp);
  // element_geometry() hands them to each shell. Empty when the model has no shells.
  ShellNormals shell_normals;

  int active_nodes() const { return static_cast<int>(node_of_active.size()); }
  int active_dofs() const { return dof_offset.empty() ? 0 : dof_offset.back(); }
  int node_dofs(int a) const { return dof_offset[a + 1] - dof_offset[a]; }
  // Active dof of component c (0 = ux .. 5 = rz) of active node a; -1 when a has fewer dofs.
  int dof(int a, int c) const { return c < node_dofs(a) ? dof_offset[a] + c : -1; }
  int node_of(int dof) const { return node_of_dof[dof]; }
  int component(int dof) const { return dof - dof_offset[node_of_dof[dof]]; }
  bool has_rotations() const { return active_dofs() > 3 * active_nodes(); }
  bool inactive_dof(int dof) const { return stiffened[dof] == 0; }

  // The active dofs of element e's element-matrix entries: (node k, component c) of its
  // node_dofs() per node at k * node_dofs() + c.
  void element_dofs(const Model& model, int e, std::vector<int>& dofs) const;
};

// Throws InputError at the offending deck line for: an element without section, an unknown
// element type or wrong node count, a section without material, a material without E and nu, a
// section without the area its truss elements need or the kind of section its elements take
// (TElement::section_measure(): *BEAM SECTION for beams and only for them). Every element
// integrates with RuleKind::Full (its standard rule) except beams, whose *BEAM SECTION chooses
// (BeamSection::integration; reduced by default).
PreparedModel prepare_model(const Model& model, const ElementRegistry& registry);

// Throws InputError at the request's line for output the model cannot have: UR or RM asked for
// when no node carries rotations, SF or SM when no element has section resultants (no beams).
void check_output_requests(const Model& model, const PreparedModel& prepared);

// The section datum of element e for ElementGeometry::cross_section: the section's thickness or
// area, 1 when it gives none (CalculiX's default thickness of plane elements).
double cross_section_of(const Model& model, int e);

// "node 17 (uy)" / "node 17 (rz)" for an active dof.
std::string describe_dof(const Model& model, const PreparedModel& prepared, int active_dof);

}  // namespace styk::solver_detail
