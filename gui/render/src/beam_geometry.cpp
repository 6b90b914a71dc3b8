#include "beam_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "styk/core/beam_section.hpp"

namespace styk::render {
namespace {

constexpr int kRoundSegments = 24;
// Points per side of a flat (RECT, BOX) outline: a nonlinear field of the fibre stresses (Mises,
// which is zero on the neutral axis) is sampled, not just interpolated between the corners.
constexpr int kSideSegments = 8;

// The outline with every side of a polygon cut into kSideSegments pieces (round outlines as they
// are: their points are dense already).
std::vector<SectionPoint> refined(const std::vector<SectionPoint>& outline, bool round) {
  if (round || outline.empty()) return outline;
  std::vector<SectionPoint> out;
  for (std::size_t j = 0; j < outline.size(); ++j) {
    const SectionPoint& a = outline[j];
    const SectionPoint& b = outline[(j + 1) % outline.size()];
    for (int k = 0; k < kSideSegments; ++k) {
      const double s = double(k) / kSideSegments;
      out.push_back({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])});
    }
  }
  return out;
}

using Vector3 = Eigen::Vector3d;

Vector3 vec(const Vec3& v) { return Vector3(v[0], v[1], v[2]); }

// The section of beam e as the renderer needs it.
struct SectionShape {
  const BeamSection* section = nullptr;
  bool round = false;               // CIRC, PIPE: smooth normals
  std::vector<SectionPoint> outer;  // counter-clockwise
  std::vector<SectionPoint> inner;  // PIPE, BOX; empty for solid sections
  BeamSectionProperties properties;
};

SectionShape section_shape(const BeamSection& section) {
  SectionShape s;
  s.section = &section;
  s.round = section.shape == BeamShape::Circ || section.shape == BeamShape::Pipe;
  s.outer = refined(beam_section_outline(section, false, kRoundSegments), s.round);
  s.inner = refined(beam_section_outline(section, true, kRoundSegments), s.round);
  s.properties = beam_section_properties(section);
  return s;
}

const BeamSection* beam_section_of(const Model& model, int e) {
  const int s = model.elements[e].section;
  if (s < 0 || s >= static_cast<int>(model.sections.size())) return nullptr;
  const Section& section = model.sections[s];
  if (!section.beam || !check_beam_section(*section.beam).empty()) return nullptr;
  return &*section.beam;
}

// Weights of the four fibre points for a section point x: bilinear between the corners of RECT
// and BOX, the first Fourier term through the axis points of CIRC and PIPE. Both reproduce a
// field linear in (x1, x2) exactly.
std::array<double, 4> fibre_weights(const SectionShape& shape, const SectionPoint& x) {
  const SectionPoint& f0 = shape.properties.fibres[0];
  if (shape.round) {
    const double c = x[0] / shape.properties.fibres[0][0];
    const double s = x[1] / shape.properties.fibres[1][1];
    return {0.25 + 0.5 * c, 0.25 + 0.5 * s, 0.25 - 0.5 * c, 0.25 - 0.5 * s};
  }
  const double s = x[0] / f0[0], r = x[1] / f0[1];  // fibre 0 is the (+, +) corner
  return {0.25 * (1 + s) * (1 + r), 0.25 * (1 - s) * (1 + r), 0.25 * (1 - s) * (1 - r),
          0.25 * (1 + s) * (1 - r)};
}

// Lagrange weights at xi of the stations `at`.
std::vector<double> lagrange(const std::vector<double>& at, double xi) {
  std::vector<double> w(at.size(), 1.0);
  for (std::size_t i = 0; i < at.size(); ++i)
    for (std::size_t j = 0; j < at.size(); ++j)
      if (i != j) w[i] *= (xi - at[j]) / (at[i] - at[j]);
  return w;
}

// The stations (xi) of element e's output points: the rule whose size matches the field's.
std::vector<double> stations_of(const TElement& f, int points) {
  for (const RuleKind kind : {RuleKind::Full, RuleKind::Reduced}) {
    const IntegrationRule rule = f.rule(kind);
    if (rule.size() != points) continue;
    std::vector<double> xi;
    for (int k = 0; k < rule.size(); k += 4) xi.push_back(rule.points[k][0]);
    return xi;
  }
  return {};
}

