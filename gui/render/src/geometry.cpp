#include "styk/render/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "beam_geometry.hpp"
#include "face_shape.hpp"
#include "line_geometry.hpp"
#include "shell_geometry.hpp"
#include "styk/core/vec3.hpp"

namespace styk::render {
namespace {

using V3 = Eigen::Vector3d;

// Where a node is drawn: deformed, relative to the frame origin.
class Placement {
 public:
  Placement(const Model& model, const Vec3& origin, const std::vector<Vec3>* u, double scale)
      : model_(model), origin_(origin), u_(u), scale_(u ? scale : 0.0) {}
  V3 operator()(int node) const {
    const Vec3& x = model_.coords[node];
    V3 p(x[0] - origin_[0], x[1] - origin_[1], x[2] - origin_[2]);
    if (scale_ != 0.0) {
      const Vec3& d = (*u_)[node];
      p += scale_ * V3(d[0], d[1], d[2]);
    }
    return p;
  }

 private:
  const Model& model_;
  Vec3 origin_;
  const std::vector<Vec3>* u_;
  double scale_;
};

Vertex make_vertex(const V3& p, const V3& n, const Rgb& c, float t) {
  return Vertex{{float(p.x()), float(p.y()), float(p.z())},
                {float(n.x()), float(n.y()), float(n.z())},
                {c.r, c.g, c.b},
                t};
}

// A face edge as seen from one skin face: its corner nodes (sorted) and where its polyline lies.
struct EdgeRef {
  int a, b;            // corner node indices, a < b
  std::uint32_t base;  // first face vertex of the face's grid
  int segments;        // grid subdivisions of the face
  int edge;            // 0..3, c_edge -> c_edge+1
  bool forward;        // the face's triangles run along the edge from a to b
};

std::uint32_t edge_vertex(const EdgeRef& r, int i) {
  const int n = r.segments;
  int col = 0, row = 0;
  switch (r.edge) {
    case 0:
      col = i, row = 0;
      break;
    case 1:
      col = n, row = i;
      break;
    case 2:
      col = n - i, row = n;
      break;
    default:
      col = 0, row = n - i;
      break;
  }
  return r.base + static_cast<std::uint32_t>(row * (n + 1) + col);
}

V3 edge_mid_normal(const FrameGeometry& g, const EdgeRef& r) {
  const auto normal = [&](int i) {
    const float* n = g.face_vertices[edge_vertex(r, i)].normal;
    return V3(n[0], n[1], n[2]);
  };
  const int n = r.segments;
  return n % 2 == 0 ? normal(n / 2) : V3(normal((n - 1) / 2) + normal((n + 1) / 2));
}

void add_polyline(const FrameGeometry& g, const EdgeRef& r, const Rgb& color,
                  std::vector<Vertex>& lines) {
  for (int i = 0; i < r.segments; ++i)
    for (int k : {i, i + 1}) {
      Vertex v = g.face_vertices[edge_vertex(r, k)];
      v.normal[0] = v.normal[1] = v.normal[2] = 0.0f;
      v.color[0] = color.r, v.color[1] = color.g, v.color[2] = color.b;
      lines.push_back(v);
    }
}

// Draws one layer's skin faces into g; returns the edge references for de-duplication.
class LayerTessellator {
 public:
  LayerTessellator(const SkinModel& skin, const GeometryRequest& rq, const Placement& place,
                   FrameGeometry& g)
      : skin_(skin), rq_(rq), place_(place), g_(g) {}

