// How each element type is drawn as a VTK cell: the cell type and which of the element's nodes,
// in which order, make the VTK cell's points.
#pragma once

#include <string>
#include <vector>

namespace styk::io {

struct VtkCellMapping {
  int vtk_type = 0;
  // node_order[k] = position (0-based) within the element of VTK point k. Its length is the
  // number of points of the VTK cell, which can be less than the element's node count.
  std::vector<int> node_order;
};

// nullptr when the type has no VTK cell (yet).
const VtkCellMapping* vtk_cell_mapping(const std::string& element_type);

}  // namespace styk::io
