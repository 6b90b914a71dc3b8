// The axes of the unrolled contact map, drawn in the overlay: a frame round the map's extent,
// ticks at round values, their numbers, the axis names.
#include <algorithm>
#include <cmath>
#include <string>

#include "styk/render/unroll.hpp"

namespace styk::render {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

struct Axis {
  std::vector<double> at;           // map coordinates of the ticks
  std::vector<std::string> labels;  // their numbers
  std::string name;
};

// Ticks of an angle range in degrees: steps of 1, 2, 5, 10, 15, 30, 45 or 90 degrees.
std::vector<double> angle_ticks(double lo, double hi) {
  const double raw = (hi - lo) / 6.0;
  double step = 90.0;
  for (double s : {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0})
    if (s >= raw) {
      step = s;
      break;
    }
  if (raw < 1.0) return nice_ticks(lo, hi);
  // Ends within a thousandth of the range of a tick take it (an axis fitted to 1e-4 degrees).
  const double slack = 1e-3 * (hi - lo);
  std::vector<double> ticks;
  for (double t = std::ceil((lo - slack) / step) * step; t <= hi + slack; t += step)
    ticks.push_back(std::abs(t) < 1e-9 * step ? 0.0 : t);
  if (ticks.size() < 2) ticks = {lo, hi};
  return ticks;
}

Axis horizontal_axis(const UnrolledSurface& s) {
  Axis axis;
  if (s.kind == UnrolledSurface::Kind::Revolved) {
    const double lo = map_degrees(s, s.u_range[0]), hi = map_degrees(s, s.u_range[1]);
    for (double degrees : angle_ticks(lo, hi)) {
      axis.at.push_back((degrees - s.start_degrees) * kDegree * s.radius);
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%g\u00b0", degrees == 0.0 ? 0.0 : degrees);
      axis.labels.push_back(buffer);
    }
    axis.name = "angle";
    return axis;
  }
  const std::vector<double> ticks = nice_ticks(s.u_range[0], s.u_range[1]);
  const NumberFormat format =
      number_format(ticks.front(), ticks.back(), std::max<int>(1, int(ticks.size()) - 1));
  for (double u : ticks) axis.at.push_back(u), axis.labels.push_back(format(u));
  axis.name = s.first_name;
  return axis;
}

Axis vertical_axis(const UnrolledSurface& s) {
  Axis axis;
  const std::vector<double> ticks = nice_ticks(s.v_range[0], s.v_range[1]);
  const NumberFormat format =
      number_format(ticks.front(), ticks.back(), std::max<int>(1, int(ticks.size()) - 1));
  for (double v : ticks) axis.at.push_back(v), axis.labels.push_back(format(v));
  axis.name = s.kind == UnrolledSurface::Kind::Revolved ? "axial position" : s.second_name;
  return axis;
}

void add_box(Overlay& o, double x0, double y0, double x1, double y1, const Rgb& c) {
  const OverlayVertex a{float(x0), float(y0), {c.r, c.g, c.b}},
      b{float(x1), float(y0), {c.r, c.g, c.b}}, d{float(x1), float(y1), {c.r, c.g, c.b}},
      e{float(x0), float(y1), {c.r, c.g, c.b}};
  o.triangles.insert(o.triangles.end(), {a, b, d, a, d, e});
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / std::max(1, target);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  // Ends within a thousandth of the range of a tick take it.
  const double slack = 1e-3 * (hi - lo);
  std::vector<double> ticks;
  const double first = std::ceil((lo - slack) / step) * step;
  for (double t = first; t <= hi + slack; t += step)
    ticks.push_back(std::abs(t) < 1e-9 * step ? 0.0 : t);
  if (ticks.size() < 2) ticks = {lo, hi};
  return ticks;
}

void reserve_map_area(Overlay& o, Typeface& typeface, const UnrolledSurface& s, int height) {
  const int px = text_pixels_for(height);
  const int line = typeface.line_height(px);
  const Axis v = vertical_axis(s);
  int widest = 0;
  for (const std::string& label : v.labels)
    widest = std::max(widest, typeface.text_width(label, px));
  const int tick = std::max(4, px / 3);
  const int left = widest + tick + px, bottom = 2 * line + tick + px / 2, top = line + px / 2;
  const int right = px * 2;
  PixelRect& m = o.model;
  m = PixelRect{m.x + left, m.y + top, std::max(1, m.width - left - right),
                std::max(1, m.height - top - bottom)};
}

void add_map_axes(Overlay& o, Typeface& typeface, const Camera& camera, const UnrolledSurface& s,
                  int height) {
  const int px = text_pixels_for(height);
  const int line = typeface.line_height(px);
  const int tick = std::max(4, px / 3);
  const PixelRect& m = o.model;
  const auto pixel = [&](double u, double v) {
    const std::array<float, 3> ndc = project(camera, {float(u), float(v), 0.0f});
    return std::array<double, 2>{m.x + (ndc[0] + 1.0) * 0.5 * m.width,
                                 m.y + (1.0 - ndc[1]) * 0.5 * m.height};
  };
  const std::array<double, 2> low = pixel(s.u_range[0], s.v_range[0]);
  const std::array<double, 2> high = pixel(s.u_range[1], s.v_range[1]);
  const double x0 = std::round(low[0]), x1 = std::round(high[0]);
  const double y0 = std::round(high[1]), y1 = std::round(low[1]);  // top, bottom
  // The frame, one pixel outside the map's extent.
  add_box(o, x0 - 1, y0 - 1, x1 + 1, y0, kInk);
  add_box(o, x0 - 1, y1, x1 + 1, y1 + 1, kInk);
  add_box(o, x0 - 1, y0 - 1, x0, y1 + 1, kInk);
  add_box(o, x1, y0 - 1, x1 + 1, y1 + 1, kInk);
  const Axis h = horizontal_axis(s), v = vertical_axis(s);
  for (std::size_t k = 0; k < h.at.size(); ++k) {
    const double x = std::round(pixel(h.at[k], s.v_range[0])[0]);
    add_box(o, x - 0.5, y1 + 1, x + 0.5, y1 + 1 + tick, kInk);
    const int w = typeface.text_width(h.labels[k], px);
    add_overlay_text(o, typeface, TextItem{h.labels[k], int(x) - w / 2, int(y1) + tick + 2, px},
                     kInk);
  }
  const int name_w = typeface.text_width(h.name, px);
  add_overlay_text(o, typeface,
                   TextItem{h.name, int((x0 + x1) / 2) - name_w / 2, int(y1) + tick + 2 + line, px},
                   kInk);
  for (std::size_t k = 0; k < v.at.size(); ++k) {
    const double y = std::round(pixel(s.u_range[0], v.at[k])[1]);
    add_box(o, x0 - 1 - tick, y - 0.5, x0 - 1, y + 0.5, kInk);
    const int w = typeface.text_width(v.labels[k], px);
    add_overlay_text(o, typeface,
                     TextItem{v.labels[k], int(x0) - 3 - tick - w, int(y) - line / 2, px}, kInk);
  }
  add_overlay_text(o, typeface, TextItem{v.name, int(x0), int(y0) - line - 2, px}, kInk);
  refresh_atlas(o, typeface);
}

}  // namespace styk::render