  void face(const SkinFace& sf, const Rgb& layer_color, std::vector<EdgeRef>& edges) {
    const Model& model = skin_.model();
    const FaceShape& shape = skin_.shapes().get(skin_.formulations()[sf.element], sf.face);
    const int* conn = model.element_nodes(sf.element);
    // A field with gaps (contact output: the slave nodes only) colours just the faces it covers
    // entirely; the others are neutral grey, or left out on request.
    const ScalarField* field = rq_.field;
    Rgb color = layer_color;
    if (field && !carries(*field, sf)) {
      if (rq_.hide_undefined_faces) return;
      field = nullptr;
      color = neutral_face_color();
    }
    const bool discrete = field && !field->categories.empty();
    const std::array<V3, 4> corner = {
        place_(conn[shape.corners[0]]), place_(conn[shape.corners[1]]),
        place_(conn[shape.corners[2]]), place_(conn[shape.corners[3]])};
    const bool field_varies = field && field->location != FieldLocation::Element;
    const FacePatch* chosen = discrete                                          ? &shape.split
                              : needs_curved(shape, conn, corner, field_varies) ? &shape.curved
                                                                                : &shape.flat;
    if (field_varies && !discrete && shape.curved_segments > 1 && rq_.refine) {
      const int level = refinement_level(shape, sf, conn, *field);
      if (level > 0)
        chosen = &skin_.shapes().refined(skin_.formulations()[sf.element], sf.face, level);
    }
    const FacePatch& patch = *chosen;

    const std::size_t count = patch.nodes.size();
    local_x_.resize(count);
    local_v_.assign(count, 0.0);
    for (std::size_t a = 0; a < count; ++a) local_x_[a] = place_(conn[patch.nodes[a]]);
    double element_value = 0.0;
    if (field) {
      const Element& element = model.elements[sf.element];
      for (std::size_t a = 0; a < count; ++a) {
        if (field->location == FieldLocation::Node)
          local_v_[a] = field->values[conn[patch.nodes[a]]];
        else if (field->location == FieldLocation::ElementNode)
          local_v_[a] = field->values[element.first_node + patch.nodes[a]];
      }
      if (field->location == FieldLocation::Element) element_value = field->values[sf.element];
    }
    // Fallback normal for degenerate grid points (a triangle's repeated corner).
    V3 face_normal = (corner[3] - corner[1]).cross(corner[2] - corner[0]);
    const double face_len = face_normal.norm();
    if (face_len > 0) face_normal /= face_len;
    // Triangles turn clockwise seen from outside the element: in the face's node order when the
    // corners' normal points out of the element, reversed otherwise (formulations differ).
    const double outwards = face_normal.dot(0.25 * (corner[0] + corner[1] + corner[2] + corner[3]) -
                                            element_centre(sf.element));
    const bool reverse = outwards < 0;
    if (outwards == 0) oriented_ = false;

    const int n = patch.segments;
    const auto base = static_cast<std::uint32_t>(g_.face_vertices.size());
    for (int p = 0; p < patch.points(); ++p) {
      V3 x = V3::Zero(), ds = V3::Zero(), dt = V3::Zero();
      double value = element_value;
      const double* N = &patch.N[p * count];
      const double* Ns = &patch.dNds[p * count];
      const double* Nt = &patch.dNdt[p * count];
      for (std::size_t a = 0; a < count; ++a) {
        x += N[a] * local_x_[a];
        ds += Ns[a] * local_x_[a];
        dt += Nt[a] * local_x_[a];
        if (field_varies && !discrete) value += N[a] * local_v_[a];
      }
      if (discrete)
        value =
            nearest_value(shape, conn, *field, double(p % (n + 1)) / n, double(p / (n + 1)) / n);
      // dt x ds points out of the element when the face lists its corners with the normal into
      // it (hexahedra, tetrahedra); a face listed the other way round (wedge faces 2-5) is
      // reversed, and so is its normal.
      V3 normal = (reverse ? -1.0 : 1.0) * dt.cross(ds);
      const double len = normal.norm();
      normal = len > 1e-12 * (ds.squaredNorm() + dt.squaredNorm()) && len > 0
                   ? V3(normal / len)
                   : V3((reverse ? -1.0 : 1.0) * face_normal);
      const float t = field ? static_cast<float>(rq_.colors->normalized(value)) : -1.0f;
      g_.face_vertices.push_back(make_vertex(x, normal, color, t));
    }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::uint32_t v00 = base + j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + (n + 1),
                      v11 = v01 + 1;
        if (discrete) {
          // One colour per cell, that of the nearest face node: the cell gets vertices of its own
          // so that no colour is interpolated between two categories.
          const float t = static_cast<float>(rq_.colors->normalized(
              nearest_value(shape, conn, *field, (i + 0.5) / n, (j + 0.5) / n)));
          const auto own = static_cast<std::uint32_t>(g_.face_vertices.size());
          for (std::uint32_t v : {v00, v10, v11, v01}) {
            Vertex copy = g_.face_vertices[v];
            copy.t = t;
            g_.face_vertices.push_back(copy);
          }
          v00 = own, v10 = own + 1, v11 = own + 2, v01 = own + 3;
        }
        if (reverse)
          g_.triangles.insert(g_.triangles.end(), {v00, v11, v10, v00, v01, v11});
        else
          g_.triangles.insert(g_.triangles.end(), {v00, v10, v11, v00, v11, v01});
      }
    for (int e = 0; e < 4; ++e) {
      if (shape.corner_count == 3 && e == 2) continue;  // the repeated corner's zero-length edge
      const int a = conn[shape.corners[e]], b = conn[shape.corners[(e + 1) % 4]];
      edges.push_back(EdgeRef{std::min(a, b), std::max(a, b), base, n, e, (a < b) != reverse});
    }
  }

