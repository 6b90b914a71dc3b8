#include "styk/mesher/split.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "styk/mesher/hex_topology.hpp"

namespace styk::mesher {
namespace {

constexpr int kCentre = 8;  // "local corner" index of a brick's centre node

// Brick faces S1..S6 by their corners, going round (Abaqus).
constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                              {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
// The two faces normal to natural axis 0, 1, 2 (xi, eta, zeta): the -1 side, then the +1 side.
constexpr int kAxisFaces[3][2] = {{5, 3}, {2, 4}, {0, 1}};

std::string brick_name(int e) { return "element " + std::to_string(e + 1); }

// What the target type looks like: corner count and, for each further node, the corner pair
// (in its own numbering) whose midpoint it is.
struct TargetLayout {
  std::string type;
  int corners = 0;
  std::vector<std::array<int, 2>> mid_edges;
  double orientation = 1.0;  // sign of the reference element's corner volume
  std::vector<std::vector<int>> faces;
};

TargetLayout target_layout(const ElementRegistry& registry, const std::string& type, int corners) {
  const TElement* element = registry.find(type);
  if (!element) throw std::invalid_argument("split: element type " + type + " is not registered");
  TargetLayout out;
  out.type = to_upper(type);
  const std::vector<int> c = corner_nodes(*element);
  const std::vector<Vec3>& xi = element->natural_nodes();
  bool corners_first = static_cast<int>(c.size()) == corners;
  for (int k = 0; corners_first && k < corners; ++k) corners_first = c[k] == k;
  if (!corners_first || element->form() != ElementForm::Solid)
    throw std::invalid_argument("split: " + out.type + " is no solid with " +
                                std::to_string(corners) + " corners numbered first");
  out.corners = corners;
  for (int k = corners; k < element->node_count(); ++k) {
    std::array<int, 2> pair{-1, -1};
    for (int i = 0; i < corners && pair[0] < 0; ++i)
      for (int j = i + 1; j < corners && pair[0] < 0; ++j) {
        double d = 0.0;
        for (int a = 0; a < 3; ++a) d += std::abs(0.5 * (xi[i][a] + xi[j][a]) - xi[k][a]);
        if (d < 1e-12) pair = {i, j};
      }
    if (pair[0] < 0)
      throw std::invalid_argument("split: node " + std::to_string(k + 1) + " of " + out.type +
                                  " is not the midpoint of an edge");
    out.mid_edges.push_back(pair);
  }
  Eigen::Matrix3d edges;
  for (int r = 0; r < 3; ++r)
    for (int a = 0; a < 3; ++a) edges(r, a) = xi[r + 1][a] - xi[0][a];
  out.orientation = edges.determinant() > 0 ? 1.0 : -1.0;
  for (const FaceDef& f : element->faces()) out.faces.push_back(f.nodes);
  return out;
}

// One brick being split: its nodes, natural corner positions and placement.
struct Brick {
  int element = 0;
  std::string type;  // C3D8 or C3D20
  std::vector<int> nodes;
  int centre = -1;  // mesh node of the centre, when one was made

  int id(int local) const { return local == kCentre ? centre : nodes[local]; }
  static Vec3 natural(int local) {
    return local == kCentre ? Vec3{0, 0, 0} : natural_nodes("C3D8")[local];
  }
};

// The diagonal of brick face f through its corner of smallest node index (and the opposite
// corner): the rule of the tetrahedra, which every face's two bricks apply alike.
std::array<int, 2> diagonal(const Brick& b, int f) {
  int k = 0;
  for (int i = 1; i < 4; ++i)
    if (b.nodes[kFaces[f][i]] < b.nodes[kFaces[f][k]]) k = i;
  return {kFaces[f][k], kFaces[f][(k + 2) % 4]};
}

using DiagonalRule = std::array<int, 2> (*)(const Mesh&, const Brick&, int);

std::array<int, 2> smallest_index_diagonal(const Mesh&, const Brick& b, int f) {
  return diagonal(b, f);
}

// The diagonal of face f that runs closer to a fixed direction in space (ties: the one through
// the smallest node index): the rule of the wedges. It depends only on the face's corners, so both
// bricks of a face agree, and the two faces a brick cuts, nearly parallel in any reasonable
// brick, get parallel diagonals even when the node numbering runs another way in each layer.
std::array<int, 2> geometric_diagonal(const Mesh& mesh, const Brick& b, int f) {
  static const Eigen::Vector3d kDirection = Eigen::Vector3d(1.0, 0.618, 0.382).normalized();
  const auto along = [&](int i, int j) {
    Eigen::Vector3d d;
    for (int a = 0; a < 3; ++a) d[a] = mesh.nodes[b.nodes[j]][a] - mesh.nodes[b.nodes[i]][a];
    return std::abs(d.normalized().dot(kDirection));
  };
  const int* c = kFaces[f];
  const double first = along(c[0], c[2]), second = along(c[1], c[3]);
  if (std::abs(first - second) < 1e-9) return diagonal(b, f);
  return first > second ? std::array<int, 2>{c[0], c[2]} : std::array<int, 2>{c[1], c[3]};
}

// The corner across the brick from corner c along natural axis `axis`.
int partner(int c, int axis) {
  Vec3 p = Brick::natural(c);
  p[axis] = -p[axis];
  for (int k = 0; k < 8; ++k)
    if (Brick::natural(k) == p) return k;
  return -1;
}

// A wedge of a brick: its lower triangle (a, b, c) and the corners above along `axis`.
struct Prism {
  std::array<int, 3> lower;
  std::array<int, 3> upper;
};

// The two prisms of a brick cut through the parallel diagonals of its faces normal to `axis`, or
// false when those diagonals are not parallel.
bool prisms_along(const Mesh& mesh, const Brick& b, int axis, DiagonalRule rule,
                  std::array<Prism, 2>& out) {
  const std::array<int, 2> low = rule(mesh, b, kAxisFaces[axis][0]);
  const std::array<int, 2> high = rule(mesh, b, kAxisFaces[axis][1]);
  const std::array<int, 2> up = {partner(low[0], axis), partner(low[1], axis)};
  if (!((up[0] == high[0] && up[1] == high[1]) || (up[0] == high[1] && up[1] == high[0])))
    return false;
  std::vector<int> others;
  for (int k : kFaces[kAxisFaces[axis][0]])
    if (k != low[0] && k != low[1]) others.push_back(k);
  for (int s = 0; s < 2; ++s) {
    out[s].lower = {low[0], low[1], others[s]};
    for (int i = 0; i < 3; ++i) out[s].upper[i] = partner(out[s].lower[i], axis);
  }
  return true;
}

double signed_volume(const std::vector<int>& locals) {
  Eigen::Matrix3d edges;
  const Vec3 o = Brick::natural(locals[0]);
  for (int r = 0; r < 3; ++r)
    for (int a = 0; a < 3; ++a) edges(r, a) = Brick::natural(locals[r + 1])[a] - o[a];
  return edges.determinant();
}

// A tetrahedron's corners (brick-local) turned to the target's orientation.
std::vector<int> oriented_tet(std::vector<int> t, const TargetLayout& layout) {
  if (signed_volume(t) * layout.orientation < 0) std::swap(t[1], t[2]);
  return t;
}

// The 3 tetrahedra of a prism, its quadrilateral faces cut through their smallest-index corners.
std::vector<std::vector<int>> prism_tets(const Brick& b, Prism p, const TargetLayout& layout) {
  int best = 0;  // position of the smallest node index among the six, 0..5
  for (int k = 1; k < 6; ++k)
    if (b.id(k < 3 ? p.lower[k] : p.upper[k - 3]) <
        b.id(best < 3 ? p.lower[best] : p.upper[best - 3]))
      best = k;
  if (best >= 3) std::swap(p.lower, p.upper), best -= 3;
  std::rotate(p.lower.begin(), p.lower.begin() + best, p.lower.end());
  std::rotate(p.upper.begin(), p.upper.begin() + best, p.upper.end());
  const int a = p.lower[0], bb = p.lower[1], c = p.lower[2];
  const int a2 = p.upper[0], b2 = p.upper[1], c2 = p.upper[2];
  std::vector<std::vector<int>> tets = {oriented_tet({a, a2, b2, c2}, layout)};
  const int smallest = std::min({b.id(bb), b.id(c), b.id(b2), b.id(c2)});
  if (smallest == b.id(bb) || smallest == b.id(c2)) {  // diagonal b - c'
    tets.push_back(oriented_tet({a, bb, c, c2}, layout));
    tets.push_back(oriented_tet({a, bb, c2, b2}, layout));
  } else {  // diagonal c - b'
    tets.push_back(oriented_tet({a, bb, c, b2}, layout));
    tets.push_back(oriented_tet({a, c, c2, b2}, layout));
  }
  return tets;
}

// The 12 tetrahedra of a brick around its centre: two per face, cut along its diagonal.
std::vector<std::vector<int>> centred_tets(const Brick& b, const TargetLayout& layout) {
  std::vector<std::vector<int>> tets;
  for (int f = 0; f < 6; ++f) {
    const std::array<int, 2> d = diagonal(b, f);
    for (int k : kFaces[f])
      if (k != d[0] && k != d[1]) tets.push_back(oriented_tet({d[0], d[1], k, kCentre}, layout));
  }
  return tets;
}

// A wedge's corners (brick-local): lower triangle then upper, turned to the target's orientation.
std::vector<int> oriented_wedge(const Prism& p, const TargetLayout& layout) {
  std::vector<int> w = {p.lower[0], p.lower[1], p.lower[2], p.upper[0], p.upper[1], p.upper[2]};
  if (signed_volume({w[0], w[1], w[2], w[3]}) * layout.orientation < 0)
    std::swap(w[1], w[2]), std::swap(w[4], w[5]);
  return w;
}

// Builds the pieces into mesh elements, placing or reusing their mid-edge nodes.
class PieceBuilder {
 public:
  PieceBuilder(Mesh& mesh, const TargetLayout& layout) : mesh_(mesh), layout_(layout) {}

  MeshElement make(const Brick& b, const std::vector<int>& corners) {
    MeshElement element{layout_.type, {}};
    for (int local : corners) element.nodes.push_back(b.id(local));
    for (const auto& edge : layout_.mid_edges)
      element.nodes.push_back(mid_node(b, corners[edge[0]], corners[edge[1]]));
    return element;
  }

  int centre(const Brick& b) { return mesh_.add_node(place(b, {0, 0, 0})); }

 private:
  Vec3 place(const Brick& b, const Vec3& xi) const {
    double N[20];
    int n = 8;
    if (b.type == "C3D20") {
      hex20_shape(xi, N);
      n = 20;
    } else {
      hex8_shape(xi, N);
    }
    Vec3 x{0, 0, 0};
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) x[d] += N[k] * mesh_.nodes[b.nodes[k]][d];
    return x;
  }

  int mid_node(const Brick& b, int u, int v) {
    const std::pair<int, int> key = std::minmax(b.id(u), b.id(v));
    const auto found = mid_.find(key);
    if (found != mid_.end()) return found->second;
    int node = -1;
    if (b.type == "C3D20" && u != kCentre && v != kCentre) {
      // A brick edge: its own mid-edge node.
      const std::vector<Vec3>& brick = natural_nodes("C3D20");
      for (int k = 8; k < 20 && node < 0; ++k) {
        bool mid = true;
        for (int d = 0; d < 3; ++d) mid = mid && brick[k][d] == 0.5 * (brick[u][d] + brick[v][d]);
        if (mid) node = b.nodes[k];
      }
    }
    if (node < 0 && b.type != "C3D20") {
      // A C3D8 brick carries no curved geometry: its pieces keep straight edges, so they
      // reproduce constant strain exactly (a curved C3D10 does not with CalculiX's 4-point rule,
      // whose degree 2 falls short of the cubic dN/dx det J: SPEC §3.1.8 patch test).
      const Vec3& p = mesh_.nodes[b.id(u)];
      const Vec3& q = mesh_.nodes[b.id(v)];
      node = mesh_.add_node({0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])});
    } else if (node < 0) {
      const Vec3 p = Brick::natural(u), q = Brick::natural(v);
      node =
          mesh_.add_node(place(b, {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])}));
    }
    mid_.emplace(key, node);
    return node;
  }

  Mesh& mesh_;
  const TargetLayout& layout_;
  std::map<std::pair<int, int>, int> mid_;
};

