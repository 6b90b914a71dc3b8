#include "reference_shape.hpp"

#include <algorithm>
#include <iterator>

#include <Eigen/Geometry>

namespace styk::mesher::detail {
namespace {

constexpr double kTolerance = 1e-9;

// The 24 proper rotations of the cube: signed permutation matrices with determinant +1.
const std::vector<CubeRotation>& cube_rotations() {
  static const std::vector<CubeRotation> rotations = [] {
    static constexpr int kPerms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                         {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    static constexpr int kParity[6] = {1, -1, -1, 1, 1, -1};
    std::vector<CubeRotation> out;
    for (int p = 0; p < 6; ++p)
      for (int s = 0; s < 8; ++s) {
        const int signs[3] = {(s & 1) ? -1 : 1, (s & 2) ? -1 : 1, (s & 4) ? -1 : 1};
        if (kParity[p] * signs[0] * signs[1] * signs[2] != 1) continue;
        CubeRotation R{};
        for (int r = 0; r < 3; ++r) R[r][kPerms[p][r]] = signs[r];
        out.push_back(R);
      }
    return out;
  }();
  return rotations;
}

}  // namespace

Eigen::Vector3d natural_point(const Vec3& xi) { return {xi[0], xi[1], xi[2]}; }

Eigen::Vector3d turn(const CubeRotation& R, const Eigen::Vector3d& x) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[r] += R[r][c] * x[c];
  return out;
}

ReferenceShape::ReferenceShape(const TElement& element) : element_(element) {
  const std::vector<int> corners = corner_nodes(element);
  for (const FaceDef& face : element.faces()) {
    std::vector<int> c;
    for (int k : face.nodes)
      if (std::binary_search(corners.begin(), corners.end(), k)) c.push_back(k);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k : c) centre += natural_point(natural()[k]);
    centres_.push_back(c.empty() ? centre : Eigen::Vector3d(centre / c.size()));
    faces_.push_back(std::move(c));
  }
}

bool ReferenceShape::on_face(int f, const Eigen::Vector3d& p) const {
  const std::vector<int>& c = faces_[f];
  if (c.size() < 3) return false;
  std::vector<Eigen::Vector3d> x;
  for (int k : c) x.push_back(natural_point(natural()[k]));
  const Eigen::Vector3d normal = (x[1] - x[0]).cross(x[2] - x[0]).normalized();
  if (std::abs(normal.dot(p - x[0])) > kTolerance) return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Eigen::Vector3d& a = x[i];
    const Eigen::Vector3d& b = x[(i + 1) % x.size()];
    if ((b - a).cross(p - a).dot(normal) < -kTolerance) return false;
  }
  return true;
}

std::vector<int> ReferenceShape::carrier_corners(const Eigen::Vector3d& p) const {
  std::vector<int> shared;
  bool any = false;
  for (int f = 0; f < face_count(); ++f) {
    if (!on_face(f, p)) continue;
    std::vector<int> c = faces_[f];
    std::sort(c.begin(), c.end());
    if (!any) {
      shared = c;
      any = true;
      continue;
    }
    std::vector<int> both;
    std::set_intersection(shared.begin(), shared.end(), c.begin(), c.end(),
                          std::back_inserter(both));
    shared = std::move(both);
  }
  return shared;
}

int ReferenceShape::face_at(const Eigen::Vector3d& centre) const {
  for (int f = 0; f < face_count(); ++f)
    if ((centres_[f] - centre).norm() < kTolerance) return f;
  return -1;
}

int ReferenceShape::node_at(const Eigen::Vector3d& p) const {
  for (std::size_t k = 0; k < natural().size(); ++k)
    if ((natural_point(natural()[k]) - p).norm() < kTolerance) return static_cast<int>(k);
  return -1;
}

bool ReferenceShape::rotation_between(int new_face, int old_face, CubeRotation& R) const {
  for (const CubeRotation& candidate : cube_rotations()) {
    if ((turn(candidate, centres_[new_face]) - centres_[old_face]).norm() > kTolerance) continue;
    bool maps_nodes = true;
    for (const Vec3& xi : natural())
      maps_nodes = maps_nodes && node_at(turn(candidate, natural_point(xi))) >= 0;
    if (!maps_nodes) continue;
    R = candidate;
    return true;
  }
  return false;
}

std::vector<int> ReferenceShape::renumbering(const CubeRotation& R) const {
  std::vector<int> old_of_new;
  for (const Vec3& xi : natural()) old_of_new.push_back(node_at(turn(R, natural_point(xi))));
  return old_of_new;
}

int ReferenceShape::rotated_face(const CubeRotation& R, int old_face) const {
  for (int g = 0; g < face_count(); ++g)
    if ((turn(R, centres_[g]) - centres_[old_face]).norm() < kTolerance) return g;
  return -1;
}

Eigen::Vector3d ReferenceShape::place(const std::vector<Vec3>& coords,
                                      const Eigen::Vector3d& xi) const {
  const int n = element_.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  element_.der({xi[0], xi[1], xi[2]}, N, dN);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) x += N[k] * natural_point(coords[k]);
  return x;
}

}  // namespace styk::mesher::detail
