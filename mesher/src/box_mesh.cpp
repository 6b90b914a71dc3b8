#include "styk/mesher/box_mesh.hpp"

#include <stdexcept>

#include "styk/mesher/mesh_size_limit.hpp"

namespace styk::mesher {
namespace {

// Corner offsets of the Abaqus hexahedron (nodes 1-8) in units of half an element.
constexpr int kCorners[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                                {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}};
// Mid-edge offsets of C3D20 nodes 9-20.
constexpr int kMidEdges[12][3] = {{1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2},
                                  {1, 2, 2}, {0, 1, 2}, {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};

// A C3D20 grid point is a node unless two or more of its addresses are odd (face/body centres).
bool is_serendipity_point(int i, int j, int k) { return (i % 2) + (j % 2) + (k % 2) <= 1; }

}  // namespace

BoxMesh::BoxMesh(const BoxSpec& spec, Model& model) : spec_(spec) {
  if (spec.type == "C3D8") {
    step_ = 1;
  } else if (spec.type == "C3D20") {
    step_ = 2;
  } else {
    throw std::invalid_argument("BoxMesh: element type must be C3D8 or C3D20, not " + spec.type);
  }
  for (int a = 0; a < 3; ++a)
    if (spec.divisions[a] < 1) throw std::invalid_argument("BoxMesh: divisions must be >= 1");
  check_block_fits(spec.divisions, step_, spec.type);
  for (int a = 0; a < 3; ++a) grid_[a] = step_ * spec.divisions[a] + 1;

  const SourceLoc here{"box mesher", 0};
  node_index_.assign(static_cast<std::size_t>(grid_[0]) * grid_[1] * grid_[2], -1);
  for (int k = 0; k < grid_[2]; ++k)
    for (int j = 0; j < grid_[1]; ++j)
      for (int i = 0; i < grid_[0]; ++i) {
        if (step_ == 2 && !is_serendipity_point(i, j, k)) continue;
        const std::size_t address = i + static_cast<std::size_t>(grid_[0]) * (j + grid_[1] * k);
        const Vec3 x{spec.origin[0] + spec.size[0] * i / (grid_[0] - 1),
                     spec.origin[1] + spec.size[1] * j / (grid_[1] - 1),
                     spec.origin[2] + spec.size[2] * k / (grid_[2] - 1)};
        node_index_[address] = model.add_node(static_cast<Id>(address + 1), x, here);
      }

  std::vector<int> conn(step_ == 1 ? 8 : 20);
  const int half = step_ == 1 ? 2 : 1;  // offsets above are in half-elements
  const auto& d = spec.divisions;
  for (int ez = 0; ez < d[2]; ++ez)
    for (int ey = 0; ey < d[1]; ++ey)
      for (int ex = 0; ex < d[0]; ++ex) {
        const int i0 = ex * step_, j0 = ey * step_, k0 = ez * step_;
        for (int c = 0; c < 8; ++c)
          conn[c] = node_at(i0 + kCorners[c][0] / half, j0 + kCorners[c][1] / half,
                            k0 + kCorners[c][2] / half);
        if (step_ == 2)
          for (int m = 0; m < 12; ++m)
            conn[8 + m] = node_at(i0 + kMidEdges[m][0], j0 + kMidEdges[m][1], k0 + kMidEdges[m][2]);
        const Id id = 1 + ex + static_cast<Id>(d[0]) * (ey + static_cast<Id>(d[1]) * ez);
        elements_.push_back(model.add_element(id, spec.type, conn, here));
      }

  if (!spec.elset.empty()) {
    ElementSet& set = model.elsets[to_upper(spec.elset)];
    set.name = to_upper(spec.elset);
    set.elements.insert(set.elements.end(), elements_.begin(), elements_.end());
  }
}

int BoxMesh::node_at(int i, int j, int k) const {
  if (i < 0 || j < 0 || k < 0 || i >= grid_[0] || j >= grid_[1] || k >= grid_[2]) return -1;
  return node_index_[i + static_cast<std::size_t>(grid_[0]) * (j + grid_[1] * k)];
}

std::vector<int> BoxMesh::face_nodes(int axis, int side) const {
  std::vector<int> out;
  const int fixed = side == 0 ? 0 : grid_[axis] - 1;
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

std::vector<BoxMesh::FaceRef> BoxMesh::face_elements(int axis, int side) const {
  // Abaqus face numbers: x-min S6, x-max S4, y-min S3, y-max S5, z-min S1, z-max S2.
  static constexpr int kFace[3][2] = {{5, 3}, {2, 4}, {0, 1}};
  std::vector<FaceRef> out;
  const auto& d = spec_.divisions;
  for (int ez = 0; ez < d[2]; ++ez)
    for (int ey = 0; ey < d[1]; ++ey)
      for (int ex = 0; ex < d[0]; ++ex) {
        const int e[3] = {ex, ey, ez};
        if (e[axis] != (side == 0 ? 0 : d[axis] - 1)) continue;
        out.push_back({elements_[ex + d[0] * (ey + d[1] * ez)], kFace[axis][side]});
      }
  return out;
}

}  // namespace styk::mesher
