#include "verification_support.hpp"

#include <cmath>
#include <stdexcept>

#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk::verification {

Results solve(const Model& model) {
  ElementRegistry registry = test::builtin_registry();
  SolveOptions options;
  return run_static_analysis(model, registry, options, nullptr, nullptr);
}

double mean_displacement(const Model& model, const Results& results, const std::string& set,
                         int dof) {
  const NodeSet* nodes = model.find_nset(set);
  if (!nodes || nodes->nodes.empty()) throw std::invalid_argument("no node set " + set);
  const IncrementResult& last = results.increments.back();
  double sum = 0.0;
  for (int n : nodes->nodes) sum += last.U[n][dof];
  return sum / static_cast<double>(nodes->nodes.size());
}

char grade(double value, double reference) {
  const double error = std::abs(value - reference) / std::abs(reference);
  if (error < 0.02) return 'A';
  if (error < 0.10) return 'B';
  if (error < 0.20) return 'C';
  if (error < 0.50) return 'D';
  return 'E';
}

}  // namespace styk::verification
