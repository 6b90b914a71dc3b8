#include "fortran_format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace styk::io {

namespace {

std::string right_aligned(std::string text, std::size_t width) {
  if (text.size() < width) text.insert(0, width - text.size(), ' ');
  return text;
}

// Fortran writes exponents of three digits without the letter: mantissa, sign, three digits.
std::string exponent_suffix(int exponent) {
  char buffer[16];
  if (std::abs(exponent) >= 100)
    std::snprintf(buffer, sizeof buffer, "%c%03d", exponent < 0 ? '-' : '+', std::abs(exponent));
  else
    std::snprintf(buffer, sizeof buffer, "E%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
  return buffer;
}

}  // namespace

std::string fortran_e13_6(double value) {
  if (!std::isfinite(value))
    return right_aligned(std::isnan(value) ? "NaN" : (value < 0 ? "-Infinity" : "Infinity"), 13);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6E", value);  // -d.ddddddE+xx or ...E+xxx
  std::string text(buffer);
  const std::size_t e = text.find('E');
  return right_aligned(text.substr(0, e) + exponent_suffix(std::atoi(text.c_str() + e + 1)), 13);
}

std::string fortran_e14_7(double value) {
  if (!std::isfinite(value))
    return right_aligned(std::isnan(value) ? "NaN" : (value < 0 ? "-Infinity" : "Infinity"), 14);
  if (value == 0.0)
    return right_aligned(std::signbit(value) ? "-0.0000000E+00" : "0.0000000E+00", 14);
  // d.ddddddE+xx carries the same 7 significant digits as 0.dddddddE+(xx+1).
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6E", std::fabs(value));
  const std::string text(buffer);
  const std::size_t e = text.find('E');
  const std::string digits = text.substr(0, 1) + text.substr(2, e - 2);
  const int exponent = std::atoi(text.c_str() + e + 1) + 1;
  return right_aligned((value < 0 ? "-0." : "0.") + digits + exponent_suffix(exponent), 14);
}

}  // namespace styk::io
