// Mechanics of the STRI3 triangle (stri3.hpp): the element's plane and lamina axes, its
// generalised strains (membrane strains and curvatures of dkt_operators.hpp), stiffness, fibre
// stresses and section forces.
#include <Eigen/Dense>

#include "dkt_operators.hpp"
#include "shell_kinematics.hpp"
#include "styk/elements/stri3.hpp"

namespace styk {
namespace {

using Row18 = Eigen::Matrix<double, 1, 18>;
using Op3 = Eigen::Matrix<double, 3, 18>;

// The element in its plane: lamina axes R (columns e1, e2, e3), the corners' in-plane
// coordinates from corner 1, and L turning global element dofs into local ones (R^T per
// translation and rotation triple).
struct Frame {
  Eigen::Matrix3d R;
  dkt::Corners x;
  Eigen::Matrix<double, 18, 18> L = Eigen::Matrix<double, 18, 18>::Zero();
  double area = 0.0;
};

Frame frame(const Stri3& element, const ElementGeometry& g) {
  const Eigen::Vector3d a = (g.X.row(1) - g.X.row(0)).transpose();
  const Eigen::Vector3d b = (g.X.row(2) - g.X.row(0)).transpose();
  const Eigen::Vector3d normal = a.cross(b);
  const double scale = std::max(g.X.cwiseAbs().maxCoeff(), 1e-300);
  if (!(normal.norm() > 1e-12 * scale * scale))
    throw InputError(g.where, shell_detail::label(element, g) +
                                  ": degenerate triangle (its corners are on one line)");
  Frame f;
  f.R = shell_detail::lamina_axes_of_normal(normal);
  for (int c = 0; c < 3; ++c)
    f.x.row(c) =
        (f.R.leftCols<2>().transpose() * (g.X.row(c) - g.X.row(0)).transpose()).transpose();
  for (int k = 0; k < 6; ++k) f.L.block<3, 3>(3 * k, 3 * k) = f.R.transpose();
  f.area = 0.5 * normal.norm();
  return f;
}

// Membrane strains (eps11, eps22, gamma12) per global element dof.
Op3 membrane(const Frame& f) {
  const Eigen::Matrix<double, 3, 6> m = dkt::membrane(f.x);
  Op3 B = Op3::Zero();
  for (int a = 0; a < 3; ++a) B.middleCols<2>(6 * a) = m.middleCols<2>(2 * a);
  return B * f.L;
}

// Places plate-dof columns (w, theta1, theta2 per corner) at the local element dofs.
template <int Rows>
Eigen::Matrix<double, Rows, 18> plate_columns(const Eigen::Matrix<double, Rows, 9>& plate) {
  Eigen::Matrix<double, Rows, 18> B = Eigen::Matrix<double, Rows, 18>::Zero();
  for (int a = 0; a < 3; ++a)
    B.template middleCols<3>(6 * a + 2) = plate.template middleCols<3>(3 * a);
  return B;
}

// Curvatures (kappa11, kappa22, 2 kappa12) at (xi, eta) per global element dof.
Op3 curvature(const Frame& f, double xi, double eta) {
  const Eigen::Matrix<double, 12, 9> T = dkt::midside_rotations(f.x);
  return plate_columns<3>(dkt::curvature(f.x, T, xi, eta)) * f.L;
}

// Gradients of the curvatures per global element dof (rows d/dx1 of kappa11, kappa22, 2 kappa12,
// then d/dx2).
Eigen::Matrix<double, 6, 18> curvature_gradient(const Frame& f) {
  const Eigen::Matrix<double, 12, 9> T = dkt::midside_rotations(f.x);
  return plate_columns<6>(dkt::curvature_gradient(f.x, T)) * f.L;
}

// theta . e3 minus the membrane's in-plane rotation at (xi, eta) per global element dof.
Row18 drilling(const Frame& f, double xi, double eta) {
  const Eigen::Matrix<double, 1, 6> omega = dkt::in_plane_rotation(f.x);
  const double N[3] = {1.0 - xi - eta, xi, eta};
  Row18 row = Row18::Zero();
  for (int a = 0; a < 3; ++a) {
    row.middleCols<2>(6 * a) = -omega.middleCols<2>(2 * a);
    row(6 * a + 5) = N[a];
  }
  return row * f.L;
}

const IntegrationRule& surface_rule() {
  static const IntegrationRule r = [] {
    IntegrationRule s;
    s.points = {
        {1.0 / 6.0, 1.0 / 6.0, 0.0}, {2.0 / 3.0, 1.0 / 6.0, 0.0}, {1.0 / 6.0, 2.0 / 3.0, 0.0}};
    s.weights = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
    return s;
  }();
  return r;
}

void check_displacements(const Stri3& element, const ElementGeometry& g,
                         const Eigen::Ref<const Eigen::VectorXd>& u) {
  if (u.size() != 18)
    throw std::invalid_argument(shell_detail::label(element, g) + ": displacement vector has " +
                                std::to_string(u.size()) + " entries, expected 18");
}

Eigen::Matrix3d plane_stress(const shell_detail::ShellSetup& s) {
  return s.D.topLeftCorner<3, 3>();
}

void put_tensor(const Eigen::Matrix3d& m, Eigen::MatrixXd& rows, Eigen::Index row) {
  rows.row(row) << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2);
}

}  // namespace

