// The number formats of CalculiX's .dat file. Expected strings are copied from ccx 2.20 output
// (tests/unit/io/data/ccx_two_steps.dat) or follow the Fortran E edit descriptor rules.
#include <gtest/gtest.h>

#include "fortran_format.hpp"

namespace styk::io {
namespace {

TEST(FortranFormat, E13_6MatchesCcxValues) {
  EXPECT_EQ(fortran_e13_6(0.0), " 0.000000E+00");
  EXPECT_EQ(fortran_e13_6(-5.714286e-4), "-5.714286E-04");
  EXPECT_EQ(fortran_e13_6(1.904762e-3), " 1.904762E-03");
  EXPECT_EQ(fortran_e13_6(400.0), " 4.000000E+02");
  EXPECT_EQ(fortran_e13_6(3.177085e-19), " 3.177085E-19");
  EXPECT_EQ(fortran_e13_6(123456.789), " 1.234568E+05");  // rounds to 7 significant digits
}

TEST(FortranFormat, E13_6DropsTheLetterForThreeDigitExponents) {
  EXPECT_EQ(fortran_e13_6(1e-120), " 1.000000-120");
  EXPECT_EQ(fortran_e13_6(-2.5e200), "-2.500000+200");
}

TEST(FortranFormat, E14_7IsTheHeaderTimeFormat) {
  EXPECT_EQ(fortran_e14_7(1.0), " 0.1000000E+01");  // ccx: "and time  0.1000000E+01"
  EXPECT_EQ(fortran_e14_7(1.5), " 0.1500000E+01");  // ccx: "and time  0.1500000E+01"
  EXPECT_EQ(fortran_e14_7(0.0), " 0.0000000E+00");
  EXPECT_EQ(fortran_e14_7(0.05), " 0.5000000E-01");
  EXPECT_EQ(fortran_e14_7(-12.5), "-0.1250000E+02");
  EXPECT_EQ(fortran_e14_7(9.99999999), " 0.1000000E+02");  // rounding carries into the exponent
  EXPECT_EQ(fortran_e14_7(1e-100), " 0.1000000E-99");
  EXPECT_EQ(fortran_e14_7(1e-101), " 0.1000000-100");
}

}  // namespace
}  // namespace styk::io
