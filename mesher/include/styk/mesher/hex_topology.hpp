// Node layouts of the bricks the mesher meshes blocks with (C3D8, C3D20: the Abaqus numbering) and
// their shape functions, which the block maps use. Every other type (converted or split) is
// described by its own TElement, through the registry the conversions are given.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk::mesher {

// Natural coordinates of the nodes of C3D8 or C3D20, in its numbering. Throws
// std::invalid_argument for any other type.
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

// A proper rotation of the reference cube (a signed permutation matrix with det +1).
using CubeRotation = std::array<std::array<int, 3>, 3>;
// Applies R to natural coordinates.
Vec3 rotate(const CubeRotation& R, const Vec3& xi);

}  // namespace styk::mesher
