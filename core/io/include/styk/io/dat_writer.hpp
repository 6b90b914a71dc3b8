// The .dat text report, laid out exactly like CalculiX's (ccx 2.20) so the two can be diffed.
// Format details are in docs/results.md ("The .dat report").
#pragma once

#include <ostream>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk {

// For every increment of `results`, prints the *NODE PRINT (U, RF) and *EL PRINT (S, E) requests of
// that increment's step, in request order and, within a request, in variable order. *EL PRINT
// prints at the integration points, or with POSITION=CENTROIDAL / AVERAGED AT NODES the centroid
// values / the nodal method-I averages of the results (docs/results.md). An empty set
// name means the whole model and is printed as "ALL". Rows are sorted by node / element id, as
// ccx does. Throws InputError (at the request's source line) for an unknown set or a variable the
// .dat report cannot print, and std::runtime_error when the results lack a requested field.
// *CONTACT PRINT (CSTR, CDIS, CSTATUS) prints one row per constrained slave node, then each
// pair's total contact force and moment and the equilibrium check (docs/results.md).
void write_dat(std::ostream& out, const Model& model, const Results& results);

}  // namespace styk
