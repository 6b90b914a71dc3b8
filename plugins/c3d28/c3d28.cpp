#include "c3d28.hpp"

#include <array>
#include <cmath>

#include <Eigen/Core>

#include "styk/elements/hex_shapes.hpp"

namespace styk::plugins {

namespace {

// The 4-point Gauss-Lobatto-Legendre nodes on [-1, 1]: -1, -a, a, 1 with a = 1/sqrt(5).
const double kA = 1.0 / std::sqrt(5.0);

// The 16 nodes of the bottom face (0-based element index, xi, eta): corners 1-4, the edge nodes
// 17-24 counter-clockwise (seen from +z) from edge 1-2, then the interior nodes 25-28.
struct BottomNode {
  int index;
  double xi, eta;
};
// clang-format off
const std::array<BottomNode, 16> kBottom = {{
    {0, -1, -1},    {1, 1, -1},    {2, 1, 1},    {3, -1, 1},     // 1-4
    {16, -kA, -1},  {17, kA, -1},  {18, 1, -kA}, {19, 1, kA},    // 17-20
    {20, kA, 1},    {21, -kA, 1},  {22, -1, kA}, {23, -1, -kA},  // 21-24
    {24, -kA, -kA}, {25, kA, -kA}, {26, kA, kA}, {27, -kA, kA},  // 25-28
}};
// clang-format on

// C3D20 index (0-based) of each C3D28 node 5-16 that keeps its C3D20 shape function:
// top corners 5-8 (= C3D20 5-8), vertical mid-edges 9-12 (= C3D20 17-20), top mid-edges 13-16.
constexpr std::array<int, 12> kFromHex20 = {4, 5, 6, 7, 16, 17, 18, 19, 12, 13, 14, 15};

// 1D cubic Lagrange polynomial through the GLL nodes that is 1 at `node` (one of them): value and
// derivative at s, from the product form l(s) = prod_{j != i} (s - s_j) / (s_i - s_j).
void gll_lagrange(double node, double s, double& value, double& derivative) {
  const std::array<double, 4> nodes = {-1.0, -kA, kA, 1.0};
  value = 1.0;
  derivative = 0.0;
  for (double other : nodes) {
    if (std::abs(other - node) < 1e-12) continue;
    const double factor = (s - other) / (node - other);
    derivative = derivative * factor + value / (node - other);
    value *= factor;
  }
}

std::vector<Vec3> c3d28_nodes() {
  const std::vector<Vec3> hex20 = hex20_natural_nodes();
  std::vector<Vec3> nodes(28);
  for (int i = 0; i < 4; ++i) nodes[i] = hex20[i];
  for (int k = 0; k < 12; ++k) nodes[4 + k] = hex20[kFromHex20[k]];
  for (const BottomNode& b : kBottom) nodes[b.index] = Vec3{b.xi, b.eta, -1.0};
  return nodes;
}

// Faces S1..S6 (1-based node lists, corners first in Abaqus order, then the other nodes going
// round the face in the same sense; S1 ends with its four interior nodes).
std::vector<FaceDef> c3d28_faces() {
  struct Face {
    std::vector<int> nodes;
    int axis;
    double value;
  };
  const std::array<Face, 6> table = {{
      {{1, 2, 3, 4, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28}, 2, -1.0},  // S1
      {{5, 8, 7, 6, 16, 15, 14, 13}, 2, 1.0},                                   // S2
      {{1, 5, 6, 2, 9, 13, 10, 18, 17}, 1, -1.0},                               // S3
      {{2, 6, 7, 3, 10, 14, 11, 20, 19}, 0, 1.0},                               // S4
      {{3, 7, 8, 4, 11, 15, 12, 22, 21}, 1, 1.0},                               // S5
      {{4, 8, 5, 1, 12, 16, 9, 24, 23}, 0, -1.0},                               // S6
  }};
  std::vector<FaceDef> faces;
  for (const Face& f : table) {
    FaceDef def;
    for (int node : f.nodes) def.nodes.push_back(node - 1);
    def.axis = f.axis;
    def.value = f.value;
    faces.push_back(std::move(def));
  }
  return faces;
}

}  // namespace

C3D28::C3D28() : nodes_(c3d28_nodes()), faces_(c3d28_faces()) {}

std::string C3D28::description() const {
  return "28-node contact hexahedron (16-node bicubic GLL contact face S1, serendipity top), "
         "4x4x3 Gauss";
}

// Blending construction of elements-ref section 4: a bottom node with GLL coordinates
// (xi_i, eta_i) gets l_i(xi) l_i(eta) (1 - zeta)/2, minus half the vertical-edge function M_k
// when it is a corner; the top and vertical-edge nodes keep their C3D20 functions (for the top
// corners, S_k (1 + zeta)/2 - M_k/2 is exactly the C3D20 corner function).
void C3D28::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  Eigen::Matrix<double, 20, 1> h;
  Eigen::Matrix<double, 20, 3> dh;
  hex20_shape(xi, h, dh);
  for (int k = 0; k < 12; ++k) {
    N(4 + k) = h(kFromHex20[k]);
    dN.row(4 + k) = dh.row(kFromHex20[k]);
  }
  const double below = 0.5 * (1.0 - xi[2]);
  for (const BottomNode& b : kBottom) {
    double lx = 0.0, dlx = 0.0, ly = 0.0, dly = 0.0;
    gll_lagrange(b.xi, xi[0], lx, dlx);
    gll_lagrange(b.eta, xi[1], ly, dly);
    N(b.index) = lx * ly * below;
    dN(b.index, 0) = dlx * ly * below;
    dN(b.index, 1) = lx * dly * below;
    dN(b.index, 2) = -0.5 * lx * ly;
  }
  for (int corner = 0; corner < 4; ++corner) {
    // M_k of bottom corner k is the C3D20 function of the vertical mid-edge node above it.
    N(corner) -= 0.5 * h(16 + corner);
    dN.row(corner) -= 0.5 * dh.row(16 + corner);
  }
}

IntegrationRule C3D28::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? gauss_rule(3, 3, 3) : gauss_rule(4, 4, 3);
}

}  // namespace styk::plugins
