// "Mesh block": what the dialog asks for, how it is checked, and the edit command it becomes.
// A hexahedral block is meshed with mesher/ and appended to the model (new node and element ids
// follow the largest existing ones). The element set NAME receives the elements; node sets and
// surfaces NAME_XMIN, NAME_XMAX, NAME_YMIN, ... the six block sides (the sides of the map:
// xi = -1 is XMIN, eta = -1 YMIN, zeta = -1 ZMIN).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "session/commands.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct BlockInput {
  bool use_corners = false;  // true: the 8 corners (C3D8 order); false: origin + size box
  std::array<Vec3, 8> corners{};
  Vec3 origin{0, 0, 0};
  Vec3 size{1, 1, 1};
  // Curved edges (SPEC §5 "8/20-node blocks"): empty = straight edges (the trilinear 8-point
  // map); otherwise the 12 mid-edge points in the C3D20 numbering of nodes 9-20 (edges 1-2, 2-3,
  // 3-4, 4-1, 5-6, 6-7, 7-8, 8-5, 1-5, 2-6, 3-7, 4-8 of the corners above or of the box), and the
  // block is meshed through the 20-point serendipity map: each edge is the quadratic through its
  // two corners and its mid-edge point.
  std::vector<Vec3> mid_edges{};
  std::array<int, 3> divisions{4, 1, 1};
  std::array<double, 3> grading{1, 1, 1};  // last / first element length per direction
  // C3D8, C3D20, or C3D21 / C3D28: C3D20 whose layer of elements on side `layer_side` becomes
  // the thesis' contact hexahedra.
  std::string type = "C3D20";
  std::string layer_side = "ZMAX";  // XMIN, XMAX, YMIN, YMAX, ZMIN, ZMAX
  std::string name = "BLOCK";
  std::string material;  // non-empty: also a solid section of the new set with this material
};

// The 8 corners of the block (the given corners, or those of the box), C3D8 order.
std::array<Vec3, 8> block_corners(const BlockInput& input);
// The midpoints of the 12 straight edges between those corners, C3D20 nodes 9-20: the mid-edge
// points that make a curved block equal to the straight one (the dialog's starting values).
std::vector<Vec3> straight_mid_edges(const BlockInput& input);

// Throws InputError for bad names, divisions, grading, size, type, layer side or material, and
// for curved edges: a count other than 12, a non-finite coordinate, or two of the 20 control
// points coinciding. A map that folds is found when meshing (model_with_block).
void check_block(const BlockInput& input, const Model& model, const ElementRegistry& registry);
// The model with the block appended. Throws InputError like check_block, for a map the mesher
// refuses (left-handed corners: "the mesher refuses the block: ..."), and for curved edges that
// fold the block ("the curved edges fold the block: ..." naming the element whose Jacobian is
// not positive).
Model model_with_block(const Model& model, const BlockInput& input,
                       const ElementRegistry& registry);
std::unique_ptr<Command> block_command(const Model& model, const BlockInput& input,
                                       const ElementRegistry& registry);

}  // namespace styk::gui
