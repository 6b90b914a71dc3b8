#include "gmsh_element_types.hpp"

#include <array>
#include <numeric>

namespace styk::gmsh {
namespace {

constexpr std::array<GmshType, 31> kTypes = {{
    {1, "2-node line", 1, 2},
    {2, "3-node triangle", 2, 3},
    {3, "4-node quadrangle", 2, 4},
    {4, "4-node tetrahedron", 3, 4},
    {5, "8-node hexahedron", 3, 8},
    {6, "6-node prism", 3, 6},
    {7, "5-node pyramid", 3, 5},
    {8, "3-node line", 1, 3},
    {9, "6-node triangle", 2, 6},
    {10, "9-node quadrangle", 2, 9},
    {11, "10-node tetrahedron", 3, 10},
    {12, "27-node hexahedron", 3, 27},
    {13, "18-node prism", 3, 18},
    {14, "14-node pyramid", 3, 14},
    {15, "1-node point", 0, 1},
    {16, "8-node quadrangle", 2, 8},
    {17, "20-node hexahedron", 3, 20},
    {18, "15-node prism", 3, 15},
    {19, "13-node pyramid", 3, 13},
    {20, "9-node triangle (incomplete cubic)", 2, 9},
    {21, "10-node triangle (cubic)", 2, 10},
    {22, "12-node triangle", 2, 12},
    {23, "15-node triangle", 2, 15},
    {24, "15-node triangle (incomplete)", 2, 15},
    {25, "21-node triangle", 2, 21},
    {26, "4-node line (cubic)", 1, 4},
    {27, "5-node line", 1, 5},
    {28, "6-node line", 1, 6},
    {29, "20-node tetrahedron (cubic)", 3, 20},
    {92, "64-node hexahedron (cubic)", 3, 64},
    {93, "125-node hexahedron (quartic)", 3, 125},
}};

std::vector<int> same_order(int count) {
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

// Gmsh numbers the edges of its second-order solids in its own order; CalculiX (Abaqus) walks
// the bottom face, then the top face, then the edges between them. Entry i is the Gmsh index of
// CalculiX node i (both 0-based), read off the two formats' node-numbering figures.
const std::vector<int> kTet10 = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
const std::vector<int> kHex20 = {0,  1, 2,  3,  4,  5,  6,  7,  8,  11,
                                 13, 9, 16, 18, 19, 17, 10, 12, 14, 15};
// Styk's C3D27 adds the face centres in face order S1..S6 (zeta -1, zeta +1, eta -1, xi +1,
// eta +1, xi -1) and the centre; Gmsh's are faces 0123, 0154, 0374, 1265, 2376, 4567.
const std::vector<int> kHex27 = {0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
                                 19, 17, 10, 12, 14, 15, 20, 25, 21, 23, 24, 22, 26};
const std::vector<int> kPrism15 = {0, 1, 2, 3, 4, 5, 6, 9, 7, 12, 14, 13, 8, 10, 11};
// A 3-node line: Gmsh ends then middle, CalculiX's B32 end, middle, end.
const std::vector<int> kLine3 = {0, 2, 1};

StykElementMapping planar_mapping(const GmshType& gmsh, const GmshImportOptions& options,
                                  std::string& why) {
  const bool quad4 = gmsh.number == 3, quad8 = gmsh.number == 16, quad9 = gmsh.number == 10;
  const bool tri3 = gmsh.number == 2;
  switch (options.planar) {
    case PlanarElements::Unset:
      why =
          "a surface mesh (its highest dimension is 2): say what its elements are with "
          "--planar cps|cpe|cax|shell";
      return {};
    case PlanarElements::Shell:
      if (quad4) return {"S4", same_order(4)};
      if (quad8) return {"S8", same_order(8)};
      if (quad9) return {"S9", same_order(9)};
      if (tri3) return {"STRI3", same_order(3)};
      why = "Styk has no shell of this kind (shells: S4, S8, S9, STRI3)";
      return {};
    case PlanarElements::PlaneStress:
    case PlanarElements::PlaneStrain:
    case PlanarElements::Axisymmetric: {
      const char* prefix = options.planar == PlanarElements::PlaneStress   ? "CPS"
                           : options.planar == PlanarElements::PlaneStrain ? "CPE"
                                                                           : "CAX";
      if (quad4) return {std::string(prefix) + "4", same_order(4)};
      if (quad8) return {std::string(prefix) + "8", same_order(8)};
      why = std::string("Styk's ") + prefix + " elements are quadrilaterals of 4 or 8 nodes (" +
            "mesh with Mesh.RecombineAll = 1 and Mesh.SecondOrderIncomplete = 1)";
      return {};
    }
  }
  return {};
}

}  // namespace

const GmshType* find_gmsh_type(int number) {
  for (const GmshType& type : kTypes)
    if (type.number == number) return &type;
  return nullptr;
}

StykElementMapping styk_mapping(const GmshType& gmsh, const GmshImportOptions& options,
                                std::string& why) {
  switch (gmsh.number) {
    case 4:
      return {"C3D4", same_order(4)};
    case 11:
      return {"C3D10", kTet10};
    case 5:
      return {"C3D8", same_order(8)};
    case 17:
      return {"C3D20", kHex20};
    case 12:
      return {"C3D27", kHex27};
    case 6:
      return {"C3D6", same_order(6)};
    case 18:
      return {"C3D15", kPrism15};
    case 1:
      return {options.lines == LineElements::Truss ? "T3D2" : "B31", same_order(2)};
    case 8:
      if (options.lines == LineElements::Truss) {
        why = "Styk's truss T3D2 has 2 nodes (use --lines beam for B32)";
        return {};
      }
      return {"B32", kLine3};
    case 2:
    case 3:
    case 10:
    case 16:
      return planar_mapping(gmsh, options, why);
    default:
      break;
  }
  if (gmsh.number == 7 || gmsh.number == 14 || gmsh.number == 19)
    why = "Styk has no pyramid (mesh without pyramids: only tetrahedra, or hexahedra and prisms)";
  else if (gmsh.number == 13)
    why = "Styk's wedge of second order has 15 nodes (Mesh.SecondOrderIncomplete = 1)";
  else
    why = "Styk has no element of this kind";
  return {};
}

}  // namespace styk::gmsh