// How one beam is coloured: by the layer, by a nodal/element field along the axis, or by the fibre
// tensors of a stress/strain field.
class BeamColouring {
 public:
  BeamColouring(const Model& model, const GeometryRequest& rq, const TElement& f, int e,
                const SectionShape& shape)
      : model_(model), field_(rq.field), colors_(rq.colors), e_(e), shape_(shape) {
    if (!field_) return;
    if (field_->tensor_value && !field_->point_offset.empty()) {
      const int first = field_->point_offset[e], last = field_->point_offset[e + 1];
      // Section forces: one value per station (4 fibre points per station otherwise).
      stations_ = stations_of(f, (field_->station_values ? 4 : 1) * (last - first));
      fibres_ = !stations_.empty();
    }
    const int* conn = model.element_nodes(e);
    if (!fibres_ && field_->location == FieldLocation::Node && !field_->defined.empty())
      for (int k = 0; k < model.elements[e].node_count; ++k)
        covered_ = covered_ && field_->defined[conn[k]] != 0;
  }

  bool has_field() const { return field_ != nullptr; }
  bool covered() const { return covered_; }

  // The field value at natural coordinate xi (shape functions N) and section point x.
  double value(double xi, const Eigen::VectorXd& N, const SectionPoint& x) const {
    if (fibres_) {
      const std::vector<double> along = lagrange(stations_, xi);
      const std::array<double, 4> around = fibre_weights(shape_, x);
      const int first = field_->point_offset[e_];
      Tensor6 t{};
      if (field_->station_values) {
        for (std::size_t s = 0; s < stations_.size(); ++s)
          for (int c = 0; c < 6; ++c) t[c] += along[s] * field_->point_tensors[first + s][c];
        return field_->tensor_value(t);
      }
      for (std::size_t s = 0; s < stations_.size(); ++s)
        for (int k = 0; k < 4; ++k) {
          const Tensor6& p = field_->point_tensors[first + 4 * s + k];
          for (int c = 0; c < 6; ++c) t[c] += along[s] * around[k] * p[c];
        }
      return field_->tensor_value(t);
    }
    const Element& element = model_.elements[e_];
    const int* conn = model_.element_nodes(e_);
    double v = 0.0;
    for (int k = 0; k < element.node_count; ++k) switch (field_->location) {
        case FieldLocation::Node:
          v += N(k) * field_->values[conn[k]];
          break;
        case FieldLocation::ElementNode:
          v += N(k) * field_->values[element.first_node + k];
          break;
        case FieldLocation::Element:
          v += N(k) * field_->values[e_];
          break;
      }
    return v;
  }

  float t(double xi, const Eigen::VectorXd& N, const SectionPoint& x) const {
    if (!field_ || !covered_) return -1.0f;
    return static_cast<float>(colors_->normalized(value(xi, N, x)));
  }

 private:
  const Model& model_;
  const ScalarField* field_;
  const ColorScale* colors_;
  int e_;
  const SectionShape& shape_;
  std::vector<double> stations_;
  bool fibres_ = false;
  bool covered_ = true;
};

// One ring of the tube: the axis point (relative to the origin, deformed) and the section axes.
struct Ring {
  double xi = 0.0;
  Eigen::VectorXd N;
  Vector3 centre, n1, n2, t;
};

std::vector<double> ring_positions(int nodes) {
  return nodes == 2 ? std::vector<double>{-1.0, 0.0, 1.0}
                    : std::vector<double>{-1.0, -0.5, 0.0, 0.5, 1.0};
}

// The rings of beam e; empty when its axes are undefined (the solver refuses such a beam).
std::vector<Ring> rings_of(const Model& model, const TElement& f, int e, const BeamSection& section,
                           const GeometryRequest& rq, const Vec3& origin) {
  const int n = f.node_count();
  const int* conn = model.element_nodes(e);
  const double scale = rq.displacement ? rq.scale : 0.0;
  const bool turned = scale != 0.0 && rq.rotation && rq.rotation->size() == model.coords.size();
  const bool planar = !f.active_dofs()[2];
  const Vec3 direction = planar ? Vec3{0.0, 0.0, -1.0} : section.direction;
  std::vector<Ring> rings;
  Eigen::MatrixXd dN(n, 3);
  for (const double xi : ring_positions(n)) {
    Ring r;
    r.xi = xi;
    r.N.resize(n);
    f.der({xi, 0.0, 0.0}, r.N, dN);
    Vector3 x = Vector3::Zero(), tangent = Vector3::Zero(), theta = Vector3::Zero();
    for (int k = 0; k < n; ++k) {
      const Vector3 X = vec(model.coords[conn[k]]) - vec(origin);
      x += r.N(k) * X;
      tangent += dN(k, 0) * X;
      if (scale != 0.0) x += scale * r.N(k) * vec((*rq.displacement)[conn[k]]);
      if (turned) theta += scale * r.N(k) * vec((*rq.rotation)[conn[k]]);
    }
    Vec3 n1, n2;
    if (!beam_section_axes({tangent.x(), tangent.y(), tangent.z()}, direction, n1, n2)) return {};
    r.centre = x;
    r.t = tangent.normalized();
    r.n1 = vec(n1);
    r.n2 = vec(n2);
    if (theta.norm() > 0.0) {  // the section turns with the beam (finite rotation of the vector)
      const Eigen::AngleAxisd turn(theta.norm(), theta.normalized());
      r.n1 = turn * r.n1;
      r.n2 = turn * r.n2;
      r.t = turn * r.t;
    }
    rings.push_back(std::move(r));
  }
  return rings;
}

