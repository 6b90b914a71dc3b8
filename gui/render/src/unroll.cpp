#include "styk/render/unroll.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <vector>

#include "styk/core/diagnostics.hpp"

namespace styk::render {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFlatSpread = 0.0175;  // normals within 1 degree: a plane
constexpr double kRevolvedMiss = 0.05;  // normals' RMS miss of the axis, / radius

using V = Eigen::Vector3d;

V to_v(const Vec3& p) { return V(p[0], p[1], p[2]); }
Vec3 to_vec(const V& v) { return {v.x(), v.y(), v.z()}; }

// The field faces' vertices: absolute positions and unit normals.
struct Samples {
  std::vector<V> points, normals;
};

Samples collect(const FrameGeometry& faces, const Vec3& origin) {
  Samples s;
  const V o = to_v(origin);
  for (const Vertex& v : faces.face_vertices) {
    const V n(v.normal[0], v.normal[1], v.normal[2]);
    if (n.norm() < 0.5) continue;  // degenerate grid point
    s.points.push_back(V(v.position[0], v.position[1], v.position[2]) + o);
    s.normals.push_back(n.normalized());
  }
  return s;
}

// The global axes projected into the plane normal to `n`, leaving out the one nearest `n`.
void plane_axes(const V& n, UnrolledSurface& out) {
  const char* names[3] = {"x", "y", "z"};
  int skip = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[skip])) skip = k;
  std::vector<int> keep;
  for (int k = 0; k < 3; ++k)
    if (k != skip) keep.push_back(k);
  // A plane normal to a global axis shows the other two as they are; a slanted one their
  // projections, primed.
  const bool slanted = std::abs(std::abs(n[skip]) - 1.0) > 1e-9;
  const auto projected = [&](int k, std::string& name) {
    V e = V::Unit(k);
    e -= e.dot(n) * n;
    name = std::string(names[k]) + (slanted ? "'" : "");
    return e.normalized();
  };
  const V first = projected(keep[0], out.first_name);
  V second = projected(keep[1], out.second_name);
  second = (second - second.dot(first) * first).normalized();  // orthogonal on a slanted plane
  out.first = to_vec(first);
  out.second = to_vec(second);
}

// The axis point: in the plane normal to `a`, the centre c of the circles the surface's points
// lie on, their radius changing linearly along the axis (a cone; constant: a cylinder). With p
// the point's in-plane position and s its axial one, |p - c|^2 = (r0 + k s)^2 is linear in
// (c, r0^2 - |c|^2, 2 r0 k, k^2): |p|^2 = 2 c.p + A + B s + C s^2, solved by least squares.
// Exact for points on a cylinder or cone, whatever the faces' normals (a quadratic face's normals
// lean off the radius by up to 1e-3 rad, a point no fit of normal lines would give exactly).
void fit_axis_point(const Samples& s, const V& a, UnrolledSurface& out) {
  V e1 = V::UnitX() - a.x() * a;
  if (e1.norm() < 0.1) e1 = V::UnitY() - a.y() * a;
  e1.normalize();
  const V e2 = a.cross(e1);
  Eigen::MatrixXd M(s.points.size(), 5);
  Eigen::VectorXd rhs(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const double x = s.points[i].dot(e1), y = s.points[i].dot(e2), z = s.points[i].dot(a);
    M.row(static_cast<Eigen::Index>(i)) << 2 * x, 2 * y, 1.0, z, z * z;
    rhs(static_cast<Eigen::Index>(i)) = x * x + y * y;
  }
  const Eigen::VectorXd c = M.colPivHouseholderQr().solve(rhs);
  out.axis.point = to_vec(c(0) * e1 + c(1) * e2);
}

// A fitted axis carries the error of the fit (curved faces are drawn from polynomial shapes: a
// C3D21 cylinder's normals miss the true axis by some 1e-6 of the radius): components below 1e-5
// of the scale are zero, so an axis along z reads (0, 0, 1) through (0, 0, 0).
V snapped(V v, double scale) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(v[k]) < 1e-5 * scale) v[k] = 0.0;
  return v;
}

// The point of the axis nearest the global origin: axial positions are then the model's own
// coordinate along the axis (z for an axis along z).
V axis_point_nearest_origin(const V& point, const V& a) { return point - point.dot(a) * a; }

double angle_of(const UnrolledSurface& s, const V& p) {
  const V a = to_v(s.axis.direction), z = to_v(s.first);
  const V d = p - to_v(s.axis.point);
  return std::atan2(d.dot(a.cross(z)), d.dot(z));
}

