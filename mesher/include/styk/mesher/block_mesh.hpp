// Structured meshing of mapped blocks and patches with per-direction density and grading.
// Nodes sit on a "fine" grid (step 1 for C3D8, 2 for C3D20: mid-edge nodes at the parameter
// midpoints of each element), which gives every node a grid address (i, j, k).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

struct BlockSpec {
  std::string type = "C3D20";                    // C3D8 or C3D20
  std::array<int, 3> divisions{1, 1, 1};         // elements along xi, eta, zeta
  std::array<double, 3> grading{1.0, 1.0, 1.0};  // last / first element length per direction
  std::string elset;                             // element set receiving the block ("" = none)
};

class Block {
 public:
  Block(int step, std::array<int, 3> divisions, std::vector<int> node_index,
        std::vector<int> elements);
  int step() const { return step_; }
  std::array<int, 3> divisions() const { return divisions_; }
  std::array<int, 3> grid_size() const { return grid_; }
  // Node at fine-grid address (i, j, k); -1 outside or where C3D20 has no node.
  int node_at(int i, int j, int k) const;
  int element_at(int ex, int ey, int ez) const;
  const std::vector<int>& elements() const { return elements_; }
  // Nodes on the block side axis = value (value -1: min, +1: max).
  std::vector<int> side_nodes(int axis, int value) const;
  // The element faces forming that block side.
  std::vector<FaceRef> side_faces(int axis, int value) const;

 private:
  int step_;
  std::array<int, 3> divisions_;
  std::array<int, 3> grid_{};
  std::vector<int> node_index_;
  std::vector<int> elements_;
};

// Meshes the block map into `mesh` (new nodes; merge coincident ones with
// merge_coincident_nodes() after adding neighbouring blocks). Throws std::invalid_argument for
// a bad type, divisions < 1, or a left-handed map (negative Jacobian at the first element).
Block mesh_block(Mesh& mesh, const BlockMap& map, const BlockSpec& spec);

// A quadrilateral mesh of a patch (the 2D pre-processor's plane meshing): 4-node (order 1) or
// 8-node (order 2) quads, nodes in the quadrilateral numbering of quad_map().
struct PatchMesh {
  std::vector<Vec3> nodes;
  std::vector<std::vector<int>> quads;
};
PatchMesh mesh_patch(const PatchMap& map, int nu, int nv, double grading_u = 1.0,
                     double grading_v = 1.0, int order = 1);

}  // namespace styk::mesher
