#include "shell_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace styk::render {
namespace {

using Vector3 = Eigen::Vector3d;

Vector3 vec(const Vec3& v) { return Vector3(v[0], v[1], v[2]); }

// Grid segments per direction of a shell's faces: a 3- or 4-node shell's field is at most
// bilinear (its Gauss points 2x2, or the triangle's 3), a quadratic shell's is quadratic and its
// surface curved.
int grid_segments(const TElement& f) { return f.node_count() <= 4 ? 4 : 6; }

// A triangular shell (STRI3): its natural coordinates are those of the triangle xi, eta >= 0,
// xi + eta <= 1, and it has three corners and edges.
bool is_triangle(const TElement& f) { return f.node_count() == 3 || f.node_count() == 6; }
int corner_count(const TElement& f) { return is_triangle(f) ? 3 : 4; }

// The faces are drawn as a grid over the parameter square (u, v) in [0, 1]^2: the square
// itself for a quadrilateral, collapsed onto the triangle for a triangle (its v = 1 side onto
// the third corner, so the last row of cells are triangles), so one grid serves both shapes.
std::array<double, 2> natural_at(const TElement& f, double u, double v) {
  if (is_triangle(f)) return {u * (1.0 - v), v};
  return {-1.0 + 2.0 * u, -1.0 + 2.0 * v};
}

// Thickness and offset of shell e (0 thickness when the model holds no section for it: a results
// file written before shell sections were stored draws the reference surface alone).
struct ShellSectionData {
  double thickness = 0.0;
  double offset = 0.0;
  double z(double zeta) const { return thickness * (0.5 * zeta - offset); }
};

ShellSectionData section_of(const Model& model, int e) {
  ShellSectionData d;
  const int s = model.elements[e].section;
  if (s < 0 || s >= static_cast<int>(model.sections.size())) return d;
  const Section& section = model.sections[s];
  if (section.thickness && *section.thickness > 0) d.thickness = *section.thickness;
  if (section.shell) d.offset = section.shell->offset;
  return d;
}

// Lagrange weights at x of the abscissae `at`.
std::vector<double> lagrange(const std::vector<double>& at, double x) {
  std::vector<double> w(at.size(), 1.0);
  for (std::size_t i = 0; i < at.size(); ++i)
    for (std::size_t j = 0; j < at.size(); ++j)
      if (i != j) w[i] *= (x - at[j]) / (at[i] - at[j]);
  return w;
}

// The sorted distinct values of `v` (to 1e-9) and each entry's index among them.
std::vector<double> distinct(const std::vector<double>& v, std::vector<int>& index) {
  std::vector<double> out = v;
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(),
                        [](double a, double b) { return std::abs(a - b) < 1e-9; }),
            out.end());
  index.clear();
  for (const double x : v) {
    const auto it = std::lower_bound(out.begin(), out.end(), x - 1e-9);
    index.push_back(static_cast<int>(it - out.begin()));
  }
  return out;
}

// How one shell is coloured: by the layer, by a nodal / element field over the surface, or by the
// stress / strain tensors of its surface Gauss points on the chosen fibre.
class ShellColouring {
 public:
  ShellColouring(const Model& model, const ScalarField* field, const ColorScale* colors,
                 const TElement& f, int e)
      : model_(model), field_(field), colors_(colors), e_(e) {
    if (!field_) return;
    if (field_->tensor_value && !field_->point_offset.empty()) fibres_ = find_points(f);
    const int* conn = model.element_nodes(e);
    if (!fibres_ && field_->location == FieldLocation::Node && !field_->defined.empty())
      for (int k = 0; k < model.elements[e].node_count; ++k)
        covered_ = covered_ && field_->defined[conn[k]] != 0;
  }

  bool has_field() const { return field_ != nullptr; }
  bool covered() const { return covered_; }

  // The field value at (xi, eta), where the shape functions are N.
  double value(double xi, double eta, const Eigen::VectorXd& N) const {
    if (fibres_) {
      const std::vector<double> weights = point_weights(xi, eta);
      const int first = field_->point_offset[e_];
      const int fibre = static_cast<int>(field_->shell_fibre);
      Tensor6 t{};
      for (std::size_t k = 0; k < weights.size(); ++k) {
        const double w = weights[k];
        const int point =
            field_->station_values ? static_cast<int>(k) : 3 * static_cast<int>(k) + fibre;
        const Tensor6& p = field_->point_tensors[first + point];
        for (int c = 0; c < 6; ++c) t[c] += w * p[c];
      }
      return field_->tensor_value(t);
    }
    const Element& element = model_.elements[e_];
    const int* conn = model_.element_nodes(e_);
    if (field_->location == FieldLocation::Element) return field_->values[e_];
    double v = 0.0;
    for (int k = 0; k < element.node_count; ++k)
      v +=
          N(k) * (field_->location == FieldLocation::Node ? field_->values[conn[k]]
                                                          : field_->values[element.first_node + k]);
    return v;
  }