Vertex vertex(const Vector3& p, const Vector3& normal, const Rgb& c, float t) {
  return Vertex{{float(p.x()), float(p.y()), float(p.z())},
                {float(normal.x()), float(normal.y()), float(normal.z())},
                {c.r, c.g, c.b},
                t};
}

Vector3 place(const Ring& r, const SectionPoint& x) { return r.centre + x[0] * r.n1 + x[1] * r.n2; }

// Outward normal of the section outline at point j: smooth (ellipse gradient) for round sections.
Vector3 smooth_normal(const Ring& r, const SectionShape& s, const SectionPoint& x) {
  const double p1 = s.properties.fibres[0][0], p2 = s.properties.fibres[1][1];
  return (x[0] / (p1 * p1) * r.n1 + x[1] / (p2 * p2) * r.n2).normalized();
}

class TubeBuilder {
 public:
  TubeBuilder(FrameGeometry& g, const Rgb& color) : g_(g), color_(color) {}

  std::uint32_t add(const Vector3& p, const Vector3& normal, float t) {
    g_.face_vertices.push_back(vertex(p, normal, color_, t));
    return static_cast<std::uint32_t>(g_.face_vertices.size() - 1);
  }
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    g_.triangles.insert(g_.triangles.end(), {a, b, c, a, c, d});
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    g_.triangles.insert(g_.triangles.end(), {a, b, c});
  }
  void line(const Vector3& a, const Vector3& b) {
    for (std::vector<Vertex>* lines : {&g_.edges, &g_.features}) {
      lines->push_back(vertex(a, Vector3::Zero(), color_, -1.0f));
      lines->push_back(vertex(b, Vector3::Zero(), color_, -1.0f));
    }
  }

 private:
  FrameGeometry& g_;
  Rgb color_;
};

void add_sides(const std::vector<Ring>& rings, const SectionShape& s, const BeamColouring& c,
               TubeBuilder& tube) {
  const std::vector<SectionPoint>& outline = s.outer;
  const std::size_t m = outline.size();
  for (std::size_t q = 0; q + 1 < rings.size(); ++q) {
    const Ring& r0 = rings[q];
    const Ring& r1 = rings[q + 1];
    for (std::size_t j = 0; j < m; ++j) {
      const SectionPoint& a = outline[j];
      const SectionPoint& b = outline[(j + 1) % m];
      Vector3 na0, nb0, na1, nb1;
      if (s.round) {
        na0 = smooth_normal(r0, s, a), nb0 = smooth_normal(r0, s, b);
        na1 = smooth_normal(r1, s, a), nb1 = smooth_normal(r1, s, b);
      } else {  // a flat side: outward normal (db2, -db1) of the counter-clockwise edge
        const double d1 = b[0] - a[0], d2 = b[1] - a[1];
        na0 = nb0 = (d2 * r0.n1 - d1 * r0.n2).normalized();
        na1 = nb1 = (d2 * r1.n1 - d1 * r1.n2).normalized();
      }
      tube.quad(tube.add(place(r0, a), na0, c.t(r0.xi, r0.N, a)),
                tube.add(place(r0, b), nb0, c.t(r0.xi, r0.N, b)),
                tube.add(place(r1, b), nb1, c.t(r1.xi, r1.N, b)),
                tube.add(place(r1, a), na1, c.t(r1.xi, r1.N, a)));
      if (!s.round && j % kSideSegments == 0)  // the long edges at the corners of a flat tube
        tube.line(place(r0, a), place(r1, a));
    }
  }
}

