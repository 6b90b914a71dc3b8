// Export of the mesh and one increment to a VTK XML UnstructuredGrid file (.vtu) for ParaView.
// Hand-written, no VTK needed: data arrays are inline base64 ("binary", UInt64 headers).
#pragma once

#include <string>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk {

// What write_vtu() wrote.
struct VtuExportSummary {
  int cells_written = 0;
};

// Writes the mesh and, when `inc` is not null, its point data (U, RF; the nodal stresses
// S_nodal_I, S_nodal_II and their Mises values when the increment holds them; contact output
// CPRESS, CSHEAR, CSLIP, CGAP, CSTATUS when it holds any, NaN away from slave nodes) and cell
// data (S_ip_mean: stress averaged over the element's integration points, S_ip_mean_mises: von
// Mises of that mean). Every element gets its id in the cell array "element_id". Each element is
// written as the VTK cell its formulation describes (TElement::vtk_cell()), so plug-in elements
// export like built-in ones. Nothing is left out: an element whose type `registry` does not know,
// or whose formulation has no VTK cell, is an InputError at the element's line naming the type,
// and no file is written. Writes `path + ".tmp"` and renames it. Throws std::runtime_error when
// the file cannot be written or `inc` does not match the model's sizes.
VtuExportSummary write_vtu(const std::string& path, const Model& model,
                           const ElementRegistry& registry, const IncrementResult* inc);

}  // namespace styk
