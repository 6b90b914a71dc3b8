// Section constants of the standard beam sections. Closed forms: Roark/Timoshenko for areas,
// moments of inertia and torsion (the rectangle's Saint-Venant series, the ellipse's exact J,
// Bredt for the thin-walled box); shear correction factors of Cowper (1966) at nu = 0, i.e. the
// classical ones: 5/6 for the rectangle, 6/7 for the solid circle (used for the ellipse),
// 6 (1 + m^2)^2 / (7 (1 + m^2)^2 + 20 m^2) for the pipe (m = r_i / r_o: 1/2 for a thin wall); the
// box takes the area of the walls parallel to the shear.
#include "styk/core/beam_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// Saint-Venant torsion constant of a solid rectangle (series, converged to round-off).
double rectangle_torsion(double a, double b) {
  const double longer = std::max(a, b), shorter = std::min(a, b);
  double sum = 0.0;
  for (int n = 1; n <= 61; n += 2)
    sum += std::tanh(n * kPi * longer / (2.0 * shorter)) / std::pow(static_cast<double>(n), 5);
  return longer * std::pow(shorter, 3) / 3.0 *
         (1.0 - 192.0 / std::pow(kPi, 5) * shorter / longer * sum);
}

BeamSectionProperties rect(double a, double b) {
  BeamSectionProperties p;
  p.area = a * b;
  p.I11 = a * b * b * b / 12.0;
  p.I22 = b * a * a * a / 12.0;
  p.J = rectangle_torsion(a, b);
  p.shear_area1 = p.shear_area2 = 5.0 / 6.0 * p.area;
  p.fibres = {{{a / 2, b / 2}, {-a / 2, b / 2}, {-a / 2, -b / 2}, {a / 2, -b / 2}}};
  // The St. Venant shear stress vanishes at the corners of a rectangle.
  return p;
}

BeamSectionProperties ellipse(double d1, double d2) {
  const double p1 = d1 / 2.0, p2 = d2 / 2.0;
  BeamSectionProperties p;
  p.area = kPi * p1 * p2;
  p.I11 = kPi * p1 * p2 * p2 * p2 / 4.0;
  p.I22 = kPi * p1 * p1 * p1 * p2 / 4.0;
  p.J = kPi * std::pow(p1 * p2, 3) / (p1 * p1 + p2 * p2);
  p.shear_area1 = p.shear_area2 = 6.0 / 7.0 * p.area;
  p.fibres = {{{p1, 0.0}, {0.0, p2}, {-p1, 0.0}, {0.0, -p2}}};
  // Exact St. Venant stresses of the ellipse: tau1 = -2 T x2 / (pi p1 p2^3),
  // tau2 = 2 T x1 / (pi p1^3 p2).
  for (int k = 0; k < 4; ++k) {
    const SectionPoint& x = p.fibres[k];
    p.torsion_shear_per_torque[k] = {-2.0 * x[1] / (kPi * p1 * p2 * p2 * p2),
                                     2.0 * x[0] / (kPi * p1 * p1 * p1 * p2)};
  }
  return p;
}

BeamSectionProperties pipe(double r, double t) {
  const double ri = r - t, m = ri / r, m2 = m * m;
  BeamSectionProperties p;
  p.area = kPi * (r * r - ri * ri);
  p.I11 = p.I22 = kPi * (std::pow(r, 4) - std::pow(ri, 4)) / 4.0;
  p.J = 2.0 * p.I11;
  const double k = 6.0 * (1 + m2) * (1 + m2) / (7.0 * (1 + m2) * (1 + m2) + 20.0 * m2);
  p.shear_area1 = p.shear_area2 = k * p.area;
  p.fibres = {{{r, 0.0}, {0.0, r}, {-r, 0.0}, {0.0, -r}}};
  for (int k2 = 0; k2 < 4; ++k2) {
    const SectionPoint& x = p.fibres[k2];
    p.torsion_shear_per_torque[k2] = {-x[1] / p.J, x[0] / p.J};
  }
  return p;
}