void add_cap(const Ring& r, double side, const SectionShape& s, const BeamColouring& c,
             TubeBuilder& tube) {
  const Vector3 normal = side * r.t;
  const std::vector<SectionPoint>& outer = s.outer;
  const std::size_t m = outer.size();
  for (std::size_t j = 0; j < m; ++j) tube.line(place(r, outer[j]), place(r, outer[(j + 1) % m]));
  if (s.inner.empty()) {
    const SectionPoint centre{0.0, 0.0};
    const std::uint32_t middle = tube.add(r.centre, normal, c.t(r.xi, r.N, centre));
    for (std::size_t j = 0; j < m; ++j) {
      const std::uint32_t a = tube.add(place(r, outer[j]), normal, c.t(r.xi, r.N, outer[j]));
      const std::uint32_t b =
          tube.add(place(r, outer[(j + 1) % m]), normal, c.t(r.xi, r.N, outer[(j + 1) % m]));
      tube.triangle(middle, a, b);
    }
    return;
  }
  const std::vector<SectionPoint>& inner = s.inner;  // same count and start as the outer outline
  for (std::size_t j = 0; j < m && j < inner.size(); ++j) {
    const std::size_t k = (j + 1) % m;
    tube.line(place(r, inner[j]), place(r, inner[k]));
    tube.quad(tube.add(place(r, outer[j]), normal, c.t(r.xi, r.N, outer[j])),
              tube.add(place(r, outer[k]), normal, c.t(r.xi, r.N, outer[k])),
              tube.add(place(r, inner[k]), normal, c.t(r.xi, r.N, inner[k])),
              tube.add(place(r, inner[j]), normal, c.t(r.xi, r.N, inner[j])));
  }
}

}  // namespace

bool is_drawn_beam(const Model& model, const TElement& formulation, int e) {
  return formulation.section_measure() == SectionMeasure::Beam &&
         beam_section_of(model, e) != nullptr;
}

void add_beam_elements(const SkinModel& skin, const SkinModel::LayerSkin& layer,
                       const GeometryRequest& request, FrameGeometry& g) {
  const Model& model = skin.model();
  for (const int e : layer.beams) {
    const TElement& f = *skin.formulations()[e];
    const BeamSection* section = beam_section_of(model, e);
    if (section == nullptr) continue;
    const SectionShape shape = section_shape(*section);
    const std::vector<Ring> rings = rings_of(model, f, e, *section, request, g.origin);
    if (rings.size() < 2) continue;
    const BeamColouring colouring(model, request, f, e, shape);
    if (colouring.has_field() && !colouring.covered() && request.hide_undefined_faces) continue;
    const Rgb color =
        colouring.has_field() && !colouring.covered() ? neutral_face_color() : layer.color;
    TubeBuilder tube(g, color);
    add_sides(rings, shape, colouring, tube);
    add_cap(rings.front(), -1.0, shape, colouring, tube);
    add_cap(rings.back(), 1.0, shape, colouring, tube);
  }
}

void add_beam_axes(const SkinModel& skin, const SkinModel::LayerSkin& layer, const Vec3& origin,
                   std::vector<Vertex>& lines) {
  const Model& model = skin.model();
  const Rgb color{0.0f, 0.0f, 0.0f};
  for (const int e : layer.beams) {
    const TElement& f = *skin.formulations()[e];
    const int n = f.node_count();
    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3);
    const int* conn = model.element_nodes(e);
    std::vector<Vector3> points;
    for (const double xi : ring_positions(n)) {
      f.der({xi, 0.0, 0.0}, N, dN);
      Vector3 x = Vector3::Zero();
      for (int k = 0; k < n; ++k) x += N(k) * (vec(model.coords[conn[k]]) - vec(origin));
      points.push_back(x);
    }
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      lines.push_back(vertex(points[k], Vector3::Zero(), color, -1.0f));
      lines.push_back(vertex(points[k + 1], Vector3::Zero(), color, -1.0f));
    }
  }
}

double largest_beam_section_radius(const Model& model, const std::vector<int>& beams) {
  double radius = 0.0;
  for (const int e : beams)
    if (const BeamSection* section = beam_section_of(model, e))
      for (const SectionPoint& x : beam_section_outline(*section, false, kRoundSegments))
        radius = std::max(radius, std::hypot(x[0], x[1]));
  return radius;
}

std::array<double, 2> beam_field_range(const SkinModel& skin, const std::vector<int>& beams,
                                       const ScalarField& field) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  if (!field.tensor_value || field.point_offset.empty()) return {lo, hi};
  const Model& model = skin.model();
  GeometryRequest request;
  request.field = &field;
  for (const int e : beams) {
    const TElement& f = *skin.formulations()[e];
    const BeamSection* section = beam_section_of(model, e);
    if (section == nullptr) continue;
    const SectionShape shape = section_shape(*section);
    const BeamColouring colouring(model, request, f, e, shape);
    Eigen::VectorXd N(f.node_count());
    Eigen::MatrixXd dN(f.node_count(), 3);
    for (const double xi : ring_positions(f.node_count())) {
      f.der({xi, 0.0, 0.0}, N, dN);
      for (const std::vector<SectionPoint>* outline : {&shape.outer, &shape.inner})
        for (const SectionPoint& x : *outline) {
          const double v = colouring.value(xi, N, x);
          lo = std::min(lo, v), hi = std::max(hi, v);
        }
    }
  }
  return {lo, hi};
}

}  // namespace styk::render
