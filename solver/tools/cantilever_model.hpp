// The cantilever of PERFORMANCE.md, built programmatically for benchmarks and tests: a block
// [0, length] x [0, width] x [0, height] of nx x ny x nz hexahedra of any registered type whose
// nodes sit on the natural grid {-1, 0, 1}^3 (C3D8, C3D20, C3D27), clamped at x = 0 and loaded by
// a total shear force in z on x = length, distributed as consistent nodal forces.
#pragma once

#include <string>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::testkit {

struct CantileverSpec {
  int nx = 10, ny = 1, nz = 1;
  double length = 10.0, width = 1.0, height = 1.0;
  std::string type = "C3D20";
  double young = 210000.0, poisson = 0.3;
  double tip_force = 1.0;  // total, in +z
};

struct Cantilever {
  Model model;
  int tip_centre_node = -1;  // node index at (length, width/2, height/2), -1 if not a mesh node
};

Cantilever make_cantilever(const CantileverSpec& spec, const ElementRegistry& registry);

}  // namespace styk::testkit
