#include "styk/core/face_param.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace styk {
namespace {

Eigen::Vector3d vec(const Vec3& x) { return {x[0], x[1], x[2]}; }

constexpr double kSquare[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

// Whether p lies in the triangle a-b-c (in its plane, to 1e-9): a fourth listed face node that
// does is a mid-edge node of a triangular face, not a corner.
bool in_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  if (!(n.norm() > 0.0) || std::abs(n.normalized().dot(p - a)) > 1e-9) return false;
  const auto side = [&](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    return (v - u).cross(p - u).dot(n) >= -1e-9 * n.squaredNorm();
  };
  return side(a, b) && side(b, c) && side(c, a);
}

}  // namespace

FaceParam::FaceParam(const TElement& element, const FaceDef& face) {
  // Built per face evaluation (contact projections build many), so it stays O(face nodes +
  // element nodes): the corners are the face's first 3 or 4 nodes, 3 when a fourth lies in the
  // triangle of the first three.
  const std::vector<Vec3>& xi = element.natural_nodes();
  if (face.nodes.size() < 3)
    throw std::invalid_argument(element.name() + ": a face needs 3 or 4 corner nodes");
  for (int k = 0; k < 3; ++k) c_[static_cast<std::size_t>(k)] = vec(xi[face.nodes[k]]);
  corners_ = 3;
  if (face.nodes.size() >= 4 && !in_triangle(vec(xi[face.nodes[3]]), c_[0], c_[1], c_[2])) {
    c_[3] = vec(xi[face.nodes[3]]);
    corners_ = 4;
  }
  // Outward: away from the mean of all natural nodes, a point inside the (convex) reference
  // element.
  Eigen::Vector3d inside = Eigen::Vector3d::Zero();
  for (const Vec3& p : xi) inside += vec(p);
  inside /= static_cast<double>(xi.size());
  const std::array<double, 2> mid = centre();
  Eigen::Vector3d dp, dq;
  tangents(mid[0], mid[1], dp, dq);
  outward_ = dp.cross(dq).dot(vec(point(mid[0], mid[1])) - inside) < 0.0 ? -1.0 : 1.0;
}

Vec3 FaceParam::point(double p, double q) const {
  Eigen::Vector3d x;
  if (triangle()) {
    x = c_[0] + p * (c_[1] - c_[0]) + q * (c_[2] - c_[0]);
  } else {
    x.setZero();
    for (int i = 0; i < 4; ++i)
      x += 0.25 * (1 + kSquare[i][0] * p) * (1 + kSquare[i][1] * q) *
           c_[static_cast<std::size_t>(i)];
  }
  return {x[0], x[1], x[2]};
}

void FaceParam::tangents(double p, double q, Eigen::Vector3d& dp, Eigen::Vector3d& dq) const {
  if (triangle()) {
    dp = c_[1] - c_[0];
    dq = c_[2] - c_[0];
    return;
  }
  dp.setZero();
  dq.setZero();
  for (int i = 0; i < 4; ++i) {
    const auto& c = c_[static_cast<std::size_t>(i)];
    dp += 0.25 * kSquare[i][0] * (1 + kSquare[i][1] * q) * c;
    dq += 0.25 * (1 + kSquare[i][0] * p) * kSquare[i][1] * c;
  }
}

double FaceParam::outside(double p, double q) const {
  if (triangle()) return std::max({0.0, -p, -q, p + q - 1.0});
  return std::max({0.0, std::abs(p) - 1.0, std::abs(q) - 1.0});
}

std::array<double, 2> FaceParam::centre() const {
  return triangle() ? std::array<double, 2>{1.0 / 3.0, 1.0 / 3.0} : std::array<double, 2>{0, 0};
}

FaceRule face_rule(bool triangle, int order) {
  std::vector<double> g, w;
  gauss_legendre(order, g, w);
  FaceRule rule;
  for (std::size_t a = 0; a < g.size(); ++a)
    for (std::size_t b = 0; b < g.size(); ++b) {
      if (!triangle) {
        rule.points.push_back({g[a], g[b]});
        rule.weights.push_back(w[a] * w[b]);
        continue;
      }
      // Collapsed square: u, v in [0, 1], p = u, q = v (1 - u), dp dq = (1 - u) du dv.
      const double u = 0.5 * (g[a] + 1.0), v = 0.5 * (g[b] + 1.0);
      rule.points.push_back({u, v * (1.0 - u)});
      rule.weights.push_back(0.25 * w[a] * w[b] * (1.0 - u));
    }
  return rule;
}

}  // namespace styk
