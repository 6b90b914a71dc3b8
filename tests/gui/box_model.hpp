// The GUI tests' known box: 4 x 4 x 4 C3D8 on [0, 4]^3 in element set BOX (ids 1..64, x fastest,
// then y, then z).
#pragma once

#include "styk/core/model.hpp"
#include "styk/mesher/block_mesh.hpp"

namespace styk::gui::test {

inline Model box_model() {
  mesher::Mesh mesh;
  mesher::BlockSpec spec;
  spec.type = "C3D8";
  spec.divisions = {4, 4, 4};
  spec.elset = "BOX";
  mesher::mesh_block(
      mesh,
      [](const Vec3& xi) {
        return Vec3{2 * (xi[0] + 1), 2 * (xi[1] + 1), 2 * (xi[2] + 1)};
      },
      spec);
  return mesher::to_model(mesh);
}

}  // namespace styk::gui::test
