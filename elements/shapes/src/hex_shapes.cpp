#include "styk/elements/hex_shapes.hpp"

#include <array>

namespace styk {

namespace {

// Node signs (xi_i, eta_i, zeta_i) of the 20-node hexahedron; the first 8 rows are the corners
// shared with the 8-node element. A 0 marks the coordinate along which a mid-edge node is centred.
constexpr std::array<std::array<int, 3>, 20> kHex20Nodes = {{
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},  // 1-4
    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1},   // 5-8
    {0, -1, -1},  {1, 0, -1},  {0, 1, -1}, {-1, 0, -1},  // 9-12
    {0, -1, 1},   {1, 0, 1},   {0, 1, 1},  {-1, 0, 1},   // 13-16
    {-1, -1, 0},  {1, -1, 0},  {1, 1, 0},  {-1, 1, 0},   // 17-20
}};

std::vector<Vec3> natural_nodes(int count) {
  std::vector<Vec3> nodes;
  nodes.reserve(count);
  for (int i = 0; i < count; ++i)
    nodes.push_back(Vec3{static_cast<double>(kHex20Nodes[i][0]),
                         static_cast<double>(kHex20Nodes[i][1]),
                         static_cast<double>(kHex20Nodes[i][2])});
  return nodes;
}

}  // namespace

std::vector<Vec3> hex8_natural_nodes() { return natural_nodes(8); }
std::vector<Vec3> hex20_natural_nodes() { return natural_nodes(20); }

std::vector<FaceDef> hex_faces(bool with_mid_edges) {
  // Abaqus face node lists (1-based): corners, then mid-edge nodes.
  struct Face {
    std::array<int, 4> corners;
    std::array<int, 4> mid_edges;
    int axis;
    double value;
  };
  static constexpr std::array<Face, 6> kFaces = {{
      {{1, 2, 3, 4}, {9, 10, 11, 12}, 2, -1.0},   // S1 zeta = -1
      {{5, 8, 7, 6}, {16, 15, 14, 13}, 2, 1.0},   // S2 zeta = +1
      {{1, 5, 6, 2}, {17, 13, 18, 9}, 1, -1.0},   // S3 eta = -1
      {{2, 6, 7, 3}, {18, 14, 19, 10}, 0, 1.0},   // S4 xi = +1
      {{3, 7, 8, 4}, {19, 15, 20, 11}, 1, 1.0},   // S5 eta = +1
      {{4, 8, 5, 1}, {20, 16, 17, 12}, 0, -1.0},  // S6 xi = -1
  }};
  std::vector<FaceDef> faces;
  for (const Face& f : kFaces) {
    FaceDef def;
    for (int node : f.corners) def.nodes.push_back(node - 1);
    if (with_mid_edges)
      for (int node : f.mid_edges) def.nodes.push_back(node - 1);
    def.axis = f.axis;
    def.value = f.value;
    faces.push_back(std::move(def));
  }
  return faces;
}

void hex8_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  for (int i = 0; i < 8; ++i) {
    const double si = kHex20Nodes[i][0], ti = kHex20Nodes[i][1], ui = kHex20Nodes[i][2];
    const double a = 1.0 + si * xi[0], b = 1.0 + ti * xi[1], c = 1.0 + ui * xi[2];
    N(i) = 0.125 * a * b * c;
    dN(i, 0) = 0.125 * si * b * c;
    dN(i, 1) = 0.125 * ti * a * c;
    dN(i, 2) = 0.125 * ui * a * b;
  }
}

void hex20_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const double x = xi[0], y = xi[1], z = xi[2];
  for (int i = 0; i < 8; ++i) {
    // Corner: N = 1/8 (1 + xi_i xi)(1 + eta_i eta)(1 + zeta_i zeta)(xi_i xi + eta_i eta +
    // zeta_i zeta - 2).
    const double si = kHex20Nodes[i][0], ti = kHex20Nodes[i][1], ui = kHex20Nodes[i][2];
    const double a = 1.0 + si * x, b = 1.0 + ti * y, c = 1.0 + ui * z;
    const double s = si * x + ti * y + ui * z - 2.0;
    N(i) = 0.125 * a * b * c * s;
    dN(i, 0) = 0.125 * si * b * c * (s + a);
    dN(i, 1) = 0.125 * ti * a * c * (s + b);
    dN(i, 2) = 0.125 * ui * a * b * (s + c);
  }
  for (int i = 8; i < 20; ++i) {
    // Mid-edge: quadratic bubble (1 - q^2) along its edge direction q, linear in the other two.
    const auto& node = kHex20Nodes[i];
    const int along = node[0] == 0 ? 0 : (node[1] == 0 ? 1 : 2);
    const int p = (along + 1) % 3, r = (along + 2) % 3;
    const double q = xi[along];
    const double bubble = 1.0 - q * q;
    const double lp = 1.0 + node[p] * xi[p], lr = 1.0 + node[r] * xi[r];
    N(i) = 0.25 * bubble * lp * lr;
    dN(i, along) = -0.5 * q * lp * lr;
    dN(i, p) = 0.25 * bubble * node[p] * lr;
    dN(i, r) = 0.25 * bubble * lp * node[r];
  }
}

}  // namespace styk
