// Small programmatic models for the solver tests (no .inp reader involved).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "cantilever_model.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk::test {

// A block [0,lx] x [0,ly] x [0,lz] of nx x ny x nz elements of `type` (E = 210000, nu = 0.3),
// without boundary conditions or steps.
inline Model block(const ElementRegistry& registry, const std::string& type, int nx, int ny, int nz,
                   double lx, double ly, double lz) {
  testkit::CantileverSpec spec;
  spec.type = type;
  spec.nx = nx;
  spec.ny = ny;
  spec.nz = nz;
  spec.length = lx;
  spec.width = ly;
  spec.height = lz;
  Model model = testkit::make_cantilever(spec, registry).model;
  model.boundaries.clear();
  model.steps.clear();
  model.source = "test.inp";
  return model;
}

inline Step static_step(double total_time = 1.0) {
  Step step;
  step.name = "STEP";
  step.has_procedure = true;
  step.procedure.total_time = total_time;
  return step;
}

// Nodes whose coordinate `axis` equals `value`.
inline std::vector<int> nodes_at(const Model& model, int axis, double value) {
  std::vector<int> nodes;
  for (int n = 0; n < model.node_count(); ++n)
    if (std::abs(model.coords[n][axis] - value) < 1e-12) nodes.push_back(n);
  return nodes;
}

// Symmetry supports of a block with a corner at the origin: u_d = 0 on the plane x_d = 0.
inline void add_symmetry_supports(Model& model) {
  for (int d = 0; d < 3; ++d)
    for (int n : nodes_at(model, d, 0.0)) model.boundaries.push_back({n, d + 1, 0.0, {}});
}

inline double max_abs_displacement(const IncrementResult& increment) {
  double m = 0.0;
  for (const Vec3& u : increment.U)
    for (double v : u) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace styk::test
