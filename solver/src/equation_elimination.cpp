#include "equation_elimination.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace styk::solver_detail {
namespace {

// "node 12, dof 2" (the dof is local when the node has a *TRANSFORM, as in the deck).
std::string dof_name(const Model& model, const PreparedModel& prepared, int dof) {
  return "node " + std::to_string(model.node_ids[prepared.node_of_active[prepared.node_of(dof)]]) +
         ", dof " + std::to_string(prepared.component(dof) + 1);
}

struct RawEquation {
  std::vector<std::pair<int, double>> terms;  // (dof, a_dj) before substitution
  SourceLoc where;
};

// Substitutes dependencies depth-first; `state` 0 = pending, 1 = on the current path, 2 = done.
class ChainResolver {
 public:
  ChainResolver(const Model& model, const PreparedModel& prepared,
                const std::map<int, RawEquation>& raw)
      : model_(model), prepared_(prepared), raw_(raw) {}

  const std::map<int, double>& resolve(int dof) {
    auto& state = state_[dof];
    if (state == 2) return resolved_[dof];
    if (state == 1) throw cycle_error(dof);
    state = 1;
    path_.push_back(dof);
    std::map<int, double> combination;
    for (const auto& [j, a] : raw_.at(dof).terms) {
      if (raw_.count(j) == 0) {
        combination[j] += a;
        continue;
      }
      for (const auto& [k, b] : resolve(j)) combination[k] += a * b;
    }
    for (auto it = combination.begin(); it != combination.end();)
      it = it->second == 0.0 ? combination.erase(it) : std::next(it);
    path_.pop_back();
    state_[dof] = 2;
    return resolved_[dof] = std::move(combination);
  }

 private:
  InputError cycle_error(int dof) const {
    const auto first = std::find(path_.begin(), path_.end(), dof);
    std::string chain;
    for (auto it = first; it != path_.end(); ++it)
      chain += dof_name(model_, prepared_, *it) + " -> ";
    chain += dof_name(model_, prepared_, dof);
    return InputError(raw_.at(dof).where,
                      "*EQUATION: the eliminated dofs depend on each other in a cycle (" + chain +
                          "); reorder the terms so that one dof of the cycle is not the first "
                          "term of any equation");
  }

  const Model& model_;
  const PreparedModel& prepared_;
  const std::map<int, RawEquation>& raw_;
  std::map<int, int> state_;
  std::map<int, std::map<int, double>> resolved_;
  std::vector<int> path_;
};

double* entry(StiffnessMatrix& K, int i, int j) {
  const std::int64_t at = K.entry_index(i, j);
  if (at < 0) throw std::logic_error("equation elimination: entry outside the widened pattern");
  return K.values().data() + at;
}

}  // namespace

EquationElimination EquationElimination::build(const Model& model, const PreparedModel& prepared,
                                               const std::vector<Equation>& generated) {
  EquationElimination out;
  std::map<int, RawEquation> raw;
  std::vector<int> involved;
  std::vector<const Equation*> all;
  for (const Equation& equation : model.equations) all.push_back(&equation);
  for (const Equation& equation : generated) all.push_back(&equation);
  for (std::size_t index = 0; index < all.size(); ++index) {
    const Equation& equation = *all[index];
    const std::size_t fewest_terms = index < model.equations.size() ? 2 : 1;
    std::vector<int> dofs;
    for (const EquationTerm& term : equation.terms) {
      if (term.node < 0 || term.node >= model.node_count())
        throw InputError(equation.where, "*EQUATION on an undefined node");
      if (term.dof < 1 || term.dof > kMaxNodeDofs)
        throw InputError(equation.where, "*EQUATION: degree of freedom " +
                                             std::to_string(term.dof) +
                                             " does not exist; nodes have 1, 2, 3 (displacements) "
                                             "and, at beam nodes, 4, 5, 6 (rotations)");
      const int a = prepared.active_of_node[term.node];
      if (a < 0)
        throw InputError(equation.where, "*EQUATION on node " +
                                             std::to_string(model.node_ids[term.node]) +
                                             ", which belongs to no element (it has no dofs)");
      const int dof = prepared.dof(a, term.dof - 1);
      if (dof < 0)
        throw InputError(equation.where, "*EQUATION: node " +
                                             std::to_string(model.node_ids[term.node]) +
                                             " has no rotational dof " + std::to_string(term.dof) +
                                             " (only beam elements carry rotations 4, 5, 6)");
      dofs.push_back(dof);
    }
    if (dofs.size() < fewest_terms || equation.terms[0].coefficient == 0.0)
      throw InputError(equation.where,
                       "*EQUATION needs at least two terms and a non-zero first coefficient");
    const int dependent = dofs[0];
    if (raw.count(dependent) != 0)
      throw InputError(equation.where, "*EQUATION: " + dof_name(model, prepared, dependent) +
                                           " is already the first (eliminated) term of the "
                                           "constraint equation at line " +
                                           std::to_string(raw[dependent].where.line) +
                                           " (an *EQUATION or a cyclic symmetry *TIE)");
    RawEquation& eq = raw[dependent];
    eq.where = equation.where;
    for (std::size_t i = 1; i < dofs.size(); ++i)
      eq.terms.emplace_back(dofs[i],
                            -equation.terms[i].coefficient / equation.terms[0].coefficient);
    involved.insert(involved.end(), dofs.begin(), dofs.end());
  }

  ChainResolver resolver(model, prepared, raw);
  for (const auto& [dof, equation] : raw) {
    DependentDof dependent;
    dependent.dof = dof;
    dependent.where = equation.where;
    for (const auto& [j, a] : resolver.resolve(dof)) dependent.masters.emplace_back(j, a);
    out.dependents_.push_back(std::move(dependent));
  }
  std::sort(involved.begin(), involved.end());
  involved.erase(std::unique(involved.begin(), involved.end()), involved.end());
  out.involved_ = std::move(involved);
  return out;
}