// Radius, fit error, the angle range (the map starts after the largest gap between the faces'
// angles) and the extents.
void measure_revolved(const Samples& s, UnrolledSurface& out) {
  const V a = to_v(out.axis.direction), p = to_v(out.axis.point);
  V zero = V::UnitX() - a.x() * a;
  if (zero.norm() < 0.1) zero = V::UnitY() - a.y() * a;
  out.first = to_vec(zero.normalized());
  double radius = 0.0, miss = 0.0;
  std::vector<double> angles;
  out.v_range = {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const V d = s.points[i] - p;
    const V radial = d - d.dot(a) * a;
    radius += radial.norm() / double(s.points.size());
    // Distance of the normal's line from the axis, in the plane normal to the axis.
    V m = s.normals[i] - s.normals[i].dot(a) * a;
    if (m.norm() > 0.1) {
      m.normalize();
      miss += (radial - radial.dot(m) * m).squaredNorm();
    }
    angles.push_back(angle_of(out, s.points[i]));
    const double axial = d.dot(a);
    out.v_range = {std::min(out.v_range[0], axial), std::max(out.v_range[1], axial)};
  }
  out.radius = radius;
  out.fit_error = radius > 0 ? std::sqrt(miss / double(s.points.size())) / radius : 1.0;
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * kPi - angles.back(), start = angles.front();
  for (std::size_t i = 1; i < angles.size(); ++i)
    if (angles[i] - angles[i - 1] > gap) gap = angles[i] - angles[i - 1], start = angles[i];
  // A start within a hair of a whole degree is that degree (a quarter model starts at 0, not
  // -1e-9).
  double degrees = start * 180.0 / kPi;
  if (std::abs(degrees - std::round(degrees)) < 1e-6) degrees = std::round(degrees);
  out.start_degrees = degrees;
  const double span = 2 * kPi - gap;
  out.u_range = {0.0, radius * span};
}

}  // namespace

UnrollAxis parse_unroll_axis(const std::string& text) {
  std::string cleaned = text;
  std::replace(cleaned.begin(), cleaned.end(), ',', ' ');
  std::istringstream in(cleaned);
  std::vector<double> numbers;
  for (std::string word; in >> word;) {
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value))
      throw InputError({}, "bad unroll axis '" + text + "': '" + word + "' is not a number");
    numbers.push_back(value);
  }
  if (numbers.size() != 6)
    throw InputError({}, "bad unroll axis '" + text +
                             "': give a point and a direction, six numbers PX,PY,PZ,DX,DY,DZ");
  UnrollAxis axis{{numbers[0], numbers[1], numbers[2]}, {numbers[3], numbers[4], numbers[5]}};
  if (std::hypot(numbers[3], numbers[4], numbers[5]) == 0.0)
    throw InputError({}, "bad unroll axis '" + text + "': the direction is zero");
  return axis;
}

