#include "styk/mesher/geometry_maps.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "styk/core/vec3.hpp"
#include "styk/mesher/hex_topology.hpp"

namespace styk::mesher {
namespace {

constexpr double kPi = 3.14159265358979323846;

using V3 = Eigen::Vector3d;

V3 unit(const V3& a) {
  const double n = a.norm();
  if (n == 0.0) throw std::invalid_argument("mesher: zero-length direction");
  return a / n;
}

// 1D quadratic Lagrange polynomials at -1, 0, +1.
void lagrange3(double s, double L[3]) {
  L[0] = 0.5 * s * (s - 1);
  L[1] = 1 - s * s;
  L[2] = 0.5 * s * (s + 1);
}

}  // namespace

std::vector<double> graded_parameters(int n, double ratio) {
  if (n < 1) throw std::invalid_argument("mesher: a line needs at least 1 division");
  if (!(ratio > 0.0)) throw std::invalid_argument("mesher: the bias ratio must be positive");
  const double q = n > 1 ? std::pow(ratio, 1.0 / (n - 1)) : 1.0;
  std::vector<double> t(n + 1, 0.0);
  double length = 1.0, total = 0.0;
  for (int i = 0; i < n; ++i) {
    total += length;
    t[i + 1] = total;
    length *= q;
  }
  for (double& v : t) v /= total;
  t[n] = 1.0;
  return t;
}

std::vector<Vec3> mesh_line(const Vec3& a, const Vec3& b, int n, double ratio) {
  std::vector<Vec3> out;
  for (double t : graded_parameters(n, ratio))
    out.push_back(to_vec3(as_eigen(a) + t * (as_eigen(b) - as_eigen(a))));
  return out;
}

PatchMap quad_map(const std::vector<Vec3>& control) {
  const std::size_t n = control.size();
  if (n != 4 && n != 8 && n != 9)
    throw std::invalid_argument("mesher: a patch needs 4, 8 or 9 control points");
  return [control, n](double u, double v) {
    static constexpr int kC[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    static constexpr int kM[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    double N[9] = {};
    if (n == 4) {
      for (int i = 0; i < 4; ++i) N[i] = 0.25 * (1 + kC[i][0] * u) * (1 + kC[i][1] * v);
    } else if (n == 8) {
      for (int i = 0; i < 4; ++i)
        N[i] = 0.25 * (1 + kC[i][0] * u) * (1 + kC[i][1] * v) * (kC[i][0] * u + kC[i][1] * v - 1);
      for (int i = 0; i < 4; ++i)
        N[4 + i] = kM[i][0] == 0 ? 0.5 * (1 - u * u) * (1 + kM[i][1] * v)
                                 : 0.5 * (1 + kM[i][0] * u) * (1 - v * v);
    } else {
      double Lu[3], Lv[3];
      lagrange3(u, Lu);
      lagrange3(v, Lv);
      for (int i = 0; i < 4; ++i) N[i] = Lu[kC[i][0] + 1] * Lv[kC[i][1] + 1];
      for (int i = 0; i < 4; ++i) N[4 + i] = Lu[kM[i][0] + 1] * Lv[kM[i][1] + 1];
      N[8] = Lu[1] * Lv[1];
    }
    V3 x = V3::Zero();
    for (std::size_t i = 0; i < n; ++i) x += N[i] * as_eigen(control[i]);
    return to_vec3(x);
  };
}

BlockMap hex_map(const std::vector<Vec3>& control) {
  const std::size_t n = control.size();
  if (n != 8 && n != 20 && n != 27)
    throw std::invalid_argument("mesher: a block needs 8, 20 or 27 control points");
  return [control, n](const Vec3& xi) {
    double N[27] = {};
    if (n == 8) {
      hex8_shape(xi, N);
    } else if (n == 20) {
      hex20_shape(xi, N);
    } else {
      // Lagrange 27: each control point's natural coordinates give its 1D factors.
      static const std::vector<Vec3> nat = [] {
        std::vector<Vec3> p = natural_nodes("C3D20");
        p.insert(p.end(),
                 {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 0}});
        return p;
      }();
      double L[3][3];
      for (int d = 0; d < 3; ++d) lagrange3(xi[d], L[d]);
      for (int i = 0; i < 27; ++i)
        N[i] = L[0][static_cast<int>(nat[i][0]) + 1] * L[1][static_cast<int>(nat[i][1]) + 1] *
               L[2][static_cast<int>(nat[i][2]) + 1];
    }
    V3 x = V3::Zero();
    for (std::size_t i = 0; i < n; ++i) x += N[i] * as_eigen(control[i]);
    return to_vec3(x);
  };
}

BlockMap revolve(const PatchMap& profile, const Vec3& origin, const Vec3& axis, double angle0,
                 double angle1) {
  const V3 k = unit(as_eigen(axis));
  return [profile, origin, k, angle0, angle1](const Vec3& xi) {
    const double angle = angle0 + 0.5 * (xi[2] + 1) * (angle1 - angle0);
    const V3 p = as_eigen(profile(xi[0], xi[1])) - as_eigen(origin);
    // Rodrigues' rotation of p about k.
    const double c = std::cos(angle), s = std::sin(angle);
    return to_vec3(as_eigen(origin) + c * p + s * k.cross(p) + (k.dot(p) * (1 - c)) * k);
  };
}

BlockMap sweep(const PatchMap& section, const PathMap& path, const Vec3& up,
               const std::function<double(double)>& twist) {
  return [section, path, up, twist](const Vec3& xi) {
    const double t = 0.5 * (xi[2] + 1);
    const double h = 1e-6;
    const V3 tangent =
        unit(as_eigen(path(std::min(1.0, t + h))) - as_eigen(path(std::max(0.0, t - h))));
    V3 ex = unit(as_eigen(up) - as_eigen(up).dot(tangent) * tangent);
    V3 ey = tangent.cross(ex);
    if (twist) {
      const double a = twist(t), c = std::cos(a), s = std::sin(a);
      const V3 rx = c * ex + s * ey;
      ey = -s * ex + c * ey;
      ex = rx;
    }
    const Vec3 local = section(xi[0], xi[1]);
    return to_vec3(as_eigen(path(t)) + local[0] * ex + local[1] * ey);
  };
}

BlockMap extrude(const PatchMap& patch, const Vec3& direction) {
  return [patch, direction](const Vec3& xi) {
    return to_vec3(as_eigen(patch(xi[0], xi[1])) + 0.5 * (xi[2] + 1) * as_eigen(direction));
  };
}

Vec3 p3g_point(double D, int n, double e, double v) {
  const double r = D / 2 - e * std::cos(n * v);
  const double s = n * e * std::sin(n * v);
  return {r * std::cos(v) - s * std::sin(v), r * std::sin(v) + s * std::cos(v), 0.0};
}

double spline_radius(double D, double d, double w, int N, double v) {
  const double pitch = 2 * kPi / N;
  double delta = std::fmod(v, pitch);
  if (delta < 0) delta += pitch;
  if (delta > pitch / 2) delta = pitch - delta;  // angle from the nearest spline centre line
  const double half = w / 2;
  if (D / 2 * std::sin(delta) <= half) return D / 2;  // on the spline tip
  if (d / 2 * std::sin(delta) >= half) return d / 2;  // on the root circle
  return half / std::sin(delta);                      // on a flank
}

}  // namespace styk::mesher
