// The errors of a solved model against its exact solution (RunRecord's measures): at named
// points, and over the body in the L2 and energy norms.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/studies/results/run_record.hpp"
#include "styk/studies/study/exact_solution.hpp"

namespace styk::studies {

// A displacement component u . direction at a node (the model's node nearest to `at`, which must
// lie within 1e-6 of the model's size); for heat, the temperature there.
struct PointProbe {
  std::string label;
  Vec3 at{};
  Vec3 direction{1, 0, 0};
};

// A stress component a . sigma . b at a node from the nodal averages (method I of SPEC §5, what
// the user sees); for heat, the heat flux component flux . a.
struct StressProbe {
  std::string label;
  Vec3 at{};
  Vec3 a{1, 0, 0};
  Vec3 b{1, 0, 0};
};

struct ProblemProbes {
  PointProbe displacement;
  StressProbe stress;
  // The exact contact pressure of a contact problem (every slave node is compared with it);
  // nullopt for problems without contact.
  std::optional<double> contact_pressure;
};

using ErrorArray = std::array<std::optional<double>, kMeasureCount>;

// Every measure of RunRecord::error that applies to the problem. `result` is the increment to
// measure (the last). Throws InputError when a named point has no node.
ErrorArray measure_errors(const Model& model, const IncrementResult& result,
                          const ElementRegistry& registry, const ExactSolution& exact,
                          const ProblemProbes& probes);

// The pieces, for tests: the relative L2 error of the displacement (temperature) and the relative
// energy norm of its error (strains B u_h against the exact strains, weighted by the material's
// D; for heat, k |grad T_h - grad T|^2), both over the body with a 4 x 4 x 4 Gauss rule on
// hexahedra (the element's full rule otherwise). The L2 error measures the displacement field
// N u_h; the energy norm the element's strain field, with C3D8I's incompatible modes (recovered
// from u_h as the solver condenses them) included.
double relative_l2_error(const Model& model, const IncrementResult& result,
                         const ElementRegistry& registry, const ExactSolution& exact);
double relative_energy_error(const Model& model, const IncrementResult& result,
                             const ElementRegistry& registry, const ExactSolution& exact);

}  // namespace styk::studies