UnrolledSurface fit_unrolled_surface(const FrameGeometry& faces, const Vec3& origin,
                                     const std::optional<UnrollAxis>& given) {
  const Samples s = collect(faces, origin);
  if (s.points.empty())
    throw InputError({}, "nothing to unroll: no face carries the field in the shown layers");
  UnrolledSurface out;
  if (given) {
    V a = to_v(given->direction).normalized();
    out.kind = UnrolledSurface::Kind::Revolved;
    out.axis_given = true;
    out.axis = {to_vec(axis_point_nearest_origin(to_v(given->point), a)), to_vec(a)};
    measure_revolved(s, out);
    return out;
  }
  V mean = V::Zero();
  for (const V& n : s.normals) mean += n / double(s.normals.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const V& n : s.normals)
    spread += (n - mean) * (n - mean).transpose() / double(s.normals.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(spread);
  if (std::sqrt(std::max(0.0, eigen.eigenvalues()(2))) < kFlatSpread) {
    out.kind = UnrolledSurface::Kind::Flat;
    const V n = mean.normalized();
    V centre = V::Zero();
    for (const V& p : s.points) centre += p / double(s.points.size());
    out.axis = {to_vec(centre), to_vec(n)};
    plane_axes(n, out);
    out.u_range = {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
    out.v_range = out.u_range;
    for (const V& p : s.points) {
      const double u = p.dot(to_v(out.first)), v = p.dot(to_v(out.second));
      out.u_range = {std::min(out.u_range[0], u), std::max(out.u_range[1], u)};
      out.v_range = {std::min(out.v_range[0], v), std::max(out.v_range[1], v)};
    }
    return out;
  }
  V a = eigen.eigenvectors().col(0).normalized();
  int largest = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(a[k]) > std::abs(a[largest])) largest = k;
  if (a[largest] < 0) a = -a;
  a = snapped(a, 1.0).normalized();
  out.kind = UnrolledSurface::Kind::Revolved;
  out.axis.direction = to_vec(a);
  fit_axis_point(s, a, out);
  // Snap the point relative to the surface's size (its distance from the axis, at most).
  double size = 0.0;
  for (const V& p : s.points) size = std::max(size, (p - to_v(out.axis.point)).norm());
  out.axis.point = to_vec(axis_point_nearest_origin(snapped(to_v(out.axis.point), size), a));
  measure_revolved(s, out);
  if (out.fit_error > kRevolvedMiss) {
    throw InputError({},
                     "the surface carrying the field is neither flat nor a surface of "
                     "revolution: its normals miss the best-fitting axis by " +
                         std::to_string(int(std::lround(100.0 * out.fit_error))) +
                         " % of its radius; give the axis (--unroll-axis PX,PY,PZ,DX,DY,DZ) "
                         "or show one fit (--contact-pair)");
  }
  return out;
}

FrameGeometry unroll_geometry(const FrameGeometry& faces, const Vec3& origin,
                              const UnrolledSurface& surface) {
  FrameGeometry map;
  const V o = to_v(origin);
  const bool revolved = surface.kind == UnrolledSurface::Kind::Revolved;
  const V a = to_v(surface.axis.direction), p = to_v(surface.axis.point);
  const double start = surface.start_degrees * kPi / 180.0;
  // Map coordinates of consecutive points of one primitive: angles unwrapped from the first one,
  // the primitive shifted whole so that its first angle lies in [start, start + 2 pi).
  const auto flatten = [&](const std::vector<const Vertex*>& group, std::vector<Vertex>& out) {
    std::vector<std::array<double, 2>> uv;
    double previous = 0.0, shift = 0.0;
    for (std::size_t k = 0; k < group.size(); ++k) {
      const Vertex& v = *group[k];
      const V x = V(v.position[0], v.position[1], v.position[2]) + o;
      if (!revolved) {
        uv.push_back({x.dot(to_v(surface.first)), x.dot(to_v(surface.second))});
        continue;
      }
      double angle = angle_of(surface, x);
      if (k == 0) {
        double first = angle;
        while (first < start - 1e-9) first += 2 * kPi;
        while (first >= start + 2 * kPi - 1e-9) first -= 2 * kPi;
        shift = first - angle;
      } else {
        while (angle + shift - previous > kPi) angle -= 2 * kPi;
        while (angle + shift - previous < -kPi) angle += 2 * kPi;
      }
      previous = angle + shift;
      uv.push_back({surface.radius * (previous - start), (x - p).dot(a)});
    }
    for (std::size_t k = 0; k < group.size(); ++k) {
      Vertex v = *group[k];
      v.position[0] = float(uv[k][0]), v.position[1] = float(uv[k][1]), v.position[2] = 0.0f;
      if (v.normal[0] != 0.0f || v.normal[1] != 0.0f || v.normal[2] != 0.0f)
        v.normal[0] = 0.0f, v.normal[1] = 0.0f, v.normal[2] = 1.0f;
      out.push_back(v);
    }
  };
  for (std::size_t t = 0; t + 2 < faces.triangles.size(); t += 3) {
    const auto base = static_cast<std::uint32_t>(map.face_vertices.size());
    flatten({&faces.face_vertices[faces.triangles[t]], &faces.face_vertices[faces.triangles[t + 1]],
             &faces.face_vertices[faces.triangles[t + 2]]},
            map.face_vertices);
    // Seen from +z of the map the surface's outside may face either way: wind every triangle
    // clockwise on the map (GL_CW front), so none is culled (the map is never `closed`).
    const float* q0 = map.face_vertices[base].position;
    const float* q1 = map.face_vertices[base + 1].position;
    const float* q2 = map.face_vertices[base + 2].position;
    const double area = (q1[0] - q0[0]) * (q2[1] - q0[1]) - (q2[0] - q0[0]) * (q1[1] - q0[1]);
    if (area > 0)
      map.triangles.insert(map.triangles.end(), {base, base + 2, base + 1});
    else
      map.triangles.insert(map.triangles.end(), {base, base + 1, base + 2});
  }
  const auto lines = [&](const std::vector<Vertex>& in, std::vector<Vertex>& out) {
    for (std::size_t k = 0; k + 1 < in.size(); k += 2) flatten({&in[k], &in[k + 1]}, out);
  };
  lines(faces.edges, map.edges);
  lines(faces.features, map.features);
  map.closed = false;
  const float big = std::numeric_limits<float>::max();
  map.lower = {big, big, 0.0f};
  map.upper = {-big, -big, 0.0f};
  for (const Vertex& v : map.face_vertices)
    for (int k = 0; k < 2; ++k) {
      map.lower[k] = std::min(map.lower[k], v.position[k]);
      map.upper[k] = std::max(map.upper[k], v.position[k]);
    }
  if (map.face_vertices.empty()) map.lower = map.upper = {0, 0, 0};
  return map;
}

}  // namespace styk::render