  float t(double xi, double eta, const Eigen::VectorXd& N) const {
    if (!field_ || !covered_) return -1.0f;
    return static_cast<float>(colors_->normalized(value(xi, eta, N)));
  }

 private:
  // The weights of the surface points' values at (xi, eta): Lagrange interpolation through a
  // tensor-product rule's points, or the linear function through a triangle's three points
  // (exact for the DKT triangle's moments, which are linear, and its constant membrane forces).
  std::vector<double> point_weights(double xi, double eta) const {
    if (linear_) {
      const Eigen::Vector3d w = linear_inverse_ * Eigen::Vector3d(1.0, xi, eta);
      return {w(0), w(1), w(2)};
    }
    const std::vector<double> wx = lagrange(xs_, xi), wy = lagrange(ys_, eta);
    std::vector<double> w;
    for (std::size_t k = 0; k < ix_.size(); ++k) w.push_back(wx[ix_[k]] * wy[iy_[k]]);
    return w;
  }

  // The surface points of the rule whose size matches the element's output points (3 fibres
  // per surface point, rule order; one value per surface point for section forces): their
  // distinct abscissae per direction, or, for three points that are not a tensor product (the
  // triangle's rule), the inverse of the matrix that fits a linear function through them.
  bool find_points(const TElement& f) {
    const int given = field_->point_offset[e_ + 1] - field_->point_offset[e_];
    const int points = field_->station_values ? 3 * given : given;
    for (const RuleKind kind : {RuleKind::Full, RuleKind::Reduced}) {
      const IntegrationRule rule = f.rule(kind);
      if (rule.size() != points || points % 3 != 0 || points == 0) continue;
      std::vector<double> xi, eta;
      for (int k = 0; k < points; k += 3) {
        xi.push_back(rule.points[k][0]);
        eta.push_back(rule.points[k][1]);
      }
      xs_ = distinct(xi, ix_);
      ys_ = distinct(eta, iy_);
      if (xs_.size() * ys_.size() == ix_.size()) return true;  // a tensor-product rule
      if (xi.size() != 3) return false;
      Eigen::Matrix3d fit;
      fit << 1.0, 1.0, 1.0, xi[0], xi[1], xi[2], eta[0], eta[1], eta[2];
      linear_inverse_ = fit.inverse();
      linear_ = std::isfinite(linear_inverse_.sum());
      return linear_;
    }
    return false;
  }

  const Model& model_;
  const ScalarField* field_;
  const ColorScale* colors_;
  int e_;
  bool fibres_ = false;
  bool covered_ = true;
  std::vector<double> xs_, ys_;  // distinct Gauss abscissae along xi and eta
  std::vector<int> ix_, iy_;     // of each surface point
  bool linear_ = false;          // three points fitted by a linear function (a triangle)
  Eigen::Matrix3d linear_inverse_ = Eigen::Matrix3d::Zero();
};

Vertex vertex(const Vector3& p, const Vector3& normal, const Rgb& c, float t) {
  return Vertex{{float(p.x()), float(p.y()), float(p.z())},
                {float(normal.x()), float(normal.y()), float(normal.z())},
                {c.r, c.g, c.b},
                t};
}

// One shell as placed: its nodes (deformed, relative to the origin) and directors (turned).
struct PlacedShell {
  const TElement* f = nullptr;
  int e = 0;
  ShellSectionData section;
  std::vector<Vector3> nodes;
  std::vector<Vector3> directors;
};

PlacedShell place_shell(const SkinModel& skin, const TElement& f, int e, const GeometryRequest& rq,
                        const Vec3& origin) {
  const Model& model = skin.model();
  const std::vector<Vec3>& resolved = skin.shell_normals().at_slot;
  PlacedShell s;
  s.f = &f;
  s.e = e;
  s.section = section_of(model, e);
  const int n = f.node_count();
  const int* conn = model.element_nodes(e);
  const double scale = rq.displacement ? rq.scale : 0.0;
  const bool turned = scale != 0.0 && rq.rotation && rq.rotation->size() == model.coords.size();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (int a = 0; a < n; ++a) {
    // The solver's director V_a: the nodal normal resolved over the mesh (averaged where the
    // shell is smooth, given by *NORMAL), else the element's own normal at node a.
    const std::size_t slot = static_cast<std::size_t>(model.elements[e].first_node + a);
    Vector3 director = slot < resolved.size() ? vec(resolved[slot]) : Vector3(Vector3::Zero());
    if (director.norm() == 0.0) {
      f.der(f.natural_nodes()[a], N, dN);
      Vector3 g1 = Vector3::Zero(), g2 = Vector3::Zero();
      for (int b = 0; b < n; ++b) {
        g1 += dN(b, 0) * vec(model.coords[conn[b]]);
        g2 += dN(b, 1) * vec(model.coords[conn[b]]);
      }
      director = g1.cross(g2);
    }
    director = director.norm() > 0 ? Vector3(director.normalized()) : Vector3::UnitZ();
    Vector3 x = vec(model.coords[conn[a]]) - vec(origin);
    if (scale != 0.0) x += scale * vec((*rq.displacement)[conn[a]]);
    if (turned) {  // the fibre turns with the node (finite rotation of the vector)
      const Vector3 theta = scale * vec((*rq.rotation)[conn[a]]);
      if (theta.norm() > 0.0)
        director = Eigen::AngleAxisd(theta.norm(), theta.normalized()) * director;
    }
    s.nodes.push_back(x);
    s.directors.push_back(director);
  }
  return s;
}

