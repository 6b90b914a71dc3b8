// The optional element results of an increment group (docs/results.md): ENER and THE at the
// integration points, EVOL, ELSE and ERR per element. Written only when the analysis filled them
// (an output request asked); files without them read back with the vectors empty.
#pragma once

#include <string>

#include "h5_util.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// What is wrong with the sizes of the increment's optional element results ("" when nothing is):
// the writer refuses such results before it touches the file.
std::string extras_size_problem(const Model& model, const IncrementResult& inc);

void write_extras(hid_t increment, const IncrementResult& inc);

// Reads what is present; sizes are checked against the model and the increment's ip_offset.
void read_extras(hid_t increment, const std::string& label, const Model& model,
                 IncrementResult& inc);

}  // namespace styk::io
