// The contact part of an increment group (docs/results.md, "contact"): per slave node status,
// area, pressure, shear, slip, gap, frame and force; per pair force and moment; the balance check.
#pragma once

#include <string>

#include "h5_util.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// Writes group "contact" under `increment` when inc.contact is not empty.
void write_contact(hid_t increment, const IncrementResult& inc);

// Reads it back if present (files of models without contact lack it). Node and pair indices are
// checked against the model.
void read_contact(hid_t increment, const std::string& label, const Model& model,
                  IncrementResult& inc);

}  // namespace styk::io