  // Whether every face so far could be oriented (its corners' normal is not parallel to the
  // face: a planar element's own face is not).
  bool oriented() const { return oriented_; }

 private:
  V3 element_centre(int element) const {
    const int* conn = skin_.model().element_nodes(element);
    const int count = skin_.model().elements[element].node_count;
    V3 sum = V3::Zero();
    for (int k = 0; k < count; ++k) sum += place_(conn[k]);
    return sum / count;
  }

  // A face with only corners is bilinear; a higher-order face is drawn subdivided when a field
  // varies over it or when, as placed (deformed), its other nodes leave the bilinear patch of
  // its corners by more than 1e-4 of its diagonals.
  bool needs_curved(const FaceShape& shape, const int* conn, const std::array<V3, 4>& c,
                    bool field_varies) const {
    if (shape.curved_segments == 1) return false;
    if (field_varies) return true;
    const double tolerance = 1e-4 * ((c[2] - c[0]).norm() + (c[3] - c[1]).norm());
    for (std::size_t k = 0; k < shape.extra_nodes.size(); ++k) {
      const double s = shape.extra_st[k][0], t = shape.extra_st[k][1];
      const V3 bilinear =
          (1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + s * t * c[2] + (1 - s) * t * c[3];
      if ((place_(conn[shape.extra_nodes[k]]) - bilinear).norm() > tolerance) return true;
    }
    return false;
  }

  // Whether the field colours this face (contact output: the faces of the slave surfaces).
  bool carries(const ScalarField& field, const SkinFace& sf) const {
    if (field.defined.empty() && !field.on_surfaces()) return true;
    return face_carries(skin_, field, sf);
  }

  // How much finer than its base grid a higher-order face is drawn for the field, so that the
  // piecewise-linear drawing follows the field's interpolation (the face's own shape functions)
  // to 1/128 of a band (1/512 of the scale for smooth colours): band limits then run where the
  // field puts them, without teeth at the grid's diagonals. The drawing's error on the base grid is
  // measured where it is largest, at the cells' centres and edge midpoints (the field there, from
  // the shape functions, against the mean of the two grid values the triangles interpolate); it
  // falls fourfold with each halving of the cells.
  int refinement_level(const FaceShape& shape, const SkinFace& sf, const int* conn,
                       const ScalarField& field) const {
    const ColorScale& scale = *rq_.colors;
    const double tolerance =
        (scale.max - scale.min) / (scale.smooth ? 512.0 : 128.0 * std::max(1, scale.bands));
    if (!(tolerance > 0)) return 0;
    const TElement* formulation = skin_.formulations()[sf.element];
    const FacePatch& fine = skin_.shapes().refined(formulation, sf.face, 1);
    const int first = skin_.model().elements[sf.element].first_node;
    const std::size_t count = fine.nodes.size();
    fine_values_.assign(static_cast<std::size_t>(fine.points()), 0.0);
    for (std::size_t a = 0; a < count; ++a) {
      const int local = fine.nodes[a];
      const double v = field.location == FieldLocation::Node ? field.values[conn[local]]
                                                             : field.values[first + local];
      for (int p = 0; p < fine.points(); ++p) fine_values_[p] += fine.N[p * count + a] * v;
    }
    const int m = fine.segments, n = shape.curved_segments;
    const auto at = [&](int i, int j) { return fine_values_[std::size_t(j) * (m + 1) + i]; };
    double error = 0.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int x = 2 * i, y = 2 * j;
        error = std::max({error, std::abs(at(x + 1, y + 1) - 0.5 * (at(x, y) + at(x + 2, y + 2))),
                          std::abs(at(x + 1, y) - 0.5 * (at(x, y) + at(x + 2, y))),
                          std::abs(at(x, y + 1) - 0.5 * (at(x, y) + at(x, y + 2))),
                          std::abs(at(x + 2, y + 1) - 0.5 * (at(x + 2, y) + at(x + 2, y + 2))),
                          std::abs(at(x + 1, y + 2) - 0.5 * (at(x, y + 2) + at(x + 2, y + 2)))});
      }
    int level = 0;
    while (level < kMaxRefinement && error > tolerance) error /= 4.0, ++level;
    return level;
  }

