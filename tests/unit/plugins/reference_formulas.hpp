// The shape functions as printed in elements-ref/README.md (corrected thesis formulas for C3D14
// and C3D21 N5-N8, the closed forms of the derived C3D28), typed in independently of the plug-in
// code, which uses the compact/blending forms. Values only; 0-based node index.
#pragma once

#include <cmath>

#include "styk/core/model.hpp"

namespace styk::test {

// elements-ref section 2, N1..N14 of C3D14 (N4 and N6 corrected).
inline double c3d14_printed(int i, const Vec3& p) {
  const double x = p[0], e = p[1], z = p[2];
  switch (i) {
    case 0:
      return (x * e + x * z + 2 * x + e * z + 2 * e + 2 * z + 2) * (x - 1) * (e - 1) * (z - 1) / 8;
    case 1:
      return (x * e + x * z + 2 * x - e * z - 2 * e - 2 * z - 2) * (x + 1) * (e - 1) * (z - 1) / 8;
    case 2:
      return (x * e - x * z - 2 * x - e * z - 2 * e + 2 * z + 2) * (x + 1) * (e + 1) * (z - 1) / 8;
    case 3:
      return (x * e - x * z - 2 * x + e * z + 2 * e - 2 * z - 2) * (x - 1) * (e + 1) * (z - 1) / 8;
    case 4:
      return -(x * e - x * z + 2 * x - e * z + 2 * e - 2 * z + 2) * (x - 1) * (e - 1) * (z + 1) / 8;
    case 5:
      return -(x * e - x * z + 2 * x + e * z - 2 * e + 2 * z - 2) * (x + 1) * (e - 1) * (z + 1) / 8;
    case 6:
      return -(x * e + x * z - 2 * x + e * z - 2 * e - 2 * z + 2) * (x + 1) * (e + 1) * (z + 1) / 8;
    case 7:
      return -(x * e + x * z - 2 * x - e * z + 2 * e + 2 * z - 2) * (x - 1) * (e + 1) * (z + 1) / 8;
    case 8:
      return (1 - x * x) * (1 - e * e) * (1 - z) / 2;
    case 9:
      return (1 - x * x) * (1 - e * e) * (1 + z) / 2;
    case 10:
      return (1 - x * x) * (1 - e) * (1 - z * z) / 2;
    case 11:
      return (1 - x * x) * (1 + e) * (1 - z * z) / 2;
    case 12:
      return (1 - x) * (1 - e * e) * (1 - z * z) / 2;
    case 13:
      return (1 + x) * (1 - e * e) * (1 - z * z) / 2;
  }
  return NAN;
}

// elements-ref section 3: the corrected top corners N5..N8 of C3D21 (i = 4..7) and N21 (i = 20).
inline double c3d21_printed(int i, const Vec3& p) {
  const double x = p[0], e = p[1], z = p[2];
  switch (i) {
    case 4:
      return ((1 - x) * (1 - e) * (1 + z) - (1 - x) * (1 - e * e) * (1 + z) -
              (1 - x * x) * (1 - e) * (1 + z) - (1 - x) * (1 - e) * (1 - z * z)) /
             8;
    case 5:
      return ((1 + x) * (1 - e) * (1 + z) - (1 - x * x) * (1 - e) * (1 + z) -
              (1 + x) * (1 - e * e) * (1 + z) - (1 + x) * (1 - e) * (1 - z * z)) /
             8;
    case 6:
      return ((1 + x) * (1 + e) * (1 + z) - (1 - x * x) * (1 + e) * (1 + z) -
              (1 + x) * (1 - e * e) * (1 + z) - (1 + x) * (1 + e) * (1 - z * z)) /
             8;
    case 7:
      return ((1 - x) * (1 + e) * (1 + z) - (1 - x * x) * (1 + e) * (1 + z) -
              (1 - x) * (1 - e * e) * (1 + z) - (1 - x) * (1 + e) * (1 - z * z)) /
             8;
    case 20:
      return (1 - x * x) * (1 - e * e) * z * (z - 1) / 2;
  }
  return NAN;
}

// elements-ref section 4: the closed forms of all 28 C3D28 functions; (xi_i, eta_i) are the node
// coordinates, 5 xi_i = +-sqrt(5) for the GLL nodes.
inline double c3d28_closed_form(int i, const Vec3& node, const Vec3& p) {
  const double x = p[0], e = p[1], z = p[2], xi = node[0], ei = node[1];
  if (i < 4)
    return (1 + xi * x) * (1 + ei * e) * (1 - z) *
           ((5 * x * x - 1) * (5 * e * e - 1) - 16 * (1 + z)) / 128;
  if (i < 8) return (1 + xi * x) * (1 + ei * e) * (1 + z) * (xi * x + ei * e + z - 2) / 8;
  if (i < 12) return (1 + xi * x) * (1 + ei * e) * (1 - z * z) / 4;
  if (i < 16)
    return xi == 0 ? (1 - x * x) * (1 + ei * e) * (1 + z) / 4
                   : (1 + xi * x) * (1 - e * e) * (1 + z) / 4;
  if (i < 24) {
    if (std::abs(ei) == 1.0)  // nodes 17, 18, 21, 22
      return 5.0 / 128 * (1 - x * x) * (1 + 5 * xi * x) * (1 + ei * e) * (5 * e * e - 1) * (1 - z);
    return 5.0 / 128 * (1 + xi * x) * (5 * x * x - 1) * (1 - e * e) * (1 + 5 * ei * e) * (1 - z);
  }
  return 25.0 / 128 * (1 - x * x) * (1 - e * e) * (1 + 5 * xi * x) * (1 + 5 * ei * e) * (1 - z);
}

}  // namespace styk::test
