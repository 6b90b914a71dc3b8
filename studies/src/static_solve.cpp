#include "styk/studies/static_solve.hpp"

#include "styk/solver/analysis.hpp"

namespace styk::studies {

mesher::StaticSolve static_solve(const ElementRegistry& registry) {
  return [&registry](const Model& model) {
    return run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  };
}

}  // namespace styk::studies