  // The value of the face node nearest to (s, t) (corners at the unit square's corners, the other
  // face nodes at their own (s, t)); the first one listed wins a tie.
  static double nearest_value(const FaceShape& shape, const int* conn, const ScalarField& field,
                              double s, double t) {
    static constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double best = std::numeric_limits<double>::max(), value = 0.0;
    const auto visit = [&](int local, double ns, double nt) {
      const double d = (s - ns) * (s - ns) + (t - nt) * (t - nt);
      if (d < best) best = d, value = field.values[conn[local]];
    };
    for (int k = 0; k < 4; ++k) visit(shape.corners[k], kCorner[k][0], kCorner[k][1]);
    for (std::size_t k = 0; k < shape.extra_nodes.size(); ++k)
      visit(shape.extra_nodes[k], shape.extra_st[k][0], shape.extra_st[k][1]);
    return value;
  }

  const SkinModel& skin_;
  const GeometryRequest& rq_;
  const Placement& place_;
  FrameGeometry& g_;
  std::vector<V3> local_x_;
  std::vector<double> local_v_;
  mutable std::vector<double> fine_values_;  // the field on the refined grid (refinement_level)
  bool oriented_ = true;
};

// Emits the layer's edges; returns whether its faces form a closed, consistently oriented skin.
bool emit_edges(FrameGeometry& g, std::vector<EdgeRef>& edges, const Rgb& color,
                double crease_cos) {
  bool closed = true;
  std::sort(edges.begin(), edges.end(), [](const EdgeRef& l, const EdgeRef& r) {
    return l.a != r.a ? l.a < r.a : (l.b != r.b ? l.b < r.b : l.base < r.base);
  });
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t end = k + 1;
    while (end < edges.size() && edges[end].a == edges[k].a && edges[end].b == edges[k].b) ++end;
    add_polyline(g, edges[k], color, g.edges);
    bool feature = end - k != 2;  // an open boundary or a non-manifold edge
    if (feature || edges[k].forward == edges[k + 1].forward) closed = false;
    if (!feature) {
      const V3 n0 = edge_mid_normal(g, edges[k]), n1 = edge_mid_normal(g, edges[k + 1]);
      const double l0 = n0.norm(), l1 = n1.norm();
      feature = l0 > 0 && l1 > 0 && n0.dot(n1) / (l0 * l1) < crease_cos;
    }
    if (feature) add_polyline(g, edges[k], color, g.features);
    k = end;
  }
  return closed;
}

void grow(FrameGeometry& g, const std::vector<Vertex>& vertices) {
  for (const Vertex& v : vertices)
    for (int k = 0; k < 3; ++k) {
      g.lower[k] = std::min(g.lower[k], v.position[k]);
      g.upper[k] = std::max(g.upper[k], v.position[k]);
    }
}

}  // namespace

