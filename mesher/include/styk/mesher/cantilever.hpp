// Builder of block cantilevers (SPEC §2.1, §3.1.1, and the scale benchmark of PERFORMANCE.md):
// a box along x, clamped on x = 0, loaded on the free end x = L. Node sets: NALL, ROOT (x = 0),
// TIP (x = L), TIPMID (the loaded edge mid-point, or the two edge end nodes of a C3D8 mesh).
#pragma once

#include "styk/core/model.hpp"
#include "styk/mesher/box_mesh.hpp"

namespace styk::mesher {

struct CantileverSpec {
  BoxSpec box;  // size = (L, width, height)
  double young = 210000.0;
  double poisson = 0.3;
  enum class Load {
    EndTraction,      // uniform traction on x = L, resultant `force`, consistent nodal loads
    TopEdgeMidpoint,  // `force` at the middle of the top edge (z = height) of the free end
  };
  Load load = Load::EndTraction;
  Vec3 force{0.0, 0.0, 1.0};
  bool print_all_displacements = false;  // *NODE PRINT, NSET=NALL instead of NSET=TIP
};

Model make_cantilever(const CantileverSpec& spec);

}  // namespace styk::mesher
