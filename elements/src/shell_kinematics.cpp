// Kinematics of the degenerated shells (shell_kinematics.hpp).
#include "shell_kinematics.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace styk::shell_detail {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v(2), v(1), v(2), 0.0, -v(0), -v(1), v(0), 0.0;
  return m;
}

// The derivatives of the displacement along xi, eta, zeta per element dof: U[j] (3 x 6n).
struct Gradients {
  Eigen::Matrix3d J;  // columns g1, g2, g3 (dx/dxi_j)
  Eigen::MatrixXd U[3];
  Eigen::VectorXd N;
};

void gradients(const Shell& shell, const ElementGeometry& g, const ShellSetup& s, const Vec3& xi,
               Gradients& out) {
  const int n = shell.node_count();
  Eigen::MatrixXd dN(n, 3);
  out.N.resize(n);
  shell.der(xi, out.N, dN);
  const double z = s.z(xi[2]), dz = 0.5 * s.thickness;
  out.J.setZero();
  for (int j = 0; j < 3; ++j) out.U[j].setZero(3, 6 * n);
  for (int a = 0; a < n; ++a) {
    const Eigen::Vector3d X = g.X.row(a).transpose();
    const Eigen::Vector3d& V = s.normals[a];
    // theta x V = -skew(V) theta: the fibre's displacement per unit z.
    const Eigen::Matrix3d G = -skew(V);
    for (int j = 0; j < 2; ++j) {
      out.J.col(j) += dN(a, j) * (X + z * V);
      out.U[j].block<3, 3>(0, 6 * a) += dN(a, j) * Eigen::Matrix3d::Identity();
      out.U[j].block<3, 3>(0, 6 * a + 3) += (dN(a, j) * z) * G;
    }
    out.J.col(2) += out.N(a) * dz * V;
    out.U[2].block<3, 3>(0, 6 * a + 3) += (out.N(a) * dz) * G;
  }
}

// Covariant strain row E_ij = (g_i . U_j + g_j . U_i) / 2.
Eigen::RowVectorXd covariant(const Gradients& d, int i, int j) {
  return 0.5 * (d.J.col(i).transpose() * d.U[j] + d.J.col(j).transpose() * d.U[i]);
}

}  // namespace

Eigen::Matrix3d lamina_axes_of_normal(const Eigen::Vector3d& normal) {
  const Eigen::Vector3d e3 = normal.normalized();
  Eigen::Vector3d reference = Eigen::Vector3d::UnitX();
  if (std::abs(reference.dot(e3)) > std::cos(0.1 * M_PI / 180.0))
    reference = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d e1 = (reference - reference.dot(e3) * e3).normalized();
  Eigen::Matrix3d R;
  R << e1, e3.cross(e1), e3;
  return R;
}

IntegrationRule with_fibres(const IntegrationRule& surface, const std::string& label) {
  IntegrationRule rule;
  rule.label = label;
  const double fibre_weight[3] = {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};
  for (int k = 0; k < surface.size(); ++k)
    for (int fibre = 0; fibre < 3; ++fibre) {
      rule.points.push_back({surface.points[k][0], surface.points[k][1], fibre - 1.0});
      rule.weights.push_back(surface.weights[k] * fibre_weight[fibre]);
    }
  return rule;
}

double surface_point_measure(const TElement& element, const ElementGeometry& g,
                             const Eigen::Ref<const Eigen::MatrixXd>& dN,
                             Eigen::Ref<Eigen::MatrixXd> dNdx, int point,
                             const std::string& degenerate) {
  const Eigen::Vector3d g1 = g.X.transpose() * dN.col(0);
  const Eigen::Vector3d g2 = g.X.transpose() * dN.col(1);
  const Eigen::Vector3d normal = g1.cross(g2);
  const double area = normal.norm();
  const double scale = std::max(g.X.cwiseAbs().maxCoeff(), 1e-300);
  if (!(area > 1e-12 * scale * scale))
    throw InputError(g.where,
                     label(element, g) + ": " + degenerate + " at point " + std::to_string(point));
  Eigen::Matrix3d J;
  J << g1, g2, normal / area;
  const Eigen::Matrix3d inverse = J.inverse();  // rows: the dual vectors g^1, g^2, n
  for (Eigen::Index a = 0; a < dN.rows(); ++a)
    dNdx.row(a) = dN(a, 0) * inverse.row(0) + dN(a, 1) * inverse.row(1);
  return area * g.cross_section;
}

