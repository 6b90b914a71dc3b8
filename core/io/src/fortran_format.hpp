// Number formats of CalculiX's .dat file (gfortran edit descriptors), reproduced with printf so
// the two reports can be compared character by character.
#pragma once

#include <string>

namespace styk::io {

// Fortran "1P,E13.6": d.ddddddE+xx right-aligned in 13 columns, e.g. "-5.714286E-04". Exponents
// of three digits drop the 'E' as Fortran does ("1.000000-100").
std::string fortran_e13_6(double value);

// Fortran "E14.7" (no scale factor): 0.dddddddE+xx right-aligned in 14 columns, e.g.
// " 0.1000000E+01" — the format of the time in block headers.
std::string fortran_e14_7(double value);

}  // namespace styk::io