BeamSectionProperties box(const std::vector<double>& d) {
  const double a = d[0], b = d[1], t1 = d[2], t2 = d[3], t3 = d[4], t4 = d[5];
  const double ai = a - t1 - t3, bi = b - t2 - t4;
  BeamSectionProperties p;
  p.area = a * b - ai * bi;
  p.I11 = (a * b * b * b - ai * bi * bi * bi) / 12.0;
  p.I22 = (b * a * a * a - bi * ai * ai * ai) / 12.0;
  // Bredt: J = 4 A_m^2 / (integral ds / t) over the wall mid-line.
  const double am = a - (t1 + t3) / 2.0, bm = b - (t2 + t4) / 2.0;
  const double Am = am * bm;
  p.J = 4.0 * Am * Am / (bm / t1 + bm / t3 + am / t2 + am / t4);
  p.shear_area1 = (t2 + t4) * a;  // the walls at +-x2 run along n1
  p.shear_area2 = (t1 + t3) * b;  // the walls at +-x1 run along n2
  p.fibres = {{{a / 2, b / 2}, {-a / 2, b / 2}, {-a / 2, -b / 2}, {a / 2, -b / 2}}};
  // Shear flow q = T / (2 A_m), counter-clockwise: along +n2 in the +x1 wall (t1), -n1 in the
  // +x2 wall (t2), -n2 in the -x1 wall (t3), +n1 in the -x2 wall (t4).
  struct Wall {
    double thickness;
    SectionPoint direction;
  };
  const Wall walls[4] = {{t1, {0, 1}}, {t2, {-1, 0}}, {t3, {0, -1}}, {t4, {1, 0}}};
  const int meeting[4][2] = {{0, 1}, {2, 1}, {2, 3}, {0, 3}};  // walls at each corner
  for (int k = 0; k < 4; ++k) {
    const Wall& thinner = walls[meeting[k][0]].thickness <= walls[meeting[k][1]].thickness
                              ? walls[meeting[k][0]]
                              : walls[meeting[k][1]];
    const double tau = 1.0 / (2.0 * Am * thinner.thickness);
    p.torsion_shear_per_torque[k] = {tau * thinner.direction[0], tau * thinner.direction[1]};
  }
  return p;
}

std::vector<SectionPoint> rectangle_outline(double a, double b) {
  return {{a / 2, -b / 2}, {a / 2, b / 2}, {-a / 2, b / 2}, {-a / 2, -b / 2}};
}

std::vector<SectionPoint> ellipse_outline(double r1, double r2, int segments) {
  std::vector<SectionPoint> out;
  for (int k = 0; k < segments; ++k) {
    const double phi = 2.0 * kPi * k / segments;
    out.push_back({r1 * std::cos(phi), r2 * std::sin(phi)});
  }
  return out;
}

}  // namespace

const char* beam_shape_name(BeamShape shape) {
  switch (shape) {
    case BeamShape::Rect:
      return "RECT";
    case BeamShape::Circ:
      return "CIRC";
    case BeamShape::Pipe:
      return "PIPE";
    case BeamShape::Box:
      return "BOX";
  }
  return "?";
}

std::array<int, 2> beam_dimension_count(BeamShape shape) {
  switch (shape) {
    case BeamShape::Rect:
      return {2, 2};
    case BeamShape::Circ:
      return {1, 2};
    case BeamShape::Pipe:
      return {2, 2};
    case BeamShape::Box:
      return {6, 6};
  }
  return {0, 0};
}

