#include "constraint_lowering.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "styk/core/local_axes.hpp"

namespace styk::solver_detail {

EquationBuilder::EquationBuilder(Model& model)
    : model_(model),
      transform_of_node_(model.node_count(), -1),
      eliminated_(3 * static_cast<std::size_t>(model.node_count()), 0) {
  for (std::size_t t = 0; t < model.transforms.size(); ++t)
    if (const NodeSet* set = model.find_nset(model.transforms[t].nset))
      for (int node : set->nodes) transform_of_node_[node] = static_cast<int>(t);
  for (const Equation& equation : model.equations) {
    const EquationTerm& first = equation.terms.front();
    // Only translations are eliminated here; a rotation (dof 4..6 of a beam node) is not.
    if (first.dof >= 1 && first.dof <= 3) eliminated_[3 * first.node + first.dof - 1] = 1;
  }
}

Eigen::Matrix3d EquationBuilder::axes_of(int node) const {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  if (node >= static_cast<int>(transform_of_node_.size()) || transform_of_node_[node] < 0) return R;
  const Transform& t = model_.transforms[transform_of_node_[node]];
  if (!local_axes_at(t.axes, model_.coords[node], R))
    throw InputError(t.where, "*TRANSFORM: node " + std::to_string(model_.node_ids[node]) +
                                  " has no local axes (it lies on the cylinder axis)");
  return R;
}

void EquationBuilder::add(const std::vector<DirectionalTerm>& terms, int dependent_node,
                          const SourceLoc& where, int component) {
  if (3 * static_cast<std::size_t>(model_.node_count()) > eliminated_.size()) {
    eliminated_.resize(3 * static_cast<std::size_t>(model_.node_count()), 0);
    transform_of_node_.resize(model_.node_count(), -1);
  }
  // Sum the coefficients per nodal dof: a . u = (R^T a) . w in the node's axes.
  std::map<std::pair<int, int>, double> coefficient;
  double scale = 0.0;
  for (const DirectionalTerm& t : terms) {
    const Eigen::Vector3d local = axes_of(t.node).transpose() * t.a;
    for (int d = 0; d < 3; ++d) coefficient[{t.node, d}] += local[d];
    scale = std::max(scale, t.a.cwiseAbs().maxCoeff());
  }
  // The eliminated term: the dependent node's free component with the largest coefficient.
  int dependent = -1;
  double largest = 1e-10 * scale;
  for (int d = 0; d < 3; ++d) {
    const double c = std::abs(coefficient[{dependent_node, d}]);
    if (component >= 0 && d != component) continue;
    if (!eliminated_[3 * dependent_node + d] && c > largest) {
      largest = c;
      dependent = d;
    }
  }
  if (dependent < 0)
    throw InputError(where, "node " + std::to_string(model_.node_ids[dependent_node]) +
                                " is constrained more than once (its dofs are already "
                                "eliminated by other equations, ties or couplings)");
  eliminated_[3 * dependent_node + dependent] = 1;
  Equation equation;
  equation.where = where;
  equation.terms.push_back(
      {dependent_node, dependent + 1, coefficient[{dependent_node, dependent}]});
  for (const auto& [key, c] : coefficient) {
    if (key.first == dependent_node && key.second == dependent) continue;
    if (std::abs(c) <= 1e-14 * scale) continue;  // round-off of the projections
    equation.terms.push_back({key.first, key.second + 1, c});
  }
  if (equation.terms.size() < 2)
    throw InputError(where, "a generated constraint on node " +
                                std::to_string(model_.node_ids[dependent_node]) +
                                " has a single term (it would fix the dof)");
  model_.equations.push_back(std::move(equation));
}

std::optional<Model> lower_constraints(const Model& model, const ElementRegistry& registry,
                                       std::vector<std::string>* notes) {
  if (model.ties.empty() && model.mpcs.empty() && model.pretension_sections.empty()) {
    bool kinematic = false;
    for (const Coupling& c : model.couplings)
      kinematic = kinematic || c.kind == Coupling::Kind::Kinematic;
    if (!kinematic) return std::nullopt;
  }
  Model lowered = model;
  EquationBuilder equations(lowered);
  // Pre-tension first: it splits nodes, which the other constraints then see as they are.
  lower_pretension_sections(lowered, registry, equations, notes);
  lower_ties(lowered, registry, equations, notes);
  lower_kinematic_couplings(lowered, registry, equations);
  lower_mpcs(lowered, equations);
  lowered.ties.clear();
  lowered.mpcs.clear();
  lowered.pretension_sections.clear();
  std::vector<Coupling> distributing;
  for (const Coupling& c : lowered.couplings)
    if (c.kind == Coupling::Kind::Distributing) distributing.push_back(c);
  lowered.couplings = std::move(distributing);
  return lowered;
}

void restrict_to_nodes(int node_count, Results& results) {
  const std::size_t n = static_cast<std::size_t>(node_count);
  auto cut = [n](auto& v) {
    if (v.size() > n) v.resize(n);
  };
  for (IncrementResult& inc : results.increments) {
    cut(inc.U);
    cut(inc.RF);
    cut(inc.S_nodal_I);
    cut(inc.S_nodal_II);
    cut(inc.E_nodal_I);
    cut(inc.E_nodal_II);
    cut(inc.scalar.value);
    cut(inc.scalar.reaction);
    cut(inc.scalar.flux_nodal);
  }
}

}  // namespace styk::solver_detail
