#include "frd_elements.hpp"

#include "styk/core/element_description.hpp"

namespace styk::frd {
namespace {

std::vector<int> pick(const std::vector<int>& from, const std::vector<int>& order) {
  std::vector<int> picked;
  picked.reserve(order.size());
  for (int i : order) picked.push_back(from.at(i));
  return picked;
}

}  // namespace

FrdCell frd_cell(const TElement& element) {
  const VtkCell cell = element.vtk_cell();
  const std::vector<int>& v = cell.nodes;
  switch (cell.type) {
    case vtk::kHexahedron:
      return {1, v};
    // VTK's quadratic hexahedron is CalculiX's C3D20 order; the .frd puts the four edges
    // between the two faces (C3D20 nodes 17-20) before the top face's mid-edge nodes (13-16).
    case vtk::kQuadraticHexahedron:
      return {4, pick(v, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15})};
    case vtk::kTetra:
      return {3, v};
    case vtk::kQuadraticTetra:
      return {6, v};
    // VTK turns a wedge's triangles the other way round (element_description.cpp); the .frd
    // keeps CalculiX's order, and for 15 nodes, like he20, the edges between the triangles
    // (C3D15 nodes 13-15) before the top triangle's mid-edge nodes (10-12).
    case vtk::kWedge:
      return {2, pick(v, {0, 2, 1, 3, 5, 4})};
    case vtk::kQuadraticWedge: {
      const std::vector<int> calculix = pick(v, {0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13});
      return {5, pick(calculix, {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 13, 14, 9, 10, 11})};
    }
    case vtk::kTriangle:
      return {7, v};
    case vtk::kQuadraticTriangle:
      return {8, v};
    case vtk::kQuad:
      return {9, v};
    case vtk::kQuadraticQuad:
      return {10, v};
    case vtk::kLine:
      return {11, v};
    // VTK's quadratic edge is ends then middle; the .frd's be3 is end, middle, end.
    case vtk::kQuadraticEdge:
      return {12, pick(v, {0, 2, 1})};
    default:
      return {};
  }
}

}  // namespace styk::frd
