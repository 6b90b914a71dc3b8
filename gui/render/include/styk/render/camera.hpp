// The camera: named views (iso, +x, -x, +y, -y, +z, -z), azimuth / elevation / zoom on top of
// them, orthographic or perspective projection, fitted to the model's bounds.
#pragma once

#include <array>
#include <string>

namespace styk::render {

using Mat4 = std::array<float, 16>;  // column-major, as OpenGL reads it

struct ViewSpec {
  std::string name =
      "iso";               // iso: from (1, -1, 1), z up; +x: from +x, z up; ...; +z: from +z, y up
  double azimuth = 0.0;    // degrees, turns the view about the screen's vertical axis
  double elevation = 0.0;  // degrees, raises the eye about the screen's horizontal axis
  double zoom = 1.0;       // > 1 enlarges the model
  bool perspective = false;
};

// Throws InputError listing the named views when `name` is not one of them.
void check_view_name(const std::string& name);

struct Camera {
  Mat4 view{};
  Mat4 projection{};
  std::array<float, 3> right{}, up{}, toward_eye{};  // unit vectors of the view, world frame
};

// Fits the box [lower, upper] into a viewport of the given aspect ratio (width / height) with a
// 5 % margin (before zoom).
Camera fit_camera(const ViewSpec& spec, const std::array<float, 3>& lower,
                  const std::array<float, 3>& upper, double aspect);

// Applies projection * view to a point; returns normalised device coordinates (x, y in -1..1).
std::array<float, 3> project(const Camera& camera, const std::array<float, 3>& point);

}  // namespace styk::render