std::string label(const TElement& element, const ElementGeometry& g) {
  return "element " + std::to_string(g.id) + " (" + element.name() + ")";
}

void simpson(int n, std::vector<double>& points, std::vector<double>& weights) {
  points.resize(n);
  weights.resize(n);
  const double h = 2.0 / (n - 1);
  for (int k = 0; k < n; ++k) {
    points[k] = -1.0 + k * h;
    weights[k] = h / 3.0 * (k == 0 || k == n - 1 ? 1.0 : k % 2 == 1 ? 4.0 : 2.0);
  }
}

ShellSetup section_setup(const TElement& shell, const ElementGeometry& g,
                         const Material& material) {
  const int n = shell.node_count();
  if (g.X.rows() != n || g.X.cols() != 3)
    throw InputError(g.where, label(shell, g) + ": has " + std::to_string(g.X.rows()) +
                                  " nodes, expected " + std::to_string(n));
  if (g.section == nullptr || !g.section->shell)
    throw InputError(g.where, label(shell, g) + " has no *SHELL SECTION");
  ShellSetup s;
  s.thickness = g.section->thickness.value_or(0.0);
  if (!(s.thickness > 0.0))
    throw InputError(g.section->where, label(shell, g) + ": the shell thickness must be positive");
  s.offset = g.section->shell->offset;
  s.section_points = g.section->shell->section_points;
  const bool constant = material.young && material.poisson && material.elastic_table.empty();
  if (!constant || material.elastic_type != ElasticType::Isotropic)
    throw InputError(g.section->where, label(shell, g) +
                                           ": shells take a constant isotropic material (one "
                                           "*ELASTIC line E, nu); material " +
                                           material.name + " is not");
  s.young = *material.young;
  s.poisson = *material.poisson;
  s.shear = s.young / (2.0 * (1.0 + s.poisson));
  const double c = s.young / (1.0 - s.poisson * s.poisson);
  s.D(0, 0) = s.D(1, 1) = c;
  s.D(0, 1) = s.D(1, 0) = c * s.poisson;
  s.D(2, 2) = s.shear;
  s.D(3, 3) = s.D(4, 4) = 5.0 / 6.0 * s.shear;  // transverse shear factor
  return s;
}

ShellSetup shell_setup(const Shell& shell, const ElementGeometry& g, const Material& material) {
  const int n = shell.node_count();
  ShellSetup s = section_setup(shell, g, material);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  const double scale = std::max(g.X.cwiseAbs().maxCoeff(), 1e-300);
  for (int a = 0; a < n; ++a) {
    shell.der(shell.natural_nodes()[a], N, dN);
    const Eigen::Vector3d g1 = g.X.transpose() * dN.col(0), g2 = g.X.transpose() * dN.col(1);
    const Eigen::Vector3d normal = g1.cross(g2);
    if (!(normal.norm() > 1e-12 * scale * scale))
      throw InputError(g.where, label(shell, g) + ": no surface normal at its node " +
                                    std::to_string(a + 1) +
                                    " (the element is degenerate or folded there)");
    s.normals.push_back(normal.normalized());
  }
  // The model's resolved normals (averaged over the elements at a node, or given by *NORMAL)
  // replace the element's own once its geometry has proved sound.
  if (g.nodal_normals.rows() == n && g.nodal_normals.cols() == 3)
    for (int a = 0; a < n; ++a) {
      const Eigen::Vector3d given = g.nodal_normals.row(a).transpose();
      if (given.norm() > 0.0) s.normals[a] = given.normalized();
    }
  return s;
}

