// What an element type tells the rest of Styk about itself besides its formulation: what it models
// (ElementForm), the VTK cell it is exported as (VtkCell) and how the mesher makes it from another
// type (ElementConversion). Everything that draws, exports or converts elements asks the
// TElement for these instead of keeping a table of type names, so a plug-in's element exports,
// draws and converts like a built-in one.
#pragma once

#include <string>
#include <vector>

namespace styk {

// What an element models, which decides how it is drawn and what its faces are.
enum class ElementForm {
  Solid,         // a 3D continuum element on (xi, eta, zeta); its faces are surfaces
  Planar,        // plane stress or plane strain in the x-y plane; its faces are its edges
  Axisymmetric,  // a ring: its section in the r-z plane (x = r, y = z) revolved about the y axis
  Line,          // a bar or beam along its nodes; no faces
  Shell,         // a surface with a thickness (its section); no faces for contact surfaces
};

// The name of a form for messages and listings ("solid", "planar", "axisymmetric", "line").
const char* form_name(ElementForm form);

// VTK cell type numbers (VTK file formats, "cell types").
namespace vtk {
constexpr int kLine = 3;
constexpr int kTriangle = 5;
constexpr int kQuad = 9;
constexpr int kTetra = 10;
constexpr int kHexahedron = 12;
constexpr int kWedge = 13;
constexpr int kQuadraticEdge = 21;
constexpr int kQuadraticTriangle = 22;
constexpr int kQuadraticQuad = 23;
constexpr int kQuadraticTetra = 24;
constexpr int kQuadraticHexahedron = 25;
constexpr int kQuadraticWedge = 26;
}  // namespace vtk

// The VTK cell an element is written as (VTU export): the cell type and, in VTK's point order, the
// element-local node indices that make its points. A cell may use fewer nodes than the element
// has (C3D27 and C3D21 are drawn as quadratic hexahedra of their first 20 nodes); the values at
// the other nodes stay in the point data.
struct VtkCell {
  int type = 0;
  std::vector<int> nodes;
};

// The cell of the element's first `count` nodes in their own order (the Abaqus/CalculiX numbering
// of hexahedra, tetrahedra, quadrilaterals and triangles is VTK's).
VtkCell vtk_first_nodes(int type, int count);

// How the mesher makes this type from a mesh of another one (mesher::convert_elements).
// - base: the type converted from; it must share this type's natural coordinates: every node of
//   the base type is a node of this type at the same natural point (C3D20 -> C3D21, C3D8 ->
//   C3D14, C3D20 -> C3D20R). The nodes this type has beyond them are placed on the base element's
//   geometry (its own shape functions) and shared between neighbours by position.
// - contact_face: the 0-based face of this type that a converted layer turns towards the
//   surface it is converted from (C3D21, C3D28: S1), or -1 when elements convert as they are
//   (every element of the base type, or the listed ones; C3D14, C3D20R).
struct ElementConversion {
  std::string base;
  int contact_face = -1;
};

}  // namespace styk
