// Export of the mesh and one increment to a VTK XML UnstructuredGrid file (.vtu) for ParaView.
// Hand-written, no VTK needed: data arrays are inline base64 ("binary", UInt64 headers).
#pragma once

#include <map>
#include <string>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk {

// What write_vtu() could not represent: element types with no VTK cell, and how many elements of
// each were left out of the file. Callers print it as a warning.
struct VtuExportSummary {
  int cells_written = 0;
  std::map<std::string, int> skipped_by_type;
};

// The VTK cell type Styk exports an element type as, or -1 when there is none. Some types are
// drawn with fewer nodes than they have (documented in docs/results.md, "VTU export").
int vtk_cell_type_for(const std::string& element_type);

// Writes the mesh and, when `inc` is not null, its point data (U, RF; the nodal stresses
// S_nodal_I, S_nodal_II and their Mises values when the increment holds them; contact output
// CPRESS, CSHEAR, CSLIP, CGAP, CSTATUS when it holds any, NaN away from slave nodes) and cell
// data (S_ip_mean: stress averaged over the element's integration points, S_ip_mean_mises: von
// Mises of that mean).
// Every element gets its id in the cell array "element_id". Elements whose type has no VTK cell
// are skipped and counted in the returned summary. Writes `path + ".tmp"` and renames it. Throws
// std::runtime_error when the file cannot be written or `inc` does not match the model's sizes.
VtuExportSummary write_vtu(const std::string& path, const Model& model, const IncrementResult* inc);

}  // namespace styk
