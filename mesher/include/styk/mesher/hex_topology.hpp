// Node layouts of the hexahedra the mesher produces (C3D8, C3D20, C3D14, C3D21, C3D28, C3D27;
// C3D8R/C3D8I are C3D8 and C3D20R is C3D20), following elements-ref/README.md, and the geometry of
// the C3D8/C3D20 maps. The mesher needs them without an element registry: it writes elements, it
// does not integrate them.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk::mesher {

// Natural coordinates of the element's nodes, in its numbering. Throws std::invalid_argument for
// a type the mesher does not know.
const std::vector<Vec3>& natural_nodes(const std::string& type);

// Axis (0 = xi, 1 = eta, 2 = zeta) and value (-1/+1) of 0-based face f (Abaqus S1..S6).
struct FaceAxis {
  int axis;
  int value;
};
FaceAxis face_axis(int face);
// 0-based face on the given axis and side (-1/+1).
int face_index(int axis, int value);

// Local node indices on face f (all nodes of the face, in element order), and its corners.
std::vector<int> face_local_nodes(const std::string& type, int face);
std::vector<int> face_corner_nodes(int face);  // the 4 of nodes 0..7

// Shape functions of the 8-node trilinear and 20-node serendipity hexahedra at xi.
void hex8_shape(const Vec3& xi, double N[8]);
void hex20_shape(const Vec3& xi, double N[20]);

// The point at natural coordinates xi of a C3D8/C3D20 element (given node coordinates in its
// numbering): used to place the extra nodes of converted elements on the C3D20 geometry.
Vec3 map_point(const std::string& type, const std::vector<Vec3>& element_coords, const Vec3& xi);

// A proper rotation of the reference cube (a signed permutation matrix with det +1).
using CubeRotation = std::array<std::array<int, 3>, 3>;
// The rotation R with old = R * new such that the new face S1 (zeta = -1) is the old face `face`.
CubeRotation rotation_to_bottom(int face);
// Applies R to natural coordinates.
Vec3 rotate(const CubeRotation& R, const Vec3& xi);
// Permutation p (new local index -> old local index) of an element of `type` re-oriented by R.
std::vector<int> rotated_numbering(const std::string& type, const CubeRotation& R);
// The new 0-based face index of old face `old_face` after re-orientation by R.
int rotated_face(const CubeRotation& R, int old_face);

}  // namespace styk::mesher
