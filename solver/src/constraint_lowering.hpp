// Ties, couplings, MPCs and pre-tension sections, turned into what the linear path already solves
// (CalculiX does the same): linear *EQUATIONs on the nodal dofs, extra nodes (the rotation node of
// a kinematic coupling, the split nodes of a pre-tension section) and, for a distributing
// coupling, a rule that carries the reference node's loads to the surface. The analysis solves a
// lowered copy of the model and reports the results on the model's own nodes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

// One term of a constraint in global directions: coefficient vector a on the displacement of
// `node` (the constraint reads sum of a . u_node = 0).
struct DirectionalTerm {
  int node = 0;
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
};

// Builds *EQUATIONs from directional terms: each term becomes up to three terms on the node's
// dofs, in its *TRANSFORM system where it has one; the dependent (first) term is the component of
// the preferred node with the largest coefficient that no equation eliminates yet.
class EquationBuilder {
 public:
  explicit EquationBuilder(Model& model);
  // Adds sum a_k . u_k = 0 with a dof of `dependent_node` as its eliminated term. Throws
  // InputError at `where` when that node has no dof left to eliminate in this equation.
  // `component` (0..2), when given, is the dependent node's nodal dof to eliminate.
  void add(const std::vector<DirectionalTerm>& terms, int dependent_node, const SourceLoc& where,
           int component = -1);

 private:
  Eigen::Matrix3d axes_of(int node) const;  // R (nodal axes as columns); identity if global
  Model& model_;
  std::vector<int> transform_of_node_;  // index into model_.transforms, -1 if none
  std::vector<char> eliminated_;        // 3 per node: the dof is some equation's first term
};

// The lowered copy of `model` when it has ties, couplings, MPCs or pre-tension sections (else
// nothing). `notes` receives what the lowering did that a user should know (slave nodes left
// untied, the pre-tension normals); may be null.
std::optional<Model> lower_constraints(const Model& model, const ElementRegistry& registry,
                                       std::vector<std::string>* notes);

// Results of a lowered model restricted to the first `node_count` nodes (the original model's).
void restrict_to_nodes(int node_count, Results& results);

// Parts of the lowering, one file each.
void lower_ties(Model& lowered, const ElementRegistry& registry, EquationBuilder& equations,
                std::vector<std::string>* notes);  // tie_lowering.cpp
void lower_kinematic_couplings(Model& lowered, const ElementRegistry& registry,
                               EquationBuilder& equations);   // coupling_lowering.cpp
void lower_mpcs(Model& lowered, EquationBuilder& equations);  // mpc_lowering.cpp
void lower_pretension_sections(Model& lowered, const ElementRegistry& registry,
                               EquationBuilder& equations,
                               std::vector<std::string>* notes);  // pretension_lowering.cpp

}  // namespace styk::solver_detail
