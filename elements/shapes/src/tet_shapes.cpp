#include "styk/elements/tet_shapes.hpp"

#include <array>
#include <cmath>

namespace styk {
namespace {

// Mid-edge nodes 5..10 as pairs of corners (0-based).
constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

// Corners of faces 1..4 and the mid-edge nodes (0-based) of their edges in the same order.
constexpr int kFaceCorners[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
constexpr int kFaceMidEdges[4][3] = {{4, 5, 6}, {7, 8, 4}, {8, 9, 5}, {9, 7, 6}};

// Volume coordinates and their derivatives with respect to (xi, eta, zeta).
std::array<double, 4> volume_coordinates(const Vec3& xi) {
  return {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
}
constexpr double kDL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

}  // namespace

std::vector<Vec3> tet4_natural_nodes() { return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; }

std::vector<Vec3> tet10_natural_nodes() {
  std::vector<Vec3> nodes = tet4_natural_nodes();
  const std::vector<Vec3> c = tet4_natural_nodes();
  for (const auto& e : kEdges)
    nodes.push_back({0.5 * (c[e[0]][0] + c[e[1]][0]), 0.5 * (c[e[0]][1] + c[e[1]][1]),
                     0.5 * (c[e[0]][2] + c[e[1]][2])});
  return nodes;
}

std::vector<FaceDef> tet_faces(bool quadratic) {
  std::vector<FaceDef> faces(4);
  for (int f = 0; f < 4; ++f) {
    faces[f].nodes.assign(kFaceCorners[f], kFaceCorners[f] + 3);
    if (quadratic)
      faces[f].nodes.insert(faces[f].nodes.end(), kFaceMidEdges[f], kFaceMidEdges[f] + 3);
    faces[f].axis = -1;
    faces[f].value = 0.0;
  }
  return faces;
}

void tet4_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const std::array<double, 4> L = volume_coordinates(xi);
  for (int i = 0; i < 4; ++i) {
    N(i) = L[i];
    for (int d = 0; d < 3; ++d) dN(i, d) = kDL[i][d];
  }
}

void tet10_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const std::array<double, 4> L = volume_coordinates(xi);
  for (int i = 0; i < 4; ++i) {
    N(i) = L[i] * (2.0 * L[i] - 1.0);
    for (int d = 0; d < 3; ++d) dN(i, d) = (4.0 * L[i] - 1.0) * kDL[i][d];
  }
  for (int m = 0; m < 6; ++m) {
    const int i = kEdges[m][0], j = kEdges[m][1];
    N(4 + m) = 4.0 * L[i] * L[j];
    for (int d = 0; d < 3; ++d) dN(4 + m, d) = 4.0 * (kDL[i][d] * L[j] + L[i] * kDL[j][d]);
  }
}

IntegrationRule tet_rule_1() { return {"1-point tetrahedron", {{0.25, 0.25, 0.25}}, {1.0 / 6.0}}; }

IntegrationRule tet_rule_4() {
  const double a = (5.0 - std::sqrt(5.0)) / 20.0, b = (5.0 + 3.0 * std::sqrt(5.0)) / 20.0;
  IntegrationRule rule;
  rule.label = "4-point tetrahedron";
  rule.points = {{a, a, a}, {b, a, a}, {a, b, a}, {a, a, b}};
  rule.weights.assign(4, 1.0 / 24.0);
  return rule;
}

}  // namespace styk
