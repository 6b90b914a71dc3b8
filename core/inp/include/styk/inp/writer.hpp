// Writes a Model as an Abaqus/CalculiX keyword deck that read_inp() reads back to an equivalent
// model and that CalculiX (ccx) accepts when the model uses only standard element types.
#pragma once

#include <ostream>

#include "styk/core/model.hpp"

namespace styk {

// Doubles are written with 17 significant digits so the round trip is exact.
void write_inp(const Model& model, std::ostream& out);

}  // namespace styk