std::vector<int> EquationElimination::dependent_dofs() const {
  std::vector<int> dofs;
  dofs.reserve(dependents_.size());
  for (const DependentDof& d : dependents_) dofs.push_back(d.dof);
  return dofs;
}

void EquationElimination::check_not_prescribed(const Model& model, const PreparedModel& prepared,
                                               const std::vector<int>& prescribed) const {
  for (const DependentDof& d : dependents_)
    if (std::binary_search(prescribed.begin(), prescribed.end(), d.dof))
      throw InputError(d.where, dof_name(model, prepared, d.dof) +
                                    " is eliminated by the constraint equation of this line (its "
                                    "first term, or a cyclic symmetry slave or axis node) and "
                                    "also prescribed by a *BOUNDARY; make another term the first "
                                    "one, or drop the boundary condition");
}

std::vector<std::pair<int, int>> EquationElimination::extra_node_couplings(
    const Model& model, const PreparedModel& prepared) const {
  if (empty()) return {};
  // Dependent nodes and the nodes of their masters.
  std::map<int, std::vector<int>> masters_of_node;  // active node -> master active nodes
  for (const DependentDof& d : dependents_) {
    std::vector<int>& masters = masters_of_node[prepared.node_of(d.dof)];
    for (const auto& [j, a] : d.masters) masters.push_back(prepared.node_of(j));
  }
  for (auto& [node, masters] : masters_of_node) {
    std::sort(masters.begin(), masters.end());
    masters.erase(std::unique(masters.begin(), masters.end()), masters.end());
  }
  // Element neighbours of each dependent node (itself included).
  std::map<int, std::vector<int>> neighbours;
  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    const int n = model.elements[e].node_count;
    for (int k = 0; k < n; ++k) {
      const int a = prepared.active_of_node[nodes[k]];
      if (masters_of_node.count(a) == 0) continue;
      std::vector<int>& list = neighbours[a];
      for (int m = 0; m < n; ++m) list.push_back(prepared.active_of_node[nodes[m]]);
    }
  }
  std::vector<std::pair<int, int>> pairs;
  for (auto& [node, list] : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    for (int m : masters_of_node[node])
      for (int s : list) {
        pairs.emplace_back(m, s);
        const auto other = masters_of_node.find(s);
        if (other == masters_of_node.end()) continue;
        for (int m2 : other->second) pairs.emplace_back(m, m2);
      }
  }
  for (std::size_t i = 0, n = pairs.size(); i < n; ++i)
    pairs.emplace_back(pairs[i].second, pairs[i].first);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

void EquationElimination::eliminate(StiffnessMatrix& K) const {
  if (empty()) return;
  std::vector<int> dependent_index(K.rows(), -1);
  for (std::size_t k = 0; k < dependents_.size(); ++k)
    dependent_index[dependents_[k].dof] = static_cast<int>(k);

  // The original rows of the dependent dofs (K is symmetric: they are also its columns).
  std::vector<std::vector<std::pair<int, double>>> rows(dependents_.size());
  for (std::size_t k = 0; k < dependents_.size(); ++k) {
    const int d = dependents_[k].dof;
    for (int p = K.row_ptr()[d]; p < K.row_ptr()[d + 1]; ++p)
      if (K.values()[p] != 0.0) rows[k].emplace_back(K.col()[p], K.values()[p]);
  }
  for (std::size_t k = 0; k < dependents_.size(); ++k) {
    const int d = dependents_[k].dof;
    for (int p = K.row_ptr()[d]; p < K.row_ptr()[d + 1]; ++p) {
      K.values()[p] = 0.0;
      *entry(K, K.col()[p], d) = 0.0;
    }
  }
  // P^T K P = E K E + E K A + A^T K E + A^T K A with E the identity on independent dofs and A
  // the rows a_dj: row d of K spreads to the masters of d, from both sides.
  for (std::size_t k = 0; k < dependents_.size(); ++k) {
    const DependentDof& dependent = dependents_[k];
    for (const auto& [l, value] : rows[k]) {
      const int other = dependent_index[l];
      for (const auto& [j, a] : dependent.masters) {
        if (other < 0) {
          *entry(K, j, l) += a * value;
          *entry(K, l, j) += a * value;
          continue;
        }
        for (const auto& [j2, a2] : dependents_[other].masters) *entry(K, j, j2) += a * value * a2;
      }
    }
  }
}

void EquationElimination::reduce(std::vector<double>& f) const {
  for (const DependentDof& d : dependents_) {
    for (const auto& [j, a] : d.masters) f[j] += a * f[d.dof];
    f[d.dof] = 0.0;
  }
}

void EquationElimination::expand(std::vector<double>& w) const {
  for (const DependentDof& d : dependents_) {
    double value = 0.0;
    for (const auto& [j, a] : d.masters) value += a * w[j];
    w[d.dof] = value;
  }
}

}  // namespace styk::solver_detail
