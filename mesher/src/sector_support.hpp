// Sector models of the cyclic joints (private to the mesher; docs/mesher.md, "Sector models"):
// cutting one sector out of a mesh, the cyclic symmetry tie between its two boundary planes
// (*TIE, CYCLIC SYMMETRY on node surfaces CYCLIC_SLAVE / CYCLIC_MASTER, *CYCLIC SYMMETRY MODEL
// about the z axis), and the supports a sector can carry.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher::detail {

// The boundary of a sector model: the nodes on its slave side (the boundary towards the
// previous sector; off the axis), on its master side (towards the next sector; off the axis), and
// on the axis. Sorted node indices.
struct SectorBoundary {
  int sectors = 0;
  std::vector<int> slave, master, axis;
  bool is_slave(int node) const;
  bool is_axis(int node) const;
};

// Mesh surfaces cut_sector() leaves: the sector's faces towards the previous and the next sector.
constexpr const char* kCyclicSlaveFaces = "CYCLIC_SLAVE_FACES";
constexpr const char* kCyclicMasterFaces = "CYCLIC_MASTER_FACES";

// Keeps the elements of a full mesh whose centroid lies in the sector theta0 <= theta <
// theta0 + 360/N about the z axis (and the nodes they use), renumbering element sets and
// surfaces, and records the faces it shares with the elements left out as the mesh surfaces
// kCyclicSlaveFaces (towards theta0) and kCyclicMasterFaces (towards theta0 + 360/N). The
// boundary need not be plane; the mesh must repeat itself N times about z (so that the element
// sets of the sectors are rotated copies of one another). Surfaces follow later splits and
// conversions, so the boundary is read from them at the end (sector_boundary).
void cut_sector(Mesh& mesh, int sectors, double theta0);

// The boundary nodes of a mesh cut by cut_sector (after any later steps): the nodes of the two
// face surfaces, those within `tolerance` of the z axis as axis nodes.
SectorBoundary sector_boundary(const Mesh& mesh, int sectors, double tolerance);

// Adds the mirror image of every element about the plane y = 0: new nodes at (x, -y, z), the
// image's numbering reflected in eta so that it stays right-handed, in the same element sets and
// surfaces (faces S3 and S5 swap). merge_coincident_nodes() then joins the halves along y = 0.
// C3D8 and C3D20 only (before any conversion).
void mirror_about_xz(Mesh& mesh);

// The faces of `mesh` lying on the half-plane at angle theta about z (all corners within
// `tolerance` of it, on its side of the axis).
std::vector<FaceRef> faces_on_half_plane(const Mesh& mesh, double theta, double tolerance);

// The cyclic symmetry tie of the sector (surfaces CYCLIC_SLAVE and CYCLIC_MASTER of TYPE=NODE,
// the axis nodes in both; *TIE NAME=CYCLIC; N sectors about the z axis).
void add_cyclic_symmetry(Model& model, const SectorBoundary& boundary);

// fix() for a sector: slave-side nodes are skipped (the tie makes them follow their master
// nodes, which are held), and a node on the axis keeps only dof 3 (the tie holds it on the axis).
void fix_in_sector(Model& model, const SectorBoundary& boundary, const std::vector<int>& nodes,
                   std::initializer_list<int> dofs);

}  // namespace styk::mesher::detail
