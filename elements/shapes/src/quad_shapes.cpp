#include "styk/elements/quad_shapes.hpp"

#include <string>

namespace styk {
namespace {

// Corner signs, counter-clockwise from (-1, -1).
constexpr double kCornerXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kCornerEta[4] = {-1.0, -1.0, 1.0, 1.0};

}  // namespace

std::vector<Vec3> quad4_natural_nodes() {
  std::vector<Vec3> nodes;
  for (int i = 0; i < 4; ++i) nodes.push_back({kCornerXi[i], kCornerEta[i], 0.0});
  return nodes;
}

std::vector<Vec3> quad8_natural_nodes() {
  std::vector<Vec3> nodes = quad4_natural_nodes();
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    nodes.push_back(
        {0.5 * (kCornerXi[i] + kCornerXi[j]), 0.5 * (kCornerEta[i] + kCornerEta[j]), 0.0});
  }
  return nodes;
}

std::vector<FaceDef> quad_edges(bool with_mid_edges) {
  // (axis, value) of edge k: P1 eta=-1, P2 xi=+1, P3 eta=+1, P4 xi=-1.
  constexpr int kAxis[4] = {1, 0, 1, 0};
  constexpr double kValue[4] = {-1.0, 1.0, 1.0, -1.0};
  std::vector<FaceDef> edges(4);
  for (int k = 0; k < 4; ++k) {
    edges[k].nodes = {k, (k + 1) % 4};
    if (with_mid_edges) edges[k].nodes.push_back(4 + k);
    edges[k].axis = kAxis[k];
    edges[k].value = kValue[k];
  }
  return edges;
}

void quad4_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const double x = xi[0], y = xi[1];
  dN.col(2).setZero();
  for (int i = 0; i < 4; ++i) {
    const double a = kCornerXi[i], b = kCornerEta[i];
    N(i) = 0.25 * (1.0 + a * x) * (1.0 + b * y);
    dN(i, 0) = 0.25 * a * (1.0 + b * y);
    dN(i, 1) = 0.25 * b * (1.0 + a * x);
  }
}

void quad8_shape(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N, Eigen::Ref<Eigen::MatrixXd> dN) {
  const double x = xi[0], y = xi[1];
  dN.col(2).setZero();
  for (int i = 0; i < 4; ++i) {
    // Corner: (1 + a x)(1 + b y)(a x + b y - 1) / 4.
    const double a = kCornerXi[i], b = kCornerEta[i];
    const double px = 1.0 + a * x, py = 1.0 + b * y, s = a * x + b * y - 1.0;
    N(i) = 0.25 * px * py * s;
    dN(i, 0) = 0.25 * a * py * (s + px);
    dN(i, 1) = 0.25 * b * px * (s + py);
  }
  for (int k = 0; k < 4; ++k) {
    const int i = 4 + k, j = (k + 1) % 4;
    const double a = 0.5 * (kCornerXi[k] + kCornerXi[j]), b = 0.5 * (kCornerEta[k] + kCornerEta[j]);
    if (a == 0.0) {  // on eta = b: (1 - x^2)(1 + b y) / 2
      N(i) = 0.5 * (1.0 - x * x) * (1.0 + b * y);
      dN(i, 0) = -x * (1.0 + b * y);
      dN(i, 1) = 0.5 * b * (1.0 - x * x);
    } else {  // on xi = a: (1 + a x)(1 - y^2) / 2
      N(i) = 0.5 * (1.0 + a * x) * (1.0 - y * y);
      dN(i, 0) = 0.5 * a * (1.0 - y * y);
      dN(i, 1) = -y * (1.0 + a * x);
    }
  }
}

IntegrationRule quad_gauss_rule(int n) {
  std::vector<double> points, weights;
  gauss_legendre(n, points, weights);
  IntegrationRule rule;
  rule.label = std::to_string(n) + "x" + std::to_string(n) + " Gauss";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      rule.points.push_back({points[i], points[j], 0.0});
      rule.weights.push_back(weights[i] * weights[j]);
    }
  return rule;
}

}  // namespace styk
