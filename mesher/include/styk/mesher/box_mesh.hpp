// A structured mesh of an axis-aligned box: nx x ny x nz hexahedra, C3D8 (trilinear) or C3D20
// (serendipity, mid-edge nodes). Nodes live on a "fine" grid with step 1 (C3D8) or 2 (C3D20) per
// element, which gives every node a grid address (i, j, k) for picking faces, edges and points.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk::mesher {

struct BoxSpec {
  std::string type = "C3D20";  // C3D8 or C3D20
  Vec3 origin{0.0, 0.0, 0.0};
  Vec3 size{1.0, 1.0, 1.0};
  std::array<int, 3> divisions{1, 1, 1};
  std::string elset = "EALL";  // element set receiving every element ("" = none)
};

class BoxMesh {
 public:
  // Adds the nodes and elements of the box to `model`, numbering nodes by grid address and
  // elements from 1 (the model should hold no other nodes/elements with those ids).
  BoxMesh(const BoxSpec& spec, Model& model);

  int step() const { return step_; }                      // 1 for C3D8, 2 for C3D20
  std::array<int, 3> grid_size() const { return grid_; }  // fine-grid points per direction
  // Node index at fine-grid address (i, j, k); -1 where no node exists (C3D20 face/body centres).
  int node_at(int i, int j, int k) const;
  // Node indices on the box face axis = side (side 0: min, 1: max).
  std::vector<int> face_nodes(int axis, int side) const;
  // Elements touching the face axis = side, with the local face index (0-based, S1 = 0).
  struct FaceRef {
    int element;
    int face;
  };
  std::vector<FaceRef> face_elements(int axis, int side) const;

 private:
  BoxSpec spec_;
  int step_ = 2;
  std::array<int, 3> grid_{};
  std::vector<int> node_index_;  // by fine-grid address, -1 = none
  std::vector<int> elements_;    // element indices, in (ex, ey, ez) order, ex fastest
};

}  // namespace styk::mesher
