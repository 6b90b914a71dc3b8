// The scalar-field part of an increment group (docs/results.md, "scalar"): the nodal temperature or
// potential, reaction flows, gradient and flux at the integration points, nodal fluxes.
#pragma once

#include <string>

#include "h5_util.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// Writes group "scalar" under `increment` when inc.scalar.kind is not None.
void write_scalar(hid_t increment, const IncrementResult& inc);

// Reads it back if present (files of mechanical analyses lack it); sizes are checked against the
// model and the increment's ip_offset.
void read_scalar(hid_t increment, const std::string& label, const Model& model,
                 IncrementResult& inc);

}  // namespace styk::io
