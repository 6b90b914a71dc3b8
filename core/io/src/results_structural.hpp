// The structural part of the results file (docs/results.md): per increment the nodal rotations
// UR and reaction moments RM of models whose nodes carry rotations, and the section forces SF and
// moments SM of beam elements at their stations; in /model the beam sections (shape, dimensions,
// first section axis, integration) and the shell sections (thickness, offset), which the renderer
// extrudes. All written only when present,
// so the files of solid models are unchanged; files without them read as empty fields.
#pragma once

#include <string>

#include "h5_util.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// Datasets "UR", "RM" (nodes x 3), "station_offsets" (elements + 1), "SF", "SM" (stations x 3)
// and "SFQ" (stations x 2: shells' Q13, Q23) under `increment` when the increment holds them.
void write_structural(hid_t increment, const IncrementResult& inc);

// Reads them back if present; sizes are checked against the model.
void read_structural(hid_t increment, const std::string& label, const Model& model,
                     IncrementResult& inc);

// Size checks before anything is written: "" when consistent, else what is wrong.
std::string structural_size_error(const Model& model, const IncrementResult& inc);

// Group "beam_sections" under `mesh` with one row per *BEAM SECTION of the model (none: no group).
void write_beam_sections(hid_t mesh, const Model& model);

// Rebuilds those sections (elset, shape, dimensions, direction, integration; no material) and
// assigns them to the elements of their sets. The element sets must have been read.
void read_beam_sections(hid_t mesh, const SourceLoc& where, Model& model);

// Group "shell_sections" under `mesh` with one row per *SHELL SECTION (elset, thickness, offset,
// section points; none: no group), so that the renderer draws the shells' thickness.
void write_shell_sections(hid_t mesh, const Model& model);

// Rebuilds those sections (no material) and assigns them to the elements of their sets.
void read_shell_sections(hid_t mesh, const SourceLoc& where, Model& model);

// Group "shell_normals" under `mesh` with one row per given nodal normal of a shell (*NORMAL, or
// fields 5-7 of *NODE; none: no group), so that the renderer draws the normals the solver used.
void write_shell_normals(hid_t mesh, const Model& model);

// Rebuilds Model::normals in their order (a later row wins, as a later *NORMAL line does).
void read_shell_normals(hid_t mesh, const SourceLoc& where, Model& model);

}  // namespace styk::io