// Replaces every brick by its pieces and carries sets and surfaces over.
void replace_bricks(Mesh& mesh, const TargetLayout& layout,
                    const std::vector<std::vector<MeshElement>>& pieces) {
  std::vector<MeshElement> elements;
  std::vector<std::vector<int>> children(mesh.elements.size());
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    if (pieces[e].empty()) {
      children[e].push_back(static_cast<int>(elements.size()));
      elements.push_back(mesh.elements[e]);
      continue;
    }
    for (const MeshElement& piece : pieces[e]) {
      children[e].push_back(static_cast<int>(elements.size()));
      elements.push_back(piece);
    }
  }
  for (auto& [name, members] : mesh.element_sets) {
    std::vector<int> now;
    for (int e : members) now.insert(now.end(), children[e].begin(), children[e].end());
    std::sort(now.begin(), now.end());
    members = std::move(now);
  }
  for (auto& [name, faces] : mesh.surfaces) {
    std::vector<FaceRef> now;
    for (const FaceRef& f : faces) {
      if (pieces[f.element].empty()) {
        now.push_back({children[f.element][0], f.face});
        continue;
      }
      std::vector<int> face_nodes;
      for (int k : kFaces[f.face]) face_nodes.push_back(mesh.elements[f.element].nodes[k]);
      std::sort(face_nodes.begin(), face_nodes.end());
      for (int child : children[f.element])
        for (std::size_t j = 0; j < layout.faces.size(); ++j) {
          bool inside = true;
          for (std::size_t k = 0; k < layout.faces[j].size() && inside; ++k) {
            if (static_cast<int>(layout.faces[j][k]) >= layout.corners) continue;
            inside = std::binary_search(face_nodes.begin(), face_nodes.end(),
                                        elements[child].nodes[layout.faces[j][k]]);
          }
          if (inside) now.push_back({child, static_cast<int>(j)});
        }
    }
    std::sort(now.begin(), now.end());
    faces = std::move(now);
  }
  mesh.elements = std::move(elements);
  mesh.faces_of_type[layout.type] = layout.faces;
}

