#include "zero_energy_modes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>

namespace styk::solver_detail {
namespace {

// The elements of a patch: per element, the position of every node.
using PatchElements = std::vector<std::vector<Vec3>>;

// Copies of the reference element in `cells` per axis, 2 apart, shifted by `shift_x` along x.
PatchElements grid_patch(const TElement& element, const std::array<int, 3>& cells, double shift_x) {
  PatchElements out;
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i) {
        std::vector<Vec3> x = element.natural_nodes();
        for (Vec3& p : x) p = {p[0] + 2.0 * i + shift_x, p[1] + 2.0 * j, p[2] + 2.0 * k};
        out.push_back(std::move(x));
      }
  return out;
}

// An orientation-reversing symmetry of the reference element: the node permutation of an affine
// map with negative determinant that carries the natural nodes onto themselves (a tetrahedron
// swapping two corners, a wedge swapping xi and eta). Empty when there is none.
std::vector<int> mirror_permutation(const TElement& element) {
  const std::vector<Vec3>& xi = element.natural_nodes();
  const std::vector<int> corners = corner_nodes(element);
  const auto node_at = [&](const Eigen::Vector3d& p) {
    for (std::size_t k = 0; k < xi.size(); ++k)
      if ((Eigen::Vector3d(xi[k][0], xi[k][1], xi[k][2]) - p).norm() < 1e-9)
        return static_cast<int>(k);
    return -1;
  };
  Eigen::MatrixXd from(corners.size(), 4);
  for (std::size_t c = 0; c < corners.size(); ++c)
    from.row(c) << xi[corners[c]][0], xi[corners[c]][1], xi[corners[c]][2], 1.0;
  std::vector<int> image = corners;
  while (std::next_permutation(image.begin(), image.end())) {
    Eigen::MatrixXd to(corners.size(), 3);
    for (std::size_t c = 0; c < corners.size(); ++c)
      to.row(c) << xi[image[c]][0], xi[image[c]][1], xi[image[c]][2];
    const Eigen::MatrixXd map = from.colPivHouseholderQr().solve(to);  // 4 x 3: [A^T; t^T]
    if ((from * map - to).norm() > 1e-9) continue;
    const Eigen::Matrix3d A = map.topRows<3>().transpose();
    if (!(A.determinant() < 0.0)) continue;
    std::vector<int> permutation;
    for (const Vec3& p : xi) {
      const int k = node_at(A * Eigen::Vector3d(p[0], p[1], p[2]) + map.row(3).transpose());
      if (k < 0) break;
      permutation.push_back(k);
    }
    if (permutation.size() == xi.size()) return permutation;
  }
  return {};
}

// The reference element and its mirror image across each of its faces (renumbered by a mirror
// symmetry so that every copy keeps a positive Jacobian): the smallest patch of a shape that does
// not tile by translation (tetrahedra, wedges).
PatchElements face_mirror_patch(const TElement& element) {
  PatchElements out{element.natural_nodes()};
  const std::vector<int> mirror = mirror_permutation(element);
  if (mirror.empty()) return out;
  const std::vector<Vec3>& xi = element.natural_nodes();
  const std::vector<int> corners = corner_nodes(element);
  for (const FaceDef& face : element.faces()) {
    std::vector<Eigen::Vector3d> c;
    for (int k : face.nodes)
      if (std::binary_search(corners.begin(), corners.end(), k))
        c.push_back(Eigen::Vector3d(xi[k][0], xi[k][1], xi[k][2]));
    if (c.size() < 3) return {element.natural_nodes()};
    const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]).normalized();
    std::vector<Vec3> copy;
    for (int k : mirror) {
      const Eigen::Vector3d p(xi[k][0], xi[k][1], xi[k][2]);
      const Eigen::Vector3d q = p - 2.0 * (p - c[0]).dot(n) * n;
      copy.push_back({q[0], q[1], q[2]});
    }
    out.push_back(std::move(copy));
  }
  return out;
}

