// The extent of each section's elements: the largest side of the bounding box of their nodes.
// The beam and shell warnings estimate how much of the bending a locked element can spoil from
// its size against the size of the structure it belongs to; the span the structure bends over
// is not known before solving, and the section's extent is the measure a check can take (a
// symmetric model's span is up to twice its extent, which the warnings' thresholds allow for).
#pragma once

#include <vector>

#include "styk/core/model.hpp"

namespace styk::solver_detail {

// By section index; 0 for sections no element uses.
std::vector<double> section_extents(const Model& model);

}  // namespace styk::solver_detail
