// The structural part of `styk check` (results_check.cpp), beyond what the reader itself refuses:
// group names that agree with the step and increment attributes, times that never run backwards,
// sorted sets, contact rows that point at existing pairs.
#pragma once

#include <hdf5.h>

#include "styk/io/results_check.hpp"
#include "styk/io/results_file.hpp"

namespace styk::io {

// Adds a problem to `report` for each inconsistency; fills report.steps and report.increments.
void check_structure(hid_t file, const ResultsFileContents& contents, ResultsCheck& report);

}  // namespace styk::io