struct Patch {
  PatchElements elements;
  int rigid_modes = 6;
};

bool within_unit_box(const TElement& element, int dimensions) {
  const std::vector<Vec3>& xi = element.natural_nodes();
  for (int d = 0; d < dimensions; ++d) {
    double lo = 1e9, hi = -1e9;
    for (const Vec3& p : xi) lo = std::min(lo, p[d]), hi = std::max(hi, p[d]);
    if (std::abs(lo + 1.0) > 1e-12 || std::abs(hi - 1.0) > 1e-12) return false;
  }
  return true;
}

Patch patch_of(const TElement& element) {
  Patch patch;
  switch (element.form()) {
    case ElementForm::Solid:
      patch.elements = within_unit_box(element, 3) ? grid_patch(element, {2, 2, 2}, 0.0)
                                                   : face_mirror_patch(element);
      break;
    case ElementForm::Planar:
      patch.rigid_modes = 3;
      patch.elements = grid_patch(element, {2, 2, 1}, 0.0);
      break;
    case ElementForm::Axisymmetric:
      patch.rigid_modes = 1;
      patch.elements = grid_patch(element, {2, 2, 1}, 3.0);  // r from 2 to 6: off the axis
      break;
    case ElementForm::Line:
    case ElementForm::Shell:  // six dofs per node: beam_warnings / shell_warnings count these
      patch.rigid_modes = 0;
      break;
  }
  return patch;
}

}  // namespace

int zero_eigenvalue_count(const Eigen::MatrixXd& K, const std::vector<Eigen::Index>& kept) {
  if (kept.empty()) return 0;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K(kept, kept), Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  const double largest = values.cwiseAbs().maxCoeff();
  int zero = 0;
  for (Eigen::Index k = 0; k < values.size(); ++k) zero += std::abs(values[k]) < 1e-9 * largest;
  return zero;
}

int spurious_zero_energy_modes(const TElement& element, RuleKind kind) {
  // Beams and shells carry rotations; their own checks (beam_warnings, shell_warnings) count
  // their modes.
  if (element.form() == ElementForm::Line || element.form() == ElementForm::Shell) return 0;
  const Patch patch = patch_of(element);
  const int n = element.node_count();
  // Nodes of the patch, merged by position.
  std::map<std::array<long long, 3>, int> index;
  std::vector<std::vector<int>> element_nodes;
  for (const std::vector<Vec3>& x : patch.elements) {
    std::vector<int> ids;
    for (const Vec3& p : x) {
      std::array<long long, 3> key{};
      for (int d = 0; d < 3; ++d) key[d] = std::llround(p[d] * 1e6);
      ids.push_back(index.emplace(key, static_cast<int>(index.size())).first->second);
    }
    element_nodes.push_back(std::move(ids));
  }
  Material unit;
  unit.young = 1.0;
  unit.poisson = 0.3;
  const int dofs = 3 * static_cast<int>(index.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs);
  ElementGeometry g;
  g.X.resize(n, 3);
  for (std::size_t c = 0; c < patch.elements.size(); ++c) {
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < 3; ++d) g.X(a, d) = patch.elements[c][a][d];
    Eigen::MatrixXd Ke;
    element.stiffness(g, unit, kind, Ke);
    const std::vector<int>& ids = element_nodes[c];
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        K.block<3, 3>(3 * ids[a], 3 * ids[b]) += Ke.block<3, 3>(3 * a, 3 * b);
  }
  // Only the displacements the type stiffens: the others are no modes, they are not there.
  const DofSet active = element.active_dofs();
  std::vector<Eigen::Index> kept;
  for (int dof = 0; dof < dofs; ++dof)
    if (active[dof % 3]) kept.push_back(dof);
  return std::max(0, zero_eigenvalue_count(K, kept) - patch.rigid_modes);
}

}  // namespace styk::solver_detail
