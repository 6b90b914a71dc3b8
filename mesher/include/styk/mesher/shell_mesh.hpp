// Shell meshes (meshing only): a patch map (u, v in [-1, 1], geometry_maps.hpp) meshed into 4-,
// 8- or 9-node shells (S4/S4R, S8/S8R, S9/S9R; the node count is the formulation's), and three
// surfaces built on it: a flat plate, a cylindrical panel and a hemisphere with a hole at its
// pole (the surfaces of the shell obstacle course: the Scordelis-Lo roof, the pinched cylinder,
// the pinched hemisphere).
//
// Element nodes: corners counter-clockwise in (u, v), then the mid-side nodes of sides 1-2, 2-3,
// 3-4, 4-1, then (9 nodes) the centre, every node on the surface (the map evaluated at its
// (u, v)). The shell normal g1 x g2 is the right-hand normal of (u, v): +z for the plate, outward
// for the panel and the hemisphere. Sets (upper-case): element set `elset`, node set `elset` (every
// node) and the node sets of the patch sides SIDE1 (v = -1), SIDE2 (u = 1), SIDE3 (v = 1),
// SIDE4 (u = -1), each prefixed with `elset` and "_" (e.g. ROOF_SIDE1); a patch closed in u (a full
// cylinder or hemisphere) has no SIDE2 / SIDE4: its seam nodes are shared.
#pragma once

#include <string>

#include "styk/core/element_registry.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

struct ShellMeshSpec {
  std::string type = "S8R";  // a shell type the registry knows (TElement::form() == Shell)
  int divisions_u = 4;       // elements along u
  int divisions_v = 4;       // elements along v
  double grading_u = 1.0;    // last / first element length along u
  double grading_v = 1.0;
  std::string elset = "SHELL";
};

// Meshes `map` into shells. closed_u: map(1, v) == map(-1, v), the seam nodes are shared.
// Throws InputError (no location) for a type that is no shell of the registry, divisions < 1
// (< 3 around a closed patch) or gradings <= 0.
Mesh mesh_shell_patch(const PatchMap& map, const ShellMeshSpec& spec,
                      const ElementRegistry& registry, bool closed_u = false);

// The rectangle [0, a] x [0, b] in the x-y plane (u along x, v along y), normal +z.
Mesh shell_plate(double a, double b, const ShellMeshSpec& spec, const ElementRegistry& registry);

// A cylindrical panel of `radius` about the y axis, `length` along y from y = 0, spanning
// `angle_degrees` (0 < angle <= 360) symmetrically about +z: x = R sin(phi), z = R cos(phi),
// phi = u angle / 2; v along y. 360 degrees is the closed cylinder (closed in u).
Mesh shell_cylindrical_panel(double radius, double length, double angle_degrees,
                             const ShellMeshSpec& spec, const ElementRegistry& registry);

// A hemisphere of `radius` about the origin, pole on +z, with a hole of `hole_degrees` about the
// pole (0 < hole < 90; MacNeal-Harder's pinched hemisphere: 18), from the equator (v = -1) to the
// hole's edge (v = 1), over `sweep_degrees` of longitude from +x (0 < sweep <= 360; 90 is the
// benchmark's quarter, 360 closes it).
Mesh shell_hemisphere(double radius, double hole_degrees, double sweep_degrees,
                      const ShellMeshSpec& spec, const ElementRegistry& registry);

}  // namespace styk::mesher