void lamina_point(const Shell& shell, const ElementGeometry& g, const ShellSetup& s, const Vec3& xi,
                  int point, LaminaPoint& out) {
  Gradients d;
  gradients(shell, g, s, xi, d);
  out.detJ = d.J.determinant();
  const double scale = std::max(g.X.cwiseAbs().maxCoeff(), 1e-300);
  if (!(out.detJ > 1e-12 * scale * scale * s.thickness))
    throw InputError(g.where, label(shell, g) + ": det J <= 0 at point " + std::to_string(point) +
                                  " (inverted, degenerate, or thicker than its curvature radius)");
  out.N = d.N;
  out.R = lamina_axes_of_normal(d.J.col(0).cross(d.J.col(1)));
  // C(a, i) = e_a . g^i: the lamina components of the contravariant base vectors.
  const Eigen::Matrix3d C = out.R.transpose() * d.J.inverse().transpose();

  Eigen::RowVectorXd E[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) E[i][j] = covariant(d, i, j);
  if (shell.assumed_shear()) {
    // MITC4: E_13 tied at (0, -1) and (0, 1), E_23 at (-1, 0) and (1, 0), at the same zeta.
    Gradients t;
    Eigen::RowVectorXd e13 = Eigen::RowVectorXd::Zero(E[0][2].size());
    Eigen::RowVectorXd e23 = e13;
    for (const double side : {-1.0, 1.0}) {
      gradients(shell, g, s, {0.0, side, xi[2]}, t);
      e13 += 0.5 * (1.0 + side * xi[1]) * covariant(t, 0, 2);
      gradients(shell, g, s, {side, 0.0, xi[2]}, t);
      e23 += 0.5 * (1.0 + side * xi[0]) * covariant(t, 1, 2);
    }
    E[0][2] = e13;
    E[1][2] = e23;
  }
  const auto e = [&](int i, int j) -> const Eigen::RowVectorXd& {
    return i <= j ? E[i][j] : E[j][i];
  };
  const auto lamina = [&](int a, int b) {
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(E[0][0].size());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (C(a, i) != 0.0 && C(b, j) != 0.0) row += (C(a, i) * C(b, j)) * e(i, j);
    return row;
  };
  out.B.resize(5, E[0][0].size());
  out.B.row(0) = lamina(0, 0);
  out.B.row(1) = lamina(1, 1);
  out.B.row(2) = 2.0 * lamina(0, 1);
  out.B.row(3) = 2.0 * lamina(0, 2);
  out.B.row(4) = 2.0 * lamina(1, 2);
}

void drilling_row(const Shell& shell, const ElementGeometry& g, const ShellSetup& s, double xi,
                  double eta, Eigen::RowVectorXd& row, double& area) {
  Gradients d;
  gradients(shell, g, s, {xi, eta, 0.0}, d);
  const Eigen::Matrix3d R = lamina_axes_of_normal(d.J.col(0).cross(d.J.col(1)));
  const Eigen::Matrix3d Jinv = d.J.inverse();
  const Eigen::Vector3d a1 = Jinv * R.col(0), a2 = Jinv * R.col(1);
  // (grad u) e1 = sum_j U_j (J^-1 e1)_j; omega = (e2 . (grad u) e1 - e1 . (grad u) e2) / 2.
  row = Eigen::RowVectorXd::Zero(6 * shell.node_count());
  for (int j = 0; j < 3; ++j)
    row -= 0.5 * (a1(j) * R.col(1).transpose() * d.U[j] - a2(j) * R.col(0).transpose() * d.U[j]);
  for (int a = 0; a < shell.node_count(); ++a)
    row.segment<3>(6 * a + 3) += d.N(a) * R.col(2).transpose();
  area = d.J.col(0).cross(d.J.col(1)).norm();
}

}  // namespace styk::shell_detail