// A point of the shell's surface at (xi, eta): the reference point, the director, the unit
// normal of the placed surface (on the director's side) and the shape functions.
struct SurfacePoint {
  Vector3 x, director, normal;
  Eigen::VectorXd N;
};

SurfacePoint surface_point(const PlacedShell& s, double xi, double eta) {
  const int n = s.f->node_count();
  SurfacePoint p;
  p.N.resize(n);
  Eigen::MatrixXd dN(n, 3);
  s.f->der({xi, eta, 0.0}, p.N, dN);
  p.x = p.director = Vector3::Zero();
  Vector3 g1 = Vector3::Zero(), g2 = Vector3::Zero();
  for (int a = 0; a < n; ++a) {
    p.x += p.N(a) * s.nodes[a];
    p.director += p.N(a) * s.directors[a];
    g1 += dN(a, 0) * s.nodes[a];
    g2 += dN(a, 1) * s.nodes[a];
  }
  p.normal = g1.cross(g2);
  p.normal = p.normal.norm() > 0 ? Vector3(p.normal.normalized()) : p.director.normalized();
  if (p.normal.dot(p.director) < 0) p.normal = -p.normal;
  return p;
}

// The natural coordinates of the point at s in [0, 1] along edge k (corner k to corner k + 1).
std::array<double, 2> edge_point(const TElement& f, int k, double s) {
  const Vec3& a = f.natural_nodes()[k];
  const Vec3& b = f.natural_nodes()[(k + 1) % corner_count(f)];
  return {(1 - s) * a[0] + s * b[0], (1 - s) * a[1] + s * b[1]};
}

class ShellBuilder {
 public:
  ShellBuilder(FrameGeometry& g, const Rgb& color) : g_(g), color_(color) {}

  std::uint32_t add(const Vector3& p, const Vector3& normal, float t) {
    g_.face_vertices.push_back(vertex(p, normal, color_, t));
    return static_cast<std::uint32_t>(g_.face_vertices.size() - 1);
  }
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    g_.triangles.insert(g_.triangles.end(), {a, b, c, a, c, d});
  }
  void line(const Vector3& a, const Vector3& b, bool feature) {
    g_.edges.push_back(vertex(a, Vector3::Zero(), color_, -1.0f));
    g_.edges.push_back(vertex(b, Vector3::Zero(), color_, -1.0f));
    if (!feature) return;
    g_.features.push_back(vertex(a, Vector3::Zero(), color_, -1.0f));
    g_.features.push_back(vertex(b, Vector3::Zero(), color_, -1.0f));
  }

 private:
  FrameGeometry& g_;
  Rgb color_;
};

// The bottom and top faces of one shell.
void add_faces(const PlacedShell& s, const ShellColouring& c, ShellBuilder& out) {
  const int m = grid_segments(*s.f);
  for (const double zeta : {-1.0, 1.0}) {
    const double z = s.section.z(zeta);
    std::vector<std::uint32_t> grid;
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i) {
        const auto [xi, eta] = natural_at(*s.f, double(i) / m, double(j) / m);
        const SurfacePoint p = surface_point(s, xi, eta);
        grid.push_back(out.add(p.x + z * p.director, zeta * p.normal, c.t(xi, eta, p.N)));
      }
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const std::uint32_t v00 = grid[j * (m + 1) + i], v10 = v00 + 1, v01 = v00 + (m + 1),
                            v11 = v01 + 1;
        out.quad(v00, v10, v11, v01);
      }
  }
}

