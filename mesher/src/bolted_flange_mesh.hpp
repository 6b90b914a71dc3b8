// The mesh of the SPEC §4.6 bolted flange with gasket, 1/32 model (private to the mesher): the
// 22.5 deg sector 0 <= theta <= 22.5 deg about the pipe axis z, half the joint (z >= 0, the
// gasket's mid-plane z = 0 is a symmetry plane), the bolt on the sector plane theta = 0 (y = 0),
// cut through its axis (y >= 0 kept). Stand-in geometry of SPEC §4.6: flange Ø50/Ø165, ring 20
// thick (FlangeLayout::ring_thickness), neck Ø60/Ø50 rising 30; gasket Ø50/Ø108; bolt on PCD 130,
// hole Ø18, shank Ø14, head Ø24 x 10. docs/mesher.md ("Bolted flange") shows the block layout.
#pragma once

#include <string>

#include "styk/mesher/mesh.hpp"

namespace styk::mesher::detail {

struct FlangeLayout {
  double gasket_half = 2.5;    // half the gasket thickness (the model holds z = 0 .. gasket_half)
  double ring_thickness = 20;  // the flange ring's (its geometry is in the thesis' lost figure)
  int gasket_rings = 8;        // radial elements of the gasket (= flange elements above it)
  int neck_rings = 3;          // radial elements of the neck wall (part of gasket_rings)
  int ring_layers = 20;        // through the flange ring's thickness
  int neck_layers = 15;
  int gasket_layers = 3;  // through the half gasket
  int outer_rings = 1;    // radial elements between the bolt region and the rim
  int shank_layers = 6;   // bolt shank, mid-plane to the head
  int head_layers = 2;
};

// Geometry constants the builder and the tests share (mm, radians).
struct FlangeGeometry {
  static constexpr double kBore = 25, kNeckOuter = 30, kRim = 82.5, kGasketOuter = 54;
  static constexpr double kNeckHeight = 30;
  static constexpr double kPitchRadius = 65, kHoleRadius = 9, kShankRadius = 7;
  static constexpr double kHeadRadius = 12, kHeadHeight = 10;
  static constexpr double kSector = 3.14159265358979323846 / 8;  // 22.5 deg
};

// Head-bearing elements around the half hole (the 20 + 20 contact elements of SPEC) and the
// gasket's elements around the sector; fixed by the block layout.
constexpr int kAroundHole = 20;
constexpr int kGasketAround = 8;

// Meshes gasket, flange (ring + neck) and bolt (shank + head) with `type` (C3D8 or C3D20) into
// `mesh`, unmerged, in element sets GASKET, FLANGE and BOLT. Throws std::invalid_argument for a
// layout that cannot be meshed (neck_rings >= gasket_rings, counts < 1, ring_layers < 2).
void mesh_bolted_flange(Mesh& mesh, const std::string& type, const FlangeLayout& layout);

}  // namespace styk::mesher::detail
