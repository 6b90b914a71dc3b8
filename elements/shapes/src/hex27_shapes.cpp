// The 27-node (triquadratic) Lagrange hexahedron: tensor products of the 1D quadratic Lagrange
// polynomials on the nodes -1, 0, +1.
#include "styk/elements/hex_shapes.hpp"

#include <array>

namespace styk {

namespace {

// Face centres 21-26 in face order S1..S6, then the element centre 27.
constexpr std::array<std::array<int, 3>, 7> kCentres = {{
    {0, 0, -1},
    {0, 0, 1},
    {0, -1, 0},
    {1, 0, 0},
    {0, 1, 0},
    {-1, 0, 0},
    {0, 0, 0},
}};

// 1D quadratic Lagrange polynomial of the node at s = -1, 0 or +1, and its derivative.
void lagrange(int node, double s, double& value, double& slope) {
  if (node == 0) {
    value = 1.0 - s * s;
    slope = -2.0 * s;
  } else {
    value = 0.5 * s * (s + node);
    slope = s + 0.5 * node;
  }
}

}  // namespace

std::vector<Vec3> hex27_natural_nodes() {
  std::vector<Vec3> nodes = hex20_natural_nodes();
  for (const auto& c : kCentres)
    nodes.push_back(
        Vec3{static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])});
  return nodes;
}

std::vector<FaceDef> hex27_faces() {
  std::vector<FaceDef> faces = hex_faces(true);
  for (std::size_t f = 0; f < faces.size(); ++f) faces[f].nodes.push_back(20 + static_cast<int>(f));
  return faces;
}

void hex27_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  static const std::vector<Vec3> nodes = hex27_natural_nodes();
  for (int a = 0; a < 27; ++a) {
    std::array<double, 3> value{}, slope{};
    for (int d = 0; d < 3; ++d) lagrange(static_cast<int>(nodes[a][d]), xi[d], value[d], slope[d]);
    N(a) = value[0] * value[1] * value[2];
    dN(a, 0) = slope[0] * value[1] * value[2];
    dN(a, 1) = value[0] * slope[1] * value[2];
    dN(a, 2) = value[0] * value[1] * slope[2];
  }
}

}  // namespace styk