bool is_brick(const MeshElement& element) {
  return element.type == "C3D8" || element.type == "C3D20";
}

std::vector<Brick> bricks_of(const Mesh& mesh, const std::vector<int>& listed) {
  std::vector<Brick> out;
  if (listed.empty()) {
    for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
      if (is_brick(mesh.elements[e]))
        out.push_back(Brick{e, mesh.elements[e].type, mesh.elements[e].nodes, -1});
    return out;
  }
  for (int e : listed) {
    if (e < 0 || e >= static_cast<int>(mesh.elements.size()) || !is_brick(mesh.elements[e]))
      throw std::invalid_argument("split: " + brick_name(e) + " is no C3D8/C3D20 brick");
    out.push_back(Brick{e, mesh.elements[e].type, mesh.elements[e].nodes, -1});
  }
  return out;
}

}  // namespace

int split_to_tetrahedra(Mesh& mesh, const ElementRegistry& registry, const std::string& type,
                        const std::vector<int>& bricks) {
  const TargetLayout layout = target_layout(registry, type, 4);
  PieceBuilder builder(mesh, layout);
  std::vector<std::vector<MeshElement>> pieces(mesh.elements.size());
  int centred = 0;
  for (Brick& b : bricks_of(mesh, bricks)) {
    std::array<Prism, 2> prisms;
    std::vector<std::vector<int>> tets;
    for (int axis : {2, 1, 0})
      if (tets.empty() && prisms_along(mesh, b, axis, smallest_index_diagonal, prisms))
        for (const Prism& p : prisms)
          for (const auto& t : prism_tets(b, p, layout)) tets.push_back(t);
    if (tets.empty()) {
      b.centre = builder.centre(b);
      tets = centred_tets(b, layout);
      ++centred;
    }
    for (const auto& t : tets) pieces[b.element].push_back(builder.make(b, t));
  }
  replace_bricks(mesh, layout, pieces);
  return centred;
}

void split_to_wedges(Mesh& mesh, const ElementRegistry& registry, const std::string& type, int axis,
                     const std::vector<int>& bricks) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("split_to_wedges: axis must be 0, 1 or 2");
  const TargetLayout layout = target_layout(registry, type, 6);
  PieceBuilder builder(mesh, layout);
  std::vector<std::vector<MeshElement>> pieces(mesh.elements.size());
  for (const Brick& b : bricks_of(mesh, bricks)) {
    std::array<Prism, 2> prisms;
    if (!prisms_along(mesh, b, axis, geometric_diagonal, prisms))
      throw std::invalid_argument("split_to_wedges: " + brick_name(b.element) +
                                  ": the diagonals of its two faces normal to the wedge axis are "
                                  "not parallel, so its wedges would not conform");
    for (const Prism& p : prisms)
      pieces[b.element].push_back(builder.make(b, oriented_wedge(p, layout)));
  }
  replace_bricks(mesh, layout, pieces);
}

}  // namespace styk::mesher