std::string check_beam_section(const BeamSection& section) {
  const std::vector<double>& d = section.dimensions;
  const std::array<int, 2> count = beam_dimension_count(section.shape);
  const std::string shape = std::string("SECTION=") + beam_shape_name(section.shape);
  if (static_cast<int>(d.size()) < count[0] || static_cast<int>(d.size()) > count[1])
    return shape + " takes " + std::to_string(count[0]) +
           (count[1] != count[0] ? " or " + std::to_string(count[1]) : "") + " dimensions, read " +
           std::to_string(d.size());
  for (double v : d)
    if (!(v > 0.0) || !std::isfinite(v))
      return shape + ": every dimension must be positive, read " + number(v);
  if (section.shape == BeamShape::Pipe && d[1] > d[0])
    return "SECTION=PIPE: the wall thickness " + number(d[1]) + " exceeds the outer radius " +
           number(d[0]);
  if (section.shape == BeamShape::Box) {
    if (!(d[2] + d[4] < d[0]) || !(d[3] + d[5] < d[1]))
      return "SECTION=BOX: the walls (t1 + t3 = " + number(d[2] + d[4]) +
             ", t2 + t4 = " + number(d[3] + d[5]) + ") leave no hollow in the " + number(d[0]) +
             " x " + number(d[1]) + " box";
    if (d[2] != d[4] || d[3] != d[5])
      return "SECTION=BOX with unequal opposite walls (t1 = " + number(d[2]) +
             ", t3 = " + number(d[4]) + ", t2 = " + number(d[3]) + ", t4 = " + number(d[5]) +
             ") has its centroid off the box centre, which Styk's beams (nodes on the centroid, "
             "no offsets) cannot place; give t1 = t3 and t2 = t4";
  }
  return {};
}

BeamSectionProperties beam_section_properties(const BeamSection& section) {
  const std::vector<double>& d = section.dimensions;
  switch (section.shape) {
    case BeamShape::Rect:
      return rect(d[0], d[1]);
    case BeamShape::Circ:
      return ellipse(d[0], d.size() > 1 ? d[1] : d[0]);
    case BeamShape::Pipe:
      return pipe(d[0], d[1]);
    case BeamShape::Box:
      return box(d);
  }
  return {};
}

std::vector<SectionPoint> beam_section_outline(const BeamSection& section, bool inner,
                                               int segments) {
  const std::vector<double>& d = section.dimensions;
  switch (section.shape) {
    case BeamShape::Rect:
      return inner ? std::vector<SectionPoint>{} : rectangle_outline(d[0], d[1]);
    case BeamShape::Circ:
      return inner ? std::vector<SectionPoint>{}
                   : ellipse_outline(d[0] / 2, (d.size() > 1 ? d[1] : d[0]) / 2, segments);
    case BeamShape::Pipe:
      if (!inner) return ellipse_outline(d[0], d[0], segments);
      return d[1] < d[0] ? ellipse_outline(d[0] - d[1], d[0] - d[1], segments)
                         : std::vector<SectionPoint>{};
    case BeamShape::Box:
      return inner ? rectangle_outline(d[0] - d[2] - d[4], d[1] - d[3] - d[5])
                   : rectangle_outline(d[0], d[1]);
  }
  return {};
}

bool beam_section_axes(const Vec3& tangent, const Vec3& direction, Vec3& n1, Vec3& n2) {
  const double tl =
      std::sqrt(tangent[0] * tangent[0] + tangent[1] * tangent[1] + tangent[2] * tangent[2]);
  const double dl = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                              direction[2] * direction[2]);
  if (!(tl > 0.0) || !(dl > 0.0)) return false;
  const Vec3 t{tangent[0] / tl, tangent[1] / tl, tangent[2] / tl};
  Vec3 m{t[1] * direction[2] - t[2] * direction[1], t[2] * direction[0] - t[0] * direction[2],
         t[0] * direction[1] - t[1] * direction[0]};
  const double ml = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (!(ml > 1e-6 * dl)) return false;
  n2 = {m[0] / ml, m[1] / ml, m[2] / ml};
  n1 = {n2[1] * t[2] - n2[2] * t[1], n2[2] * t[0] - n2[0] * t[2], n2[0] * t[1] - n2[1] * t[0]};
  return true;
}

}  // namespace styk
