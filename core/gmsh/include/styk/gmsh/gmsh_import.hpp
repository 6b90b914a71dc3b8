// Import of Gmsh meshes (.msh, ASCII format 2.2 and 4.1, read from the format's published
// description) into a mesh-only Model that write_inp() turns into a CalculiX deck
// (`styk import`, docs/input.md "Importing Gmsh meshes").
#pragma once

#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk {

// What the mesh's elements become when its highest dimension is 2 (a surface mesh) or 1 (lines):
// Gmsh does not say whether a quadrilateral is a plane-stress plate, a ring section or a shell.
enum class PlanarElements { Unset, PlaneStress, PlaneStrain, Axisymmetric, Shell };
enum class LineElements { Beam, Truss };

struct GmshImportOptions {
  PlanarElements planar = PlanarElements::Unset;  // required for a 2-D mesh
  LineElements lines = LineElements::Beam;
};

struct GmshImportSummary {
  std::string format;                      // "2.2" or "4.1"
  int dimension = 0;                       // the highest element dimension: what became elements
  std::vector<std::string> element_types;  // Styk types written, in the order first met
  int lower_dimension_elements = 0;        // boundary elements that only gave node sets
  int unused_nodes = 0;                    // nodes of no imported element (left out)
};

// Reads the Gmsh mesh at `path`. The elements of the mesh's highest dimension become elements
// (Gmsh node order converted to CalculiX's); every physical group becomes a node set named by
// its physical name (upper-cased, characters other than letters, digits and _ replaced by _;
// unnamed groups "PHYSICAL<dim>D_<tag>"), and the physical groups of the highest dimension also
// element sets. EALL and NALL hold every element and node. Throws InputError at `path:line` for
// a malformed file, a binary file, and an element type Styk has no equivalent for (named).
Model import_gmsh(const std::string& path, const GmshImportOptions& options,
                  GmshImportSummary* summary = nullptr);

// The highest element dimension of the mesh at `path` (3 solids, 2 surfaces, 1 lines), so that a
// caller can ask what a surface mesh's elements are before importing it. Throws as import_gmsh().
int gmsh_mesh_dimension(const std::string& path);

}  // namespace styk