// The element edges drawn on both faces (features where the edge is free) and, on a free edge,
// the wall between them with its corner lines.
void add_edges(const PlacedShell& s, const ShellColouring& c, const std::array<bool, 4>& free,
               ShellBuilder& out) {
  const int m = grid_segments(*s.f);
  const auto [xi_c, eta_c] = natural_at(*s.f, 0.5, is_triangle(*s.f) ? 1.0 / 3.0 : 0.5);
  const Vector3 centre = surface_point(s, xi_c, eta_c).x;
  for (int k = 0; k < corner_count(*s.f); ++k) {
    std::vector<SurfacePoint> points;
    std::vector<std::array<double, 2>> at;
    for (int i = 0; i <= m; ++i) {
      at.push_back(edge_point(*s.f, k, double(i) / m));
      points.push_back(surface_point(s, at.back()[0], at.back()[1]));
    }
    const double zb = s.section.z(-1.0), zt = s.section.z(1.0);
    for (int i = 0; i < m; ++i)
      for (const double z : {zb, zt})
        out.line(points[i].x + z * points[i].director, points[i + 1].x + z * points[i + 1].director,
                 free[k]);
    if (!free[k]) continue;
    out.line(points[0].x + zb * points[0].director, points[0].x + zt * points[0].director, true);
    out.line(points[m].x + zb * points[m].director, points[m].x + zt * points[m].director, true);
    if (s.section.thickness <= 0) continue;
    std::vector<std::uint32_t> bottom, top;
    for (int i = 0; i <= m; ++i) {
      const SurfacePoint& p = points[i];
      const Vector3 along = points[std::min(i + 1, m)].x - points[std::max(i - 1, 0)].x;
      Vector3 normal = along.cross(p.director);
      normal = normal.norm() > 0 ? Vector3(normal.normalized()) : Vector3::Zero();
      if (normal.dot(p.x - centre) < 0) normal = -normal;
      const float t = c.t(at[i][0], at[i][1], p.N);
      bottom.push_back(out.add(p.x + zb * p.director, normal, t));
      top.push_back(out.add(p.x + zt * p.director, normal, t));
    }
    for (int i = 0; i < m; ++i) out.quad(bottom[i], bottom[i + 1], top[i + 1], top[i]);
  }
}

// Per shell of the layer, which of its three or four edges no other shell of the layer shares
// (by their corner nodes).
std::vector<std::array<bool, 4>> free_edges(const SkinModel& skin, const std::vector<int>& shells) {
  const Model& model = skin.model();
  const auto corners = [&](int e) { return corner_count(*skin.formulations()[e]); };
  std::map<std::pair<int, int>, int> count;
  const auto key = [&](int e, int k) {
    const int* conn = model.element_nodes(e);
    const int a = conn[k], b = conn[(k + 1) % corners(e)];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  for (const int e : shells)
    for (int k = 0; k < corners(e); ++k) ++count[key(e, k)];
  std::vector<std::array<bool, 4>> out;
  for (const int e : shells) {
    std::array<bool, 4> free{};
    for (int k = 0; k < corners(e); ++k) free[k] = count[key(e, k)] == 1;
    out.push_back(free);
  }
  return out;
}

}  // namespace

bool is_drawn_shell(const TElement& formulation) {
  return formulation.form() == ElementForm::Shell;
}

void add_shell_elements(const SkinModel& skin, const SkinModel::LayerSkin& layer,
                        const GeometryRequest& request, FrameGeometry& g) {
  const Model& model = skin.model();
  const std::vector<std::array<bool, 4>> free = free_edges(skin, layer.shells);
  for (std::size_t i = 0; i < layer.shells.size(); ++i) {
    const int e = layer.shells[i];
    const TElement& f = *skin.formulations()[e];
    const ShellColouring colouring(model, request.field, request.colors, f, e);
    if (colouring.has_field() && !colouring.covered() && request.hide_undefined_faces) continue;
    const Rgb color =
        colouring.has_field() && !colouring.covered() ? neutral_face_color() : layer.color;
    const PlacedShell placed = place_shell(skin, f, e, request, g.origin);
    ShellBuilder out(g, color);
    add_faces(placed, colouring, out);
    add_edges(placed, colouring, free[i], out);
  }
}

double largest_shell_reach(const Model& model, const std::vector<int>& shells) {
  double reach = 0.0;
  for (const int e : shells) {
    const ShellSectionData s = section_of(model, e);
    reach = std::max(reach, s.thickness * (0.5 + std::abs(s.offset)));
  }
  return reach;
}

std::array<double, 2> shell_field_range(const SkinModel& skin, const std::vector<int>& shells,
                                        const ScalarField& field) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const Model& model = skin.model();
  for (const int e : shells) {
    const TElement& f = *skin.formulations()[e];
    const ShellColouring colouring(model, &field, nullptr, f, e);
    if (!colouring.covered()) continue;
    const int m = grid_segments(f);
    Eigen::VectorXd N(f.node_count());
    Eigen::MatrixXd dN(f.node_count(), 3);
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i) {
        const auto [xi, eta] = natural_at(f, double(i) / m, double(j) / m);
        f.der({xi, eta, 0.0}, N, dN);
        const double v = colouring.value(xi, eta, N);
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
  }
  return {lo, hi};
}

}  // namespace styk::render