SkinModel::SkinModel(const Model& model, const ElementRegistry& registry,
                     const std::vector<Layer>& layers, const ElementFilter& filter)
    : model_(model),
      formulations_(element_formulations(model, registry)),
      shell_normals_(resolve_shell_normals(model, formulations_)),
      shapes_(std::make_unique<FaceShapes>(formulations_)) {
  for (const TElement* f : formulations_)
    if (f && !drawn_.count(f)) drawn_.emplace(f, drawn_faces(*f));
  std::vector<char> used(model.coords.size(), 0), any(model.coords.size(), 0);
  for (const Layer& layer : layers) {
    if (!layer.visible) continue;
    LayerSkin skin;
    skin.name = layer.name;
    skin.color = layer.color;
    skin.elements = filter_elements(model, layer.elements, filter);
    skin.faces = extract_skin(model, formulations_, skin.elements);
    for (int e : skin.elements) {
      if (is_drawn_beam(model, *formulations_[e], e))
        skin.beams.push_back(e);
      else if (is_drawn_shell(*formulations_[e]))
        skin.shells.push_back(e);
      else if (is_line_element(*formulations_[e]))
        skin.lines.push_back(e);
    }
    std::fill(used.begin(), used.end(), 0);
    for (int e : skin.elements) {
      const int* nodes = model.element_nodes(e);
      for (int k = 0; k < model.elements[e].node_count; ++k) used[nodes[k]] = 1;
    }
    for (std::size_t n = 0; n < used.size(); ++n)
      if (used[n]) skin.nodes.push_back(static_cast<int>(n)), any[n] = 1;
    layers_.push_back(std::move(skin));
  }
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi{-lo[0], -lo[1], -lo[2]};
  bool seen = false;
  for (std::size_t n = 0; n < any.size(); ++n) {
    if (!any[n]) continue;
    seen = true;
    for (int k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], model.coords[n][k]), hi[k] = std::max(hi[k], model.coords[n][k]);
  }
  if (seen) {
    // Beam sections and shell thicknesses reach beyond their nodes.
    double radius = 0.0;
    for (const LayerSkin& layer : layers_)
      radius = std::max({radius, largest_beam_section_radius(model, layer.beams),
                         largest_shell_reach(model, layer.shells)});
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      lo[k] -= radius, hi[k] += radius;
      centre_[k] = 0.5 * (lo[k] + hi[k]), d2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    size_ = std::sqrt(d2);
  }
}

SkinModel::~SkinModel() = default;

std::size_t SkinModel::face_count() const {
  std::size_t count = 0;
  for (const LayerSkin& layer : layers_) count += layer.faces.size();
  return count;
}

