// Names what a value of a results-file dataset belongs to ("node 17, component 2", "element 3,
// integration point 5"), so a refusal points at the entity and not only at a row number. Works
// on any open results file (also one being written: the mesh and the index datasets come first).
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>

#include "h5_integrity.hpp"

namespace styk::io {

// "node 17", "element 3, integration point 5", "contact slave node 12", "row 4" when the row
// cannot be matched to an entity. Never throws: a file too damaged to look up ids gives "row r".
std::string describe_row(hid_t file, const std::string& dataset_path, std::uint64_t row);

// "dataset /steps/step_1/increment_1/S: element 1, integration point 3, component 2 is nan (4
// values of the dataset are not finite numbers)" or "attribute total_time of /steps/...: is inf".
std::string describe_non_finite(hid_t file, const h5::NonFiniteError& error);

}  // namespace styk::io
