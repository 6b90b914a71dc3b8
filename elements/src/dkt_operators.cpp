// The discrete-Kirchhoff triangle's operators (dkt_operators.hpp). The rotations beta are
// interpolated with the quadratic triangle's six functions in the area coordinates
// l0 = 1 - xi - eta, l1 = xi, l2 = eta: corners l_a (2 l_a - 1), mid-sides 4 l_a l_b.
#include "dkt_operators.hpp"

#include <array>
#include <cmath>

#include <Eigen/Dense>

namespace styk::dkt {
namespace {

// The corners of the mid-side nodes 3, 4, 5.
constexpr int kSide[3][2] = {{1, 2}, {2, 0}, {0, 1}};

// Gradients of the area coordinates in the plane, rows l0, l1, l2 (constant on the triangle).
Eigen::Matrix<double, 3, 2> area_gradients(const Corners& x) {
  const double twice = twice_area(x);
  Eigen::Matrix<double, 3, 2> g;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    g(a, 0) = (x(b, 1) - x(c, 1)) / twice;
    g(a, 1) = (x(c, 0) - x(b, 0)) / twice;
  }
  return g;
}

// Gradients of the six quadratic functions at area coordinates l, rows node 0..5.
Eigen::Matrix<double, 6, 2> quadratic_gradients(const Eigen::Matrix<double, 3, 2>& dl,
                                                const std::array<double, 3>& l) {
  Eigen::Matrix<double, 6, 2> g;
  for (int a = 0; a < 3; ++a) g.row(a) = (4.0 * l[a] - 1.0) * dl.row(a);
  for (int k = 0; k < 3; ++k) {
    const int a = kSide[k][0], b = kSide[k][1];
    g.row(3 + k) = 4.0 * (l[b] * dl.row(a) + l[a] * dl.row(b));
  }
  return g;
}

// Their (constant) second derivatives d2N / dx_i dx_j.
std::array<Eigen::Matrix2d, 6> quadratic_hessians(const Eigen::Matrix<double, 3, 2>& dl) {
  std::array<Eigen::Matrix2d, 6> h;
  for (int a = 0; a < 3; ++a) h[a] = 4.0 * dl.row(a).transpose() * dl.row(a);
  for (int k = 0; k < 3; ++k) {
    const int a = kSide[k][0], b = kSide[k][1];
    h[3 + k] = 4.0 * (dl.row(a).transpose() * dl.row(b) + dl.row(b).transpose() * dl.row(a));
  }
  return h;
}

}  // namespace

double twice_area(const Corners& x) {
  return (x(1, 0) - x(0, 0)) * (x(2, 1) - x(0, 1)) - (x(2, 0) - x(0, 0)) * (x(1, 1) - x(0, 1));
}

Eigen::Matrix<double, 12, 9> midside_rotations(const Corners& x) {
  Eigen::Matrix<double, 12, 9> T = Eigen::Matrix<double, 12, 9>::Zero();
  for (int a = 0; a < 3; ++a) {
    T(2 * a, 3 * a + 2) = 1.0;       // beta1 = theta2
    T(2 * a + 1, 3 * a + 1) = -1.0;  // beta2 = -theta1
  }
  for (int k = 0; k < 3; ++k) {
    const int i = kSide[k][0], j = kSide[k][1];
    const Eigen::Vector2d side = (x.row(j) - x.row(i)).transpose();
    const double length = side.norm();
    const Eigen::Vector2d s = side / length;
    const Eigen::Matrix<double, 2, 9> sum = T.block<2, 9>(2 * i, 0) + T.block<2, 9>(2 * j, 0);
    Eigen::Matrix<double, 1, 9> dw = Eigen::Matrix<double, 1, 9>::Zero();
    dw(3 * j) = 1.0;
    dw(3 * i) = -1.0;
    // Tangential rotation at the mid-side minus the mean of the corners' tangential rotations.
    const Eigen::Matrix<double, 1, 9> correction =
        -1.5 / length * dw - 0.75 * (s.transpose() * sum);
    T.block<2, 9>(2 * (3 + k), 0) = 0.5 * sum + s * correction;
  }
  return T;
}

Eigen::Matrix<double, 3, 9> curvature(const Corners& x, const Eigen::Matrix<double, 12, 9>& T,
                                      double xi, double eta) {
  const Eigen::Matrix<double, 6, 2> dN =
      quadratic_gradients(area_gradients(x), {1.0 - xi - eta, xi, eta});
  Eigen::Matrix<double, 3, 9> B = Eigen::Matrix<double, 3, 9>::Zero();
  for (int m = 0; m < 6; ++m) {
    B.row(0) += dN(m, 0) * T.row(2 * m);
    B.row(1) += dN(m, 1) * T.row(2 * m + 1);
    B.row(2) += dN(m, 1) * T.row(2 * m) + dN(m, 0) * T.row(2 * m + 1);
  }
  return B;
}

Eigen::Matrix<double, 6, 9> curvature_gradient(const Corners& x,
                                               const Eigen::Matrix<double, 12, 9>& T) {
  const std::array<Eigen::Matrix2d, 6> h = quadratic_hessians(area_gradients(x));
  Eigen::Matrix<double, 6, 9> G = Eigen::Matrix<double, 6, 9>::Zero();
  for (int j = 0; j < 2; ++j)
    for (int m = 0; m < 6; ++m) {
      G.row(3 * j) += h[m](0, j) * T.row(2 * m);
      G.row(3 * j + 1) += h[m](1, j) * T.row(2 * m + 1);
      G.row(3 * j + 2) += h[m](1, j) * T.row(2 * m) + h[m](0, j) * T.row(2 * m + 1);
    }
  return G;
}

Eigen::Matrix<double, 3, 6> membrane(const Corners& x) {
  const Eigen::Matrix<double, 3, 2> dl = area_gradients(x);
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int a = 0; a < 3; ++a) {
    B(0, 2 * a) = dl(a, 0);
    B(1, 2 * a + 1) = dl(a, 1);
    B(2, 2 * a) = dl(a, 1);
    B(2, 2 * a + 1) = dl(a, 0);
  }
  return B;
}

Eigen::Matrix<double, 1, 6> in_plane_rotation(const Corners& x) {
  const Eigen::Matrix<double, 3, 2> dl = area_gradients(x);
  Eigen::Matrix<double, 1, 6> row;
  for (int a = 0; a < 3; ++a) {
    row(2 * a) = -0.5 * dl(a, 1);
    row(2 * a + 1) = 0.5 * dl(a, 0);
  }
  return row;
}

}  // namespace styk::dkt
