// .dat blocks beyond U, RF, S and E (docs/results.md): the element energies, volumes and
// centrifugal loads of *EL PRINT (ENER, ELSE, EVOL, CENT) and the *SECTION PRINT statistics, laid
// out as ccx 2.20 prints them.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::io {

// Whether `var` is one of the *EL PRINT variables print_element_extra() prints.
bool is_element_extra(const std::string& var);

// One *EL PRINT variable ENER (per integration point), ELSE, EVOL or CENT (per element) for the
// elements (indices, id order) of the request's set named `set`; TOTALS=YES adds the sum (ELSE,
// EVOL), TOTALS=ONLY prints the sum alone.
void print_element_extra(std::ostream& out, const Model& model, const OutputRequest& request,
                         const std::string& var, const std::string& set,
                         const std::vector<int>& elements, const IncrementResult& inc);

// The statistics block of a *SECTION PRINT request.
void print_section(std::ostream& out, const OutputRequest& request, const IncrementResult& inc);

}  // namespace styk::io
