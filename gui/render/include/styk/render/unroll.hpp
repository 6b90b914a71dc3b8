// The unrolled contact map: a surface field (contact pressure, shear, slip, gap, status) laid flat,
// over (angle, axial position) for a cylindrical or conical surface, or over two in-plane axes for
// a flat one: how the pressure along a fit is read in practice. The surface's axis is fitted to
// the drawn faces' normals or given.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/font.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/overlay.hpp"

namespace styk::render {

struct UnrollAxis {
  Vec3 point{};      // a point of the axis
  Vec3 direction{};  // any length but zero
};

// "PX,PY,PZ,DX,DY,DZ" (six numbers, commas or blanks); InputError otherwise or for a zero
// direction.
UnrollAxis parse_unroll_axis(const std::string& text);

struct UnrolledSurface {
  enum class Kind { Revolved, Flat };
  Kind kind = Kind::Revolved;
  bool axis_given = false;
  // Revolved: the axis (unit direction, its largest component positive, and its point nearest the
  // global origin, so that axial positions are coordinates along the axis). Flat: the plane's
  // centre and unit normal.
  UnrollAxis axis;
  // Revolved: unit direction of angle 0, normal to the axis (the global x or y axis projected).
  // Flat: the map's horizontal and vertical axes, in the plane (global axes projected, in order
  // x, y, z, leaving out the one nearest the normal).
  Vec3 first{}, second{};
  std::string first_name, second_name;  // Flat: "x", "y", "z" or with a prime when projected
  double radius = 0.0;                  // Revolved: mean distance of the surface from the axis
  double start_degrees = 0.0;           // Revolved: the angle at the map's left edge
  double fit_error = 0.0;  // RMS miss of the face normals from the axis, / radius (Revolved)
  // The map's extent: u horizontal (Revolved: radius x angle, Flat: along `first`), v vertical
  // (axial position along the axis / along `second`), both in model lengths.
  std::array<double, 2> u_range{}, v_range{};
};

// Fits the surface of `faces` (a FrameGeometry of the field's faces alone, undeformed, relative to
// `origin`): Flat when the normals spread by less than 1 degree, otherwise the axis whose lines
// the normals cross (cylinders and cones). A given axis makes it Revolved about that axis.
// InputError when the surface is neither (the normals miss the fitted axis by more than 5 % of the
// radius) or has no faces.
UnrolledSurface fit_unrolled_surface(const FrameGeometry& faces, const Vec3& origin,
                                     const std::optional<UnrollAxis>& given);

// The map's geometry: every triangle of `faces` laid flat at z = 0 (u, v as above, normals +z,
// the same colours and scale positions), triangles that the angle's cut would split moved whole to
// one side; edges and feature lines likewise. The origin is (0, 0, 0) of the map.
FrameGeometry unroll_geometry(const FrameGeometry& faces, const Vec3& origin,
                              const UnrolledSurface& surface);

// The angle in degrees of map coordinate u (Revolved).
inline double map_degrees(const UnrolledSurface& s, double u) {
  return s.start_degrees + u / s.radius * 57.29577951308232;
}

// The map's axes in the overlay: build_overlay() first, then map_area() takes the room for the
// tick labels off the overlay's model area (where the map is drawn; fit the camera to it), then
// add_map_axes() draws a frame round the map's extent with ticks at round values (angles in
// degrees, lengths in model units) and the axis names, using the camera the map is drawn with.
void reserve_map_area(Overlay& overlay, Typeface& typeface, const UnrolledSurface& surface,
                      int height);
void add_map_axes(Overlay& overlay, Typeface& typeface, const Camera& camera,
                  const UnrolledSurface& surface, int height);

// Round tick values covering [lo, hi]: steps of 1, 2 or 5 times a power of ten, about `target`
// of them (at least 2 ticks when lo < hi).
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

}  // namespace styk::render
