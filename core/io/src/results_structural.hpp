// The structural part of the results file (docs/results.md): per increment the nodal rotations
// UR and reaction moments RM of models whose nodes carry rotations, and the section forces SF and
// moments SM of beam elements at their stations. All written only when present, so the files of
// solid models are unchanged; files without them read as empty fields.
#pragma once

#include <string>

#include "h5_util.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// Datasets "UR", "RM" (nodes x 3), "station_offsets" (elements + 1), "SF", "SM" (stations x 3)
// under `increment` when the increment holds them.
void write_structural(hid_t increment, const IncrementResult& inc);

// Reads them back if present; sizes are checked against the model.
void read_structural(hid_t increment, const std::string& label, const Model& model,
                     IncrementResult& inc);

// Size checks before anything is written: "" when consistent, else what is wrong.
std::string structural_size_error(const Model& model, const IncrementResult& inc);

}  // namespace styk::io
