#include "model_constraints.hpp"

#include <algorithm>
#include <iterator>

#include "assembly.hpp"
#include "cyclic_equations.hpp"

namespace styk::solver_detail {

ModelConstraints ModelConstraints::build(const Model& model, const PreparedModel& prepared,
                                         const ElementRegistry& registry) {
  ModelConstraints out;
  out.rotations_ = NodeRotations::from_transforms(model, prepared);
  out.cyclic_ =
      cyclic_equations(model, prepared, out.rotations_, resolve_cyclic_symmetries(model, registry));
  out.equations_ = EquationElimination::build(model, prepared, out.cyclic_);
  return out;
}

void ModelConstraints::apply(StiffnessMatrix& K) const {
  rotations_.rotate_stiffness(K);
  equations_.eliminate(K);
}

std::vector<int> ModelConstraints::known_dofs(const Model& model, const PreparedModel& prepared,
                                              const std::vector<int>& prescribed) const {
  if (equations_.empty()) return prescribed;
  equations_.check_not_prescribed(model, prepared, prescribed);
  const std::vector<int> dependent = equations_.dependent_dofs();
  std::vector<int> known;
  known.reserve(prescribed.size() + dependent.size());
  std::merge(prescribed.begin(), prescribed.end(), dependent.begin(), dependent.end(),
             std::back_inserter(known));
  return known;
}

std::vector<double> ModelConstraints::nodal_forces(const Model& model,
                                                   const PreparedModel& prepared,
                                                   const StepConditions& conditions) const {
  StepConditions distributed;
  distributed.pressures = conditions.pressures;
  std::vector<double> f = assemble_loads(model, prepared, distributed);
  rotations_.to_local(f);
  for (const DofValue& load : conditions.nodal_loads) f[load.dof] += load.value;
  return f;
}

std::vector<double> ModelConstraints::plus_global(std::vector<double> f,
                                                  std::vector<double> global) const {
  if (global.empty()) return f;
  rotations_.to_local(global);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] += global[i];
  return f;
}

std::vector<double> ModelConstraints::reduced_forces(std::vector<double> nodal) const {
  equations_.reduce(nodal);
  return nodal;
}

void ModelConstraints::to_global_displacements(std::vector<double>& w) const {
  equations_.expand(w);
  rotations_.to_global(w);
}

std::vector<Restraint> ModelConstraints::restraints(const Model& model,
                                                    const PreparedModel& prepared,
                                                    const std::vector<int>& prescribed) const {
  std::vector<Restraint> out;
  out.reserve(prescribed.size() + model.equations.size() + cyclic_.size());
  for (int dof : prescribed)
    out.push_back(Restraint{
        {{prepared.node_of(dof), rotations_.direction(dof), rotations_.rotational(dof)}}});
  std::vector<const Equation*> equations;
  for (const Equation& equation : model.equations) equations.push_back(&equation);
  for (const Equation& equation : cyclic_) equations.push_back(&equation);
  for (const Equation* each : equations) {
    const Equation& equation = *each;
    Restraint restraint;
    for (const EquationTerm& term : equation.terms) {
      const int a = prepared.active_of_node[term.node];
      const int dof = prepared.dof(a, term.dof - 1);  // checked by EquationElimination::build
      restraint.terms.push_back(RestraintTerm{a, term.coefficient * rotations_.direction(dof),
                                              rotations_.rotational(dof)});
    }
    out.push_back(std::move(restraint));
  }
  return out;
}

std::vector<int> ModelConstraints::reaction_dofs(const std::vector<int>& prescribed) const {
  const std::vector<int>& involved = equations_.involved_dofs();
  std::vector<int> dofs;
  std::set_union(prescribed.begin(), prescribed.end(), involved.begin(), involved.end(),
                 std::back_inserter(dofs));
  return dofs;
}

}  // namespace styk::solver_detail