void Stri3::stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind,
                      Eigen::MatrixXd& K, const ElementOptions&) const {
  const shell_detail::ShellSetup s = shell_detail::section_setup(*this, g, material.material());
  const Frame f = frame(*this, g);
  const Eigen::Matrix3d D0 = plane_stress(s);
  const double t = s.thickness, zm = -s.offset * t;  // mid-surface from the reference surface
  // Section stiffness of (membrane strains, curvatures) about the reference surface.
  const Eigen::Matrix3d A = t * D0, B = zm * t * D0, Dbb = (t * t * t / 12.0 + t * zm * zm) * D0;
  const Op3 Em = membrane(f);
  const double drill = shell_detail::kDrillingFactor * s.shear * t;
  K.setZero(18, 18);
  const IntegrationRule& r = surface_rule();
  for (int p = 0; p < r.size(); ++p) {
    const double w = 2.0 * f.area * r.weights[p];
    const Op3 Kb = curvature(f, r.points[p][0], r.points[p][1]);
    const Row18 d = drilling(f, r.points[p][0], r.points[p][1]);
    K.noalias() += w * (Em.transpose() * A * Em + Kb.transpose() * Dbb * Kb +
                        Em.transpose() * B * Kb + Kb.transpose() * B * Em);
    K.noalias() += (w * drill) * d.transpose() * d;
  }
  K = 0.5 * (K + K.transpose()).eval();
}

void Stri3::strains_stresses(const ElementGeometry& g, const ElementMaterial& material,
                             RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                             Eigen::MatrixXd& strain, Eigen::MatrixXd& stress,
                             const ElementOptions& options,
                             const Eigen::MatrixXd* initial_stress) const {
  Eigen::VectorXd unused;
  eigenstrain_load(g, material, kind, unused, options, initial_stress);  // refuses both
  check_displacements(*this, g, u);
  const shell_detail::ShellSetup s = shell_detail::section_setup(*this, g, material.material());
  const Frame f = frame(*this, g);
  const IntegrationRule r = rule(kind);
  const Eigen::Vector3d membrane_strain = membrane(f) * u;
  strain.resize(r.size(), 6);
  stress.resize(r.size(), 6);
  for (int k = 0; k < r.size(); ++k) {
    const Eigen::Vector3d e =
        membrane_strain + s.z(r.points[k][2]) * (curvature(f, r.points[k][0], r.points[k][1]) * u);
    const Eigen::Vector3d sigma = plane_stress(s) * e;
    Eigen::Matrix3d m;
    m << sigma(0), sigma(2), 0.0, sigma(2), sigma(1), 0.0, 0.0, 0.0, 0.0;
    put_tensor(f.R * m * f.R.transpose(), stress, k);
    const double e33 = -s.poisson / (1.0 - s.poisson) * (e(0) + e(1));  // sigma33 = 0
    m << e(0), 0.5 * e(2), 0.0, 0.5 * e(2), e(1), 0.0, 0.0, 0.0, e33;
    put_tensor(f.R * m * f.R.transpose(), strain, k);
  }
}

void Stri3::section_resultants(const ElementGeometry& g, const ElementMaterial& material,
                               RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                               Eigen::MatrixXd& forces, Eigen::MatrixXd& moments) const {
  Eigen::VectorXd unused;
  eigenstrain_load(g, material, kind, unused);  // refuses temperature changes
  check_displacements(*this, g, u);
  const shell_detail::ShellSetup s = shell_detail::section_setup(*this, g, material.material());
  const Frame f = frame(*this, g);
  const Eigen::Matrix3d D0 = plane_stress(s);
  const double t = s.thickness, zm = -s.offset * t;
  const Eigen::Vector3d membrane_strain = membrane(f) * u;
  const IntegrationRule& r = surface_rule();
  forces.resize(r.size(), 5);
  moments.resize(r.size(), 3);
  // Transverse shear forces from the moments' equilibrium (constant on the element).
  const Eigen::Matrix<double, 6, 1> dkappa = curvature_gradient(f) * u;
  const Eigen::Vector3d dM1 = t * t * t / 12.0 * D0 * dkappa.head<3>();  // d M / d x1
  const Eigen::Vector3d dM2 = t * t * t / 12.0 * D0 * dkappa.tail<3>();  // d M / d x2
  const double Q13 = dM1(0) + dM2(2), Q23 = dM1(2) + dM2(1);
  for (int p = 0; p < r.size(); ++p) {
    const Eigen::Vector3d kappa = curvature(f, r.points[p][0], r.points[p][1]) * u;
    forces.row(p).head<3>() = (t * D0 * (membrane_strain + zm * kappa)).transpose();
    forces(p, 3) = Q13;
    forces(p, 4) = Q23;
    moments.row(p) = (t * t * t / 12.0 * D0 * kappa).transpose();
  }
}

}  // namespace styk
