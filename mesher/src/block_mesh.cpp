#include "styk/mesher/block_mesh.hpp"

#include <stdexcept>

#include "styk/mesher/hex_topology.hpp"
#include "styk/mesher/mesh_size_limit.hpp"

namespace styk::mesher {
namespace {

// Corner offsets of nodes 1-8 and mid-edge offsets of nodes 9-20, in half elements.
constexpr int kCorners[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                                {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}};
constexpr int kMidEdges[12][3] = {{1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2},
                                  {1, 2, 2}, {0, 1, 2}, {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};

// Fine-grid natural coordinates along one direction: element ends from the grading, plus the
// parameter midpoints when step == 2.
std::vector<double> fine_coordinates(int n, double ratio, int step) {
  const std::vector<double> t = graded_parameters(n, ratio);
  std::vector<double> out;
  for (int i = 0; i < n; ++i) {
    out.push_back(2 * t[i] - 1);
    if (step == 2) out.push_back(t[i] + t[i + 1] - 1);
  }
  out.push_back(1.0);
  return out;
}

double map_jacobian(const BlockMap& map, const Vec3& xi) {
  const double h = 1e-6;
  Vec3 d[3];
  for (int a = 0; a < 3; ++a) {
    Vec3 p = xi, m = xi;
    p[a] += h;
    m[a] -= h;
    const Vec3 xp = map(p), xm = map(m);
    for (int c = 0; c < 3; ++c) d[a][c] = (xp[c] - xm[c]) / (2 * h);
  }
  return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
         d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
}

}  // namespace

Block::Block(int step, std::array<int, 3> divisions, std::vector<int> node_index,
             std::vector<int> elements)
    : step_(step),
      divisions_(divisions),
      node_index_(std::move(node_index)),
      elements_(std::move(elements)) {
  for (int a = 0; a < 3; ++a) grid_[a] = step_ * divisions_[a] + 1;
}

int Block::node_at(int i, int j, int k) const {
  if (i < 0 || j < 0 || k < 0 || i >= grid_[0] || j >= grid_[1] || k >= grid_[2]) return -1;
  return node_index_[i + static_cast<std::size_t>(grid_[0]) *
                             (j + static_cast<std::size_t>(grid_[1]) * k)];
}

int Block::element_at(int ex, int ey, int ez) const {
  return elements_[ex + static_cast<std::size_t>(divisions_[0]) *
                            (ey + static_cast<std::size_t>(divisions_[1]) * ez)];
}

std::vector<int> Block::side_nodes(int axis, int value) const {
  std::vector<int> out;
  const int fixed = value < 0 ? 0 : grid_[axis] - 1;
  for (int k = 0; k < grid_[2]; ++k)
    for (int j = 0; j < grid_[1]; ++j)
      for (int i = 0; i < grid_[0]; ++i) {
        const int address[3] = {i, j, k};
        if (address[axis] != fixed) continue;
        const int n = node_at(i, j, k);
        if (n >= 0) out.push_back(n);
      }
  return out;
}

std::vector<FaceRef> Block::side_faces(int axis, int value) const {
  std::vector<FaceRef> out;
  const int face = face_index(axis, value);
  const int fixed = value < 0 ? 0 : divisions_[axis] - 1;
  for (int ez = 0; ez < divisions_[2]; ++ez)
    for (int ey = 0; ey < divisions_[1]; ++ey)
      for (int ex = 0; ex < divisions_[0]; ++ex) {
        const int e[3] = {ex, ey, ez};
        if (e[axis] == fixed) out.push_back({element_at(ex, ey, ez), face});
      }
  return out;
}

Block mesh_block(Mesh& mesh, const BlockMap& map, const BlockSpec& spec) {
  int step = 0;
  if (spec.type == "C3D8")
    step = 1;
  else if (spec.type == "C3D20")
    step = 2;
  else
    throw std::invalid_argument("mesh_block: element type must be C3D8 or C3D20, not " + spec.type);
  for (int a = 0; a < 3; ++a)
    if (spec.divisions[a] < 1) throw std::invalid_argument("mesh_block: divisions must be >= 1");
  check_block_fits(spec.divisions, step, spec.type);

  std::array<std::vector<double>, 3> xi;
  std::array<int, 3> grid{};
  for (int a = 0; a < 3; ++a) {
    xi[a] = fine_coordinates(spec.divisions[a], spec.grading[a], step);
    grid[a] = static_cast<int>(xi[a].size());
  }
  // Handedness: the element (0,0,0) must have a positive Jacobian.
  const Vec3 first_centre{(xi[0][0] + xi[0][step]) / 2, (xi[1][0] + xi[1][step]) / 2,
                          (xi[2][0] + xi[2][step]) / 2};
  if (!(map_jacobian(map, first_centre) > 0.0))
    throw std::invalid_argument("mesh_block: the block map is left-handed or degenerate");

  const std::size_t total = static_cast<std::size_t>(grid[0]) * grid[1] * grid[2];
  std::vector<int> node_index(total, -1);
  mesh.nodes.reserve(mesh.nodes.size() + total);
  for (int k = 0; k < grid[2]; ++k)
    for (int j = 0; j < grid[1]; ++j)
      for (int i = 0; i < grid[0]; ++i) {
        if (step == 2 && (i % 2) + (j % 2) + (k % 2) > 1) continue;  // no C3D20 node there
        node_index[i + static_cast<std::size_t>(grid[0]) *
                           (j + static_cast<std::size_t>(grid[1]) * k)] =
            mesh.add_node(map({xi[0][i], xi[1][j], xi[2][k]}));
      }

  const auto& d = spec.divisions;
  std::vector<int> elements;
  elements.reserve(static_cast<std::size_t>(d[0]) * d[1] * d[2]);
  mesh.elements.reserve(mesh.elements.size() + static_cast<std::size_t>(d[0]) * d[1] * d[2]);
  auto node_at = [&](int i, int j, int k) {
    return node_index[i + static_cast<std::size_t>(grid[0]) *
                              (j + static_cast<std::size_t>(grid[1]) * k)];
  };
  const int half = step == 1 ? 2 : 1;
  for (int ez = 0; ez < d[2]; ++ez)
    for (int ey = 0; ey < d[1]; ++ey)
      for (int ex = 0; ex < d[0]; ++ex) {
        std::vector<int> conn(step == 1 ? 8 : 20);
        const int i0 = ex * step, j0 = ey * step, k0 = ez * step;
        for (int c = 0; c < 8; ++c)
          conn[c] = node_at(i0 + kCorners[c][0] / half, j0 + kCorners[c][1] / half,
                            k0 + kCorners[c][2] / half);
        if (step == 2)
          for (int m = 0; m < 12; ++m)
            conn[8 + m] = node_at(i0 + kMidEdges[m][0], j0 + kMidEdges[m][1], k0 + kMidEdges[m][2]);
        elements.push_back(mesh.add_element(spec.type, std::move(conn)));
      }
  if (!spec.elset.empty()) mesh.add_to_element_set(spec.elset, elements);
  std::vector<std::vector<int>>& faces = mesh.faces_of_type[spec.type];
  faces.clear();
  for (int f = 0; f < 6; ++f) faces.push_back(face_local_nodes(spec.type, f));
  return Block(step, d, std::move(node_index), std::move(elements));
}

PatchMesh mesh_patch(const PatchMap& map, int nu, int nv, double grading_u, double grading_v,
                     int order) {
  if (order != 1 && order != 2) throw std::invalid_argument("mesh_patch: order must be 1 or 2");
  const std::vector<double> u = fine_coordinates(nu, grading_u, order);
  const std::vector<double> v = fine_coordinates(nv, grading_v, order);
  const int gu = static_cast<int>(u.size()), gv = static_cast<int>(v.size());
  PatchMesh out;
  std::vector<int> index(static_cast<std::size_t>(gu) * gv, -1);
  for (int j = 0; j < gv; ++j)
    for (int i = 0; i < gu; ++i) {
      if (order == 2 && i % 2 == 1 && j % 2 == 1) continue;  // 8-node quads: no centre node
      index[i + static_cast<std::size_t>(gu) * j] = static_cast<int>(out.nodes.size());
      out.nodes.push_back(map(u[i], v[j]));
    }
  auto at = [&](int i, int j) { return index[i + static_cast<std::size_t>(gu) * j]; };
  for (int ej = 0; ej < nv; ++ej)
    for (int ei = 0; ei < nu; ++ei) {
      const int i0 = ei * order, j0 = ej * order, s = order;
      std::vector<int> q = {at(i0, j0), at(i0 + s, j0), at(i0 + s, j0 + s), at(i0, j0 + s)};
      if (order == 2) {
        q.insert(q.end(), {at(i0 + 1, j0), at(i0 + 2, j0 + 1), at(i0 + 1, j0 + 2), at(i0, j0 + 1)});
      }
      out.quads.push_back(std::move(q));
    }
  return out;
}

}  // namespace styk::mesher