std::vector<int> SkinModel::visible_nodes() const {
  std::vector<int> nodes;
  for (const LayerSkin& layer : layers_)
    nodes.insert(nodes.end(), layer.nodes.begin(), layer.nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

FrameGeometry build_geometry(const SkinModel& skin, const GeometryRequest& rq) {
  FrameGeometry g;
  g.origin = skin.centre();
  const Placement place(skin.model(), g.origin, rq.displacement, rq.scale);
  const double crease_cos = std::cos(rq.feature_angle_degrees * 3.14159265358979323846 / 180.0);
  LayerTessellator tessellate(skin, rq, place, g);
  std::vector<EdgeRef> edges;
  g.closed = !skin.layers().empty();
  for (const SkinModel::LayerSkin& layer : skin.layers()) {
    edges.clear();
    for (const SkinFace& face : layer.faces) tessellate.face(face, layer.color, edges);
    if (!emit_edges(g, edges, layer.color, crease_cos)) g.closed = false;
    if (!tessellate.oriented()) g.closed = false;
    add_line_elements(skin, layer, rq, g.origin, g.bars);
    if (!layer.beams.empty() && rq.beam_sections) {
      add_beam_elements(skin, layer, rq, g);
      g.closed = false;  // the tubes are drawn without back-face culling
    }
    if (!layer.shells.empty()) {
      add_shell_elements(skin, layer, rq, g);
      g.closed = false;  // nor are the shells
    }
    if (!rq.points) continue;
    for (int node : layer.nodes) {
      float t = -1.0f;
      if (rq.field && rq.field->location == FieldLocation::Node && rq.field->defined_at(node))
        t = static_cast<float>(rq.colors->normalized(rq.field->values[node]));
      g.points.push_back(make_vertex(place(node), V3::Zero(), layer.color, t));
    }
  }
  if (rq.outline) {
    GeometryRequest undeformed;
    undeformed.points = false;
    undeformed.beam_sections = false;  // beams: their axes below
    undeformed.feature_angle_degrees = rq.feature_angle_degrees;
    if (rq.hide_undefined_faces) {  // the outline of the same faces
      undeformed.field = rq.field;
      undeformed.colors = rq.colors;
      undeformed.hide_undefined_faces = true;
    }
    FrameGeometry base = build_geometry(skin, undeformed);
    g.outline = std::move(base.features);
    g.outline.insert(g.outline.end(), base.bars.begin(), base.bars.end());  // undeformed bars
    for (const SkinModel::LayerSkin& layer : skin.layers())
      add_beam_axes(skin, layer, g.origin, g.outline);
    for (Vertex& v : g.outline)
      v.color[0] = kOutline.r, v.color[1] = kOutline.g, v.color[2] = kOutline.b;
  }
  const float big = std::numeric_limits<float>::max();
  g.lower = {big, big, big};
  g.upper = {-big, -big, -big};
  grow(g, g.face_vertices);
  grow(g, g.points);
  grow(g, g.outline);
  grow(g, g.edges);
  grow(g, g.bars);
  if (g.lower[0] > g.upper[0]) g.lower = g.upper = {0, 0, 0};
  return g;
}

bool face_carries(const SkinModel& skin, const ScalarField& field, const SkinFace& face) {
  const Model& model = skin.model();
  const int* conn = model.element_nodes(face.element);
  std::vector<int> nodes;
  for (int a : skin.face_def(face.element, face.face).nodes) nodes.push_back(conn[a]);
  if (!std::all_of(nodes.begin(), nodes.end(), [&](int n) { return field.defined_at(n); }))
    return false;
  // The corners' normal, turned away from the element's centre.
  const FaceShape& shape = skin.shapes().get(skin.formulations()[face.element], face.face);
  const auto at = [&](int local) -> Eigen::Vector3d { return as_eigen(model.coords[conn[local]]); };
  const Eigen::Vector3d c0 = at(shape.corners[0]), c1 = at(shape.corners[1]),
                        c2 = at(shape.corners[2]), c3 = at(shape.corners[3]);
  Eigen::Vector3d normal = (c2 - c0).cross(c3 - c1);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  const int count = model.elements[face.element].node_count;
  for (int k = 0; k < count; ++k) centre += at(k) / count;
  if (normal.dot(0.25 * (c0 + c1 + c2 + c3) - centre) < 0) normal = -normal;
  const double length = normal.norm();
  const Vec3 outward = length > 0 ? to_vec3(normal / length) : Vec3{0, 0, 0};
  return field.carries(face.element, face.face, nodes, outward);
}

namespace {

// With a field drawn on shells from their point tensors: per node, whether a visible element
// other than such a shell uses it (a node of shells only is not drawn with its nodal value).
std::vector<char> nodes_drawn_by_value(const SkinModel& skin,
                                       const std::vector<char>& fibre_shell) {
  const Model& model = skin.model();
  std::vector<char> used(model.coords.size(), 0);
  for (const SkinModel::LayerSkin& layer : skin.layers())
    for (int e : layer.elements) {
      if (fibre_shell[e]) continue;
      const int* nodes = model.element_nodes(e);
      for (int k = 0; k < model.elements[e].node_count; ++k) used[nodes[k]] = 1;
    }
  return used;
}

}  // namespace

std::array<double, 2> field_range(const SkinModel& skin, const ScalarField& field) {
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  const auto visit = [&](double v) { lo = std::min(lo, v), hi = std::max(hi, v); };
  const Model& model = skin.model();
  // Shells coloured by their fibre tensors: their values on the fibre, below.
  std::vector<char> fibre_shell(model.elements.size(), 0);
  if (field.tensor_value && !field.point_offset.empty())
    for (const SkinModel::LayerSkin& layer : skin.layers()) {
      for (int e : layer.shells) fibre_shell[e] = 1;
      if (field.station_values)  // beams too: their nodes hold no section force
        for (int e : layer.beams) fibre_shell[e] = 1;
    }
  if (field.location == FieldLocation::Node) {
    const std::vector<char> by_value = nodes_drawn_by_value(skin, fibre_shell);
    for (int n : skin.visible_nodes())
      if (field.defined_at(n) && by_value[n]) visit(field.values[n]);
  } else {
    for (const SkinModel::LayerSkin& layer : skin.layers())
      for (int e : layer.elements) {
        if (fibre_shell[e]) continue;
        if (field.location == FieldLocation::Element) {
          visit(field.values[e]);
          continue;
        }
        const Element& element = model.elements[e];
        for (int k = 0; k < element.node_count; ++k) visit(field.values[element.first_node + k]);
      }
  }
  // Beams coloured by fibre tensors: the values over their sections.
  for (const SkinModel::LayerSkin& layer : skin.layers()) {
    const std::array<double, 2> beams = beam_field_range(skin, layer.beams, field);
    if (beams[0] <= beams[1]) visit(beams[0]), visit(beams[1]);
    const std::array<double, 2> shells = shell_field_range(skin, layer.shells, field);
    if (shells[0] <= shells[1]) visit(shells[0]), visit(shells[1]);
  }
  if (lo > hi) return {0.0, 0.0};
  return {lo, hi};
}

}  // namespace styk::render
