#include "styk/render/camera.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include <Eigen/Geometry>

#include "styk/core/diagnostics.hpp"

namespace styk::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

using D3 = Eigen::Vector3d;

D3 unit(const D3& a) {
  const double l = a.norm();
  return l > 0 ? D3(a / l) : a;
}

// Rodrigues: v turned by angle (radians) about the unit axis k.
D3 rotate(const D3& v, const D3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * k.cross(v) + (k.dot(v) * (1 - c)) * k;
}

struct NamedView {
  D3 toward_eye;
  D3 up;
};

const std::map<std::string, NamedView>& named_views() {
  static const std::map<std::string, NamedView> kViews = {
      {"iso", {{1, -1, 1}, {0, 0, 1}}}, {"+x", {{1, 0, 0}, {0, 0, 1}}},
      {"-x", {{-1, 0, 0}, {0, 0, 1}}},  {"+y", {{0, 1, 0}, {0, 0, 1}}},
      {"-y", {{0, -1, 0}, {0, 0, 1}}},  {"+z", {{0, 0, 1}, {0, 1, 0}}},
      {"-z", {{0, 0, -1}, {0, 1, 0}}},
  };
  return kViews;
}

std::string canonical(std::string name) {
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (name.size() == 1 && (name[0] == 'x' || name[0] == 'y' || name[0] == 'z')) name = "+" + name;
  return name;
}

Mat4 look_at(const D3& eye, const D3& right, const D3& up, const D3& back) {
  Mat4 m{};
  m[0] = float(right.x()), m[4] = float(right.y()), m[8] = float(right.z());
  m[1] = float(up.x()), m[5] = float(up.y()), m[9] = float(up.z());
  m[2] = float(back.x()), m[6] = float(back.y()), m[10] = float(back.z());
  m[12] = float(-right.dot(eye)), m[13] = float(-up.dot(eye)), m[14] = float(-back.dot(eye));
  m[15] = 1.0f;
  return m;
}

Mat4 orthographic(double half_w, double half_h, double near, double far) {
  Mat4 m{};
  m[0] = float(1.0 / half_w);
  m[5] = float(1.0 / half_h);
  m[10] = float(-2.0 / (far - near));
  m[14] = float(-(far + near) / (far - near));
  m[15] = 1.0f;
  return m;
}

Mat4 perspective(double fovy, double aspect, double near, double far) {
  Mat4 m{};
  const double f = 1.0 / std::tan(fovy / 2);
  m[0] = float(f / aspect);
  m[5] = float(f);
  m[10] = float((far + near) / (near - far));
  m[11] = -1.0f;
  m[14] = float(2 * far * near / (near - far));
  return m;
}

}  // namespace

void check_view_name(const std::string& name) {
  if (named_views().count(canonical(name))) return;
  std::string known;
  for (const auto& entry : named_views()) known += (known.empty() ? "" : ", ") + entry.first;
  throw InputError({}, "unknown view '" + name + "'; views: " + known);
}

Camera fit_camera(const ViewSpec& spec, const std::array<float, 3>& lower,
                  const std::array<float, 3>& upper, double aspect) {
  check_view_name(spec.name);
  const NamedView& named = named_views().at(canonical(spec.name));
  D3 back = unit(named.toward_eye);
  D3 right = unit(named.up.cross(back));
  D3 up = back.cross(right);
  // Azimuth about the screen's vertical, then elevation about the (new) horizontal axis; the
  // whole frame turns, so looking straight down never loses its "up".
  const double az = spec.azimuth * kPi / 180.0, el = spec.elevation * kPi / 180.0;
  back = rotate(back, up, az), right = rotate(right, up, az);
  back = rotate(back, right, -el), up = rotate(up, right, -el);

  const D3 lo(lower[0], lower[1], lower[2]), hi(upper[0], upper[1], upper[2]);
  const D3 centre = 0.5 * (lo + hi);
  double radius = 0.5 * (hi - lo).norm();
  if (!(radius > 0)) radius = 1.0;
  double half_x = 0, half_y = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const D3 p(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(),
               corner & 4 ? hi.z() : lo.z());
    half_x = std::max(half_x, std::abs((p - centre).dot(right)));
    half_y = std::max(half_y, std::abs((p - centre).dot(up)));
  }
  const double zoom = spec.zoom > 0 ? spec.zoom : 1.0;
  Camera camera;
  if (!spec.perspective) {
    double half_h = std::max(half_y, half_x / aspect) * 1.05 / zoom;
    if (!(half_h > 0)) half_h = radius;
    const D3 eye = centre + (3.0 * radius) * back;
    camera.view = look_at(eye, right, up, back);
    camera.projection = orthographic(half_h * aspect, half_h, 0.5 * radius, 5.5 * radius);
  } else {
    const double fovy = 30.0 * kPi / 180.0;
    const double half_fov = std::min(fovy / 2, std::atan(std::tan(fovy / 2) * aspect));
    const double distance = radius * 1.05 / std::sin(half_fov);
    const D3 eye = centre + distance * back;
    camera.view = look_at(eye, right, up, back);
    const double zoomed = 2.0 * std::atan(std::tan(fovy / 2) / zoom);
    camera.projection =
        perspective(zoomed, aspect, std::max(distance - 1.1 * radius, 1e-3 * distance),
                    distance + 1.1 * radius);
  }
  camera.right = {float(right.x()), float(right.y()), float(right.z())};
  camera.up = {float(up.x()), float(up.y()), float(up.z())};
  camera.toward_eye = {float(back.x()), float(back.y()), float(back.z())};
  return camera;
}

std::array<float, 3> project(const Camera& camera, const std::array<float, 3>& p) {
  const auto apply = [](const Mat4& m, const std::array<float, 4>& v) {
    std::array<float, 4> r{};
    for (int i = 0; i < 4; ++i)
      r[i] = m[i] * v[0] + m[4 + i] * v[1] + m[8 + i] * v[2] + m[12 + i] * v[3];
    return r;
  };
  const auto clip = apply(camera.projection, apply(camera.view, {p[0], p[1], p[2], 1.0f}));
  return {clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3]};
}

}  // namespace styk::render
