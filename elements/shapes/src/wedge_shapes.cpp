#include "styk/elements/wedge_shapes.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace styk {
namespace {

// Mid-edge nodes 7..15 as pairs of corners (0-based).
constexpr int kEdges[9][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5},
                              {5, 3}, {0, 3}, {1, 4}, {2, 5}};

// Faces 1..5: corners, then the mid-edge nodes (0-based) of their edges in the same order.
const std::vector<std::vector<int>> kFaceCorners = {
    {0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
const std::vector<std::vector<int>> kFaceMidEdges = {
    {6, 7, 8}, {9, 10, 11}, {6, 13, 9, 12}, {7, 14, 10, 13}, {8, 12, 11, 14}};

// Triangle coordinates of the corners: L = 1 - xi - eta, xi, eta; the top repeats the bottom.
std::array<double, 3> triangle_coordinates(const Vec3& xi) {
  return {1.0 - xi[0] - xi[1], xi[0], xi[1]};
}
constexpr double kDL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};

}  // namespace

std::vector<Vec3> wedge6_natural_nodes() {
  return {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
}

std::vector<Vec3> wedge15_natural_nodes() {
  std::vector<Vec3> nodes = wedge6_natural_nodes();
  const std::vector<Vec3> c = wedge6_natural_nodes();
  for (const auto& e : kEdges)
    nodes.push_back({0.5 * (c[e[0]][0] + c[e[1]][0]), 0.5 * (c[e[0]][1] + c[e[1]][1]),
                     0.5 * (c[e[0]][2] + c[e[1]][2])});
  return nodes;
}

std::vector<FaceDef> wedge_faces(bool quadratic) {
  std::vector<FaceDef> faces(5);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    faces[f].nodes = kFaceCorners[f];
    if (quadratic)
      faces[f].nodes.insert(faces[f].nodes.end(), kFaceMidEdges[f].begin(), kFaceMidEdges[f].end());
    faces[f].axis = -1;
    faces[f].value = 0.0;
  }
  return faces;
}

void wedge6_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const std::array<double, 3> L = triangle_coordinates(xi);
  for (int level = 0; level < 2; ++level) {
    const double s = level == 0 ? -1.0 : 1.0;
    const double h = 0.5 * (1.0 + s * xi[2]);
    for (int i = 0; i < 3; ++i) {
      const int a = 3 * level + i;
      N(a) = L[i] * h;
      dN(a, 0) = kDL[i][0] * h;
      dN(a, 1) = kDL[i][1] * h;
      dN(a, 2) = 0.5 * s * L[i];
    }
  }
}

void wedge15_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const std::array<double, 3> L = triangle_coordinates(xi);
  const double z = xi[2];
  // Corners: 1/2 L (2L - 1)(1 + s z) - 1/2 L (1 - z^2), s = -1 below, +1 above.
  for (int level = 0; level < 2; ++level) {
    const double s = level == 0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i) {
      const int a = 3 * level + i;
      const double quad = L[i] * (2.0 * L[i] - 1.0), dquad = 4.0 * L[i] - 1.0;
      N(a) = 0.5 * quad * (1.0 + s * z) - 0.5 * L[i] * (1.0 - z * z);
      for (int d = 0; d < 2; ++d)
        dN(a, d) = kDL[i][d] * (0.5 * dquad * (1.0 + s * z) - 0.5 * (1.0 - z * z));
      dN(a, 2) = 0.5 * s * quad + L[i] * z;
    }
  }
  // Mid-edge nodes of the triangles: 2 L_i L_j (1 + s z).
  for (int m = 0; m < 6; ++m) {
    const double s = m < 3 ? -1.0 : 1.0;
    const int i = kEdges[m][0] % 3, j = kEdges[m][1] % 3;
    const double LL = L[i] * L[j];
    N(6 + m) = 2.0 * LL * (1.0 + s * z);
    for (int d = 0; d < 2; ++d)
      dN(6 + m, d) = 2.0 * (kDL[i][d] * L[j] + L[i] * kDL[j][d]) * (1.0 + s * z);
    dN(6 + m, 2) = 2.0 * s * LL;
  }
  // Vertical mid-edge nodes: L_i (1 - z^2).
  for (int i = 0; i < 3; ++i) {
    N(12 + i) = L[i] * (1.0 - z * z);
    for (int d = 0; d < 2; ++d) dN(12 + i, d) = kDL[i][d] * (1.0 - z * z);
    dN(12 + i, 2) = -2.0 * L[i] * z;
  }
}

IntegrationRule wedge_rule(int triangle_points, int zeta_points) {
  std::vector<std::array<double, 2>> tri;
  std::vector<double> tri_w;
  if (triangle_points == 1) {
    tri = {{1.0 / 3.0, 1.0 / 3.0}};
    tri_w = {0.5};
  } else if (triangle_points == 3) {
    tri = {{1.0 / 6.0, 1.0 / 6.0}, {2.0 / 3.0, 1.0 / 6.0}, {1.0 / 6.0, 2.0 / 3.0}};
    tri_w = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
  } else {
    throw std::invalid_argument("wedge_rule: 1 or 3 triangle points, not " +
                                std::to_string(triangle_points));
  }
  std::vector<double> z, z_w;
  gauss_legendre(zeta_points, z, z_w);
  IntegrationRule rule;
  rule.label = std::to_string(triangle_points) + "x" + std::to_string(zeta_points) + " wedge";
  for (std::size_t k = 0; k < z.size(); ++k)
    for (std::size_t t = 0; t < tri.size(); ++t) {
      rule.points.push_back({tri[t][0], tri[t][1], z[k]});
      rule.weights.push_back(tri_w[t] * z_w[k]);
    }
  return rule;
}

}  // namespace styk
