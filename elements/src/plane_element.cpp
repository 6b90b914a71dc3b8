#include "styk/elements/plane_element.hpp"

#include <cstdio>
#include <string>

#include <Eigen/Dense>

#include "edge_quadrature.hpp"
namespace styk {
namespace {

std::string label(const ElementGeometry& g, const TElement& e) {
  return "element " + std::to_string(g.id) + " (" + e.name() + ")";
}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

void check_thickness(const ElementGeometry& g, const TElement& e) {
  if (!(g.cross_section > 0.0))
    throw InputError(g.where, label(g, e) + ": thickness " + format_number(g.cross_section) +
                                  " must be positive (first data line of its *SOLID SECTION)");
}

}  // namespace

void PlaneElement::bee(const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
                       Eigen::Ref<Eigen::MatrixXd> B) const {
  B.setZero();
  for (Eigen::Index a = 0; a < dNdx.rows(); ++a) {
    const double dx = dNdx(a, 0), dy = dNdx(a, 1);
    const Eigen::Index c = 3 * a;
    B(0, c) = dx;
    B(1, c + 1) = dy;
    B(3, c) = dy;  // gamma_12
    B(3, c + 1) = dx;
  }
}

namespace {
// The out-of-plane stress components that plane stress frees: 33, 13, 23 (Voigt 2, 4, 5), and
// the in-plane ones 11, 22, 12 (0, 1, 3).
constexpr int kOut[3] = {2, 4, 5};
constexpr int kIn[3] = {0, 1, 3};
}  // namespace

void PlaneElement::dee(const MaterialPoint& material, Matrix6d& D) const {
  D = material.D;
  if (kind_ == PlaneKind::Strain) return;
  // sigma33 = sigma13 = sigma23 = 0: eliminate the out-of-plane strains from the 3D law (static
  // condensation, D_ii - D_io D_oo^-1 D_oi). Isotropic: the in-plane block becomes
  // E/(1-nu^2) [1 nu; nu 1]. The out-of-plane rows and columns are zero so that they carry no
  // stress whatever their (B-bar or thermal) strain.
  Eigen::Matrix3d Doo, Dio;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Doo(i, j) = material.D(kOut[i], kOut[j]);
      Dio(i, j) = material.D(kIn[i], kOut[j]);
    }
  const Eigen::Matrix3d correction = Dio * Doo.inverse() * Dio.transpose();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(kIn[i], kIn[j]) -= correction(i, j);
  for (int o : kOut) {
    D.row(o).setZero();
    D.col(o).setZero();
  }
}

double PlaneElement::point_measure(const ElementGeometry& g,
                                   const Eigen::Ref<const Eigen::VectorXd>&,
                                   const Eigen::Ref<const Eigen::MatrixXd>& dN,
                                   Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  check_thickness(g, *this);
  Eigen::Matrix2d J;
  J.noalias() = dN.leftCols<2>().transpose() * g.X.leftCols<2>();  // J(i, j) = dx_j / dxi_i
  const double det = J.determinant();
  // As for solids: degenerate relative to the lengths of the natural tangents (Hadamard).
  const double scale = J.row(0).norm() * J.row(1).norm();
  if (!(det > 1e-12 * scale))
    throw InputError(g.where, label(g, *this) + ": Jacobian determinant " + format_number(det) +
                                  " at integration point " + std::to_string(point) +
                                  " is not positive: the element is inverted, degenerate or its "
                                  "nodes run clockwise in the x-y plane");
  dNdx.leftCols<2>().noalias() = dN.leftCols<2>() * J.inverse().transpose();
  dNdx.col(2).setZero();
  return det * g.cross_section;
}

void PlaneElement::face_quadrature(const ElementGeometry& g, const FaceDef& face,
                                   std::vector<Vec3>& points,
                                   std::vector<Eigen::Vector3d>& weighted_normals) const {
  check_thickness(g, *this);
  elements_detail::edge_quadrature(
      *this, g, face, [&](const Eigen::VectorXd&) { return g.cross_section; }, points,
      weighted_normals);
}

void PlaneElement::complete_strain(const MaterialPoint& material,
                                   Eigen::Matrix<double, 6, 1>& engineering) const {
  if (kind_ == PlaneKind::Strain) return;  // eps33 = gamma13 = gamma23 = 0 by definition
  // sigma_o = 0 of the 3D law: eps_o = eps_th,o - D_oo^-1 D_oi (eps_i - eps_th,i). Isotropic:
  // eps33 = -nu/(1-nu) (eps11 + eps22) + (1+nu)/(1-nu) alpha dT.
  Eigen::Matrix3d Doo, Doi;
  Eigen::Vector3d mechanical_in;
  for (int i = 0; i < 3; ++i) {
    mechanical_in(i) = engineering(kIn[i]) - material.thermal_strain(kIn[i]);
    for (int j = 0; j < 3; ++j) {
      Doo(i, j) = material.D(kOut[i], kOut[j]);
      Doi(i, j) = material.D(kOut[i], kIn[j]);
    }
  }
  const Eigen::Vector3d out = Doo.inverse() * (Doi * mechanical_in);
  for (int i = 0; i < 3; ++i) engineering(kOut[i]) = material.thermal_strain(kOut[i]) - out(i);
}

}  // namespace styk
