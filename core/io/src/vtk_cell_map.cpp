// Node orders: Abaqus/CalculiX number the corners of a hexahedron 1-4 (bottom, counter-clockwise
// seen from the top) and 5-8 (top), then the mid-edge nodes of the bottom (1-2, 2-3, 3-4, 4-1),
// the top (5-6, 6-7, 7-8, 8-5) and the vertical edges (1-5, 2-6, 3-7, 4-8). VTK_HEXAHEDRON and
// VTK_QUADRATIC_HEXAHEDRON use exactly that order (0-based), as do the quadrilaterals, triangles
// and tetrahedra below; only the 3-node line differs (Abaqus puts the middle node second, VTK
// last).
#include <map>
#include <numeric>

#include "styk/io/vtu_export.hpp"
#include "vtk_cell_map.hpp"

namespace styk::io {

namespace {

enum VtkType : int {
  kLine = 3,
  kTriangle = 5,
  kQuad = 9,
  kTetra = 10,
  kHexahedron = 12,
  kQuadraticEdge = 21,
  kQuadraticTriangle = 22,
  kQuadraticQuad = 23,
  kQuadraticTetra = 24,
  kQuadraticHexahedron = 25,
};

VtkCellMapping first_nodes(int vtk_type, int count) {
  VtkCellMapping m{vtk_type, std::vector<int>(count)};
  std::iota(m.node_order.begin(), m.node_order.end(), 0);
  return m;
}

std::map<std::string, VtkCellMapping> build_table() {
  std::map<std::string, VtkCellMapping> table;
  auto add = [&](std::initializer_list<const char*> names, const VtkCellMapping& m) {
    for (const char* name : names) table[name] = m;
  };
  add({"C3D8", "C3D8R", "C3D8I", "C3D8R0", "C3D8H", "DC3D8"}, first_nodes(kHexahedron, 8));
  add({"C3D20", "C3D20R", "C3D20H", "DC3D20"}, first_nodes(kQuadraticHexahedron, 20));
  // Drawn with a subset of their nodes (their values at the other nodes stay in the point data):
  // C3D27 and C3D21 start with the 20 C3D20 nodes; C3D14 and C3D28 start with the 8 corners.
  add({"C3D27", "C3D21"}, first_nodes(kQuadraticHexahedron, 20));
  add({"C3D14", "C3D28"}, first_nodes(kHexahedron, 8));
  add({"C3D4", "DC3D4"}, first_nodes(kTetra, 4));
  add({"C3D10", "DC3D10"}, first_nodes(kQuadraticTetra, 10));
  add({"CPS3", "CPE3", "CAX3"}, first_nodes(kTriangle, 3));
  add({"CPS6", "CPE6", "CAX6"}, first_nodes(kQuadraticTriangle, 6));
  add({"CPS4", "CPE4", "CPS4R", "CPE4R", "CAX4", "CAX4R"}, first_nodes(kQuad, 4));
  add({"CPS8", "CPE8", "CPS8R", "CPE8R", "CAX8", "CAX8R"}, first_nodes(kQuadraticQuad, 8));
  // Shells as their reference surface; S9's centre node stays in the point data.
  add({"S4", "S4R"}, first_nodes(kQuad, 4));
  add({"S8", "S8R", "S9", "S9R"}, first_nodes(kQuadraticQuad, 8));
  add({"T3D2", "B21", "B31", "B31R"}, first_nodes(kLine, 2));
  add({"T3D3", "B22", "B32", "B32R"}, VtkCellMapping{kQuadraticEdge, {0, 2, 1}});
  return table;
}

}  // namespace

const VtkCellMapping* vtk_cell_mapping(const std::string& element_type) {
  static const std::map<std::string, VtkCellMapping> table = build_table();
  const auto it = table.find(element_type);
  return it == table.end() ? nullptr : &it->second;
}

}  // namespace styk::io

namespace styk {

int vtk_cell_type_for(const std::string& element_type) {
  const io::VtkCellMapping* m = io::vtk_cell_mapping(element_type);
  return m == nullptr ? -1 : m->vtk_type;
}

}  // namespace styk
