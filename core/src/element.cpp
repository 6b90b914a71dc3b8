// TElement defaults (BEE, DEE, hooks) and template methods (Jacobian, stiffness, thermal load,
// internal force, face loads, stresses); the integration itself is in element_integration.cpp.
//
// Every template method allocates its workspaces once per call, before the integration-point
// loop; inside the loop only fixed-size temporaries and `noalias()` products are used.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "styk/core/element.hpp"
#include "styk/core/face_param.hpp"

#include "element_integration.hpp"

namespace styk {

namespace {

// "element 12 (C3D8)": how every message names an element.
std::string element_label(const ElementGeometry& g, const TElement& e) {
  return "element " + std::to_string(g.id) + " (" + e.name() + ")";
}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

void check_geometry(const ElementGeometry& g, const TElement& e) {
  if (g.X.rows() != e.node_count() || g.X.cols() != 3)
    throw InputError(g.where, element_label(g, e) + ": has " + std::to_string(g.X.rows()) +
                                  " nodes, expected " + std::to_string(e.node_count()));
}

void check_displacements(const ElementGeometry& g, const TElement& e,
                         const Eigen::Ref<const Eigen::VectorXd>& u) {
  if (u.size() != e.node_dofs() * e.node_count())
    throw std::invalid_argument(element_label(g, e) + ": displacement vector has " +
                                std::to_string(u.size()) + " entries, expected " +
                                std::to_string(e.node_dofs() * e.node_count()));
}

const FaceDef& checked_face(const ElementGeometry& g, const TElement& e, int face) {
  const auto& faces = e.faces();
  if (face < 0 || face >= static_cast<int>(faces.size()))
    throw InputError(g.where, element_label(g, e) + " has no face S" + std::to_string(face + 1) +
                                  " (faces S1..S" + std::to_string(faces.size()) + ")");
  return faces[face];
}

// Face quadrature of a face parametrised from its corners (FaceDef::axis = -1): the area vectors
// point out of the element.
void corner_face_quadrature(const TElement& e, const ElementGeometry& g, const FaceDef& face,
                            std::vector<Vec3>& points,
                            std::vector<Eigen::Vector3d>& weighted_normals) {
  const FaceParam param(e, face);
  const FaceRule rule = face_rule(param.triangle(), e.face_rule_order());
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  Eigen::Matrix3d J;
  Eigen::Vector3d dp, dq;
  points.clear();
  weighted_normals.clear();
  for (std::size_t k = 0; k < rule.weights.size(); ++k) {
    const Vec3 xi = param.point(rule.points[k][0], rule.points[k][1]);
    e.der(xi, N, dN);
    param.tangents(rule.points[k][0], rule.points[k][1], dp, dq);
    J.noalias() = dN.transpose() * g.X;  // row i = dx / dxi_i
    const Eigen::Vector3d xp = J.transpose() * dp, xq = J.transpose() * dq;
    points.push_back(xi);
    weighted_normals.push_back(rule.weights[k] * param.outward() * xp.cross(xq));
  }
}

// Visits the face integration points: calls visit(N, dA, weight-free) with the shape functions and
// the weighted area vector (oriented along +face.axis) from TElement::face_quadrature.
template <typename Visit>
void for_each_face_point(const ElementGeometry& g, const TElement& e, const FaceDef& face,
                         Visit&& visit) {
  std::vector<Vec3> points;
  std::vector<Eigen::Vector3d> weighted_normals;
  e.face_quadrature(g, face, points, weighted_normals);
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  for (std::size_t k = 0; k < points.size(); ++k) {
    e.der(points[k], N, dN);
    visit(N, weighted_normals[k]);
  }
}

// A constant material whose nodes changed temperature by `nodal_dT` from 0: the thermal strain
// alpha dT of a constant coefficient (the callers that give changes rather than temperatures).
ElementMaterial with_temperature_change(const Material& material,
                                        const Eigen::Ref<const Eigen::VectorXd>& nodal_dT,
                                        const TElement& e) {
  if (nodal_dT.size() != e.node_count())
    throw std::invalid_argument(e.name() + ": " + std::to_string(nodal_dT.size()) +
                                " nodal temperatures given, expected " +
                                std::to_string(e.node_count()));
  return ElementMaterial(material, nullptr, nodal_dT, Eigen::VectorXd::Zero(nodal_dT.size()));
}

// The element D at the element centre, what hourglass stabilisation scales with.
Matrix6d stabilisation_law(const ElementGeometry& g, const ElementMaterial& material,
                           const TElement& e) {
  const int n = e.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  e.der({0.0, 0.0, 0.0}, N, dN);
  MaterialPoint point;
  material.at(N, g.X.transpose() * N, point);
  Matrix6d D;
  e.dee(point, D);
  return D;
}

}  // namespace

void TElement::bee(const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
                   Eigen::Ref<Eigen::MatrixXd> B) const {
  B.setZero();
  for (Eigen::Index a = 0; a < dNdx.rows(); ++a) {
    const double dx = dNdx(a, 0), dy = dNdx(a, 1), dz = dNdx(a, 2);
    const Eigen::Index c = 3 * a;
    B(0, c) = dx;
    B(1, c + 1) = dy;
    B(2, c + 2) = dz;
    B(3, c) = dy;  // gamma_12
    B(3, c + 1) = dx;
    B(4, c) = dz;  // gamma_13
    B(4, c + 2) = dx;
    B(5, c + 1) = dz;  // gamma_23
    B(5, c + 2) = dy;
  }
}

void TElement::dee(const MaterialPoint& material, Matrix6d& D) const { D = material.D; }

double TElement::jacobian(const ElementGeometry& g, const Eigen::Ref<const Eigen::MatrixXd>& dN,
                          Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  Eigen::Matrix3d J;
  J.noalias() = dN.transpose() * g.X;  // J(i, j) = dx_j / dxi_i
  const double det = J.determinant();
  // Degenerate means small relative to the lengths of the three natural tangents (Hadamard's
  // bound), so the test does not depend on the unit of length.
  const double scale = J.row(0).norm() * J.row(1).norm() * J.row(2).norm();
  if (!(det > 1e-12 * scale))
    throw InputError(g.where, element_label(g, *this) + ": Jacobian determinant " +
                                  format_number(det) + " at integration point " +
                                  std::to_string(point) +
                                  " is not positive: the element is inverted or degenerate");
  dNdx.noalias() = dN * J.inverse().transpose();
  return det;
}

double TElement::point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>&,
                               const Eigen::Ref<const Eigen::MatrixXd>& dN,
                               Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  return jacobian(g, dN, dNdx, point);
}

void TElement::strain_operator(const ElementGeometry&, const Eigen::Ref<const Eigen::VectorXd>&,
                               const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
                               Eigen::Ref<Eigen::MatrixXd> B) const {
  bee(dNdx, B);
}

void TElement::face_quadrature(const ElementGeometry& g, const FaceDef& face,
                               std::vector<Vec3>& points,
                               std::vector<Eigen::Vector3d>& weighted_normals) const {
  if (face.axis < 0) {
    corner_face_quadrature(*this, g, face, points, weighted_normals);
    return;
  }
  std::vector<double> gauss, weights;
  gauss_legendre(face_rule_order(), gauss, weights);
  // Free natural coordinates (s, t) in cyclic order after the face axis, so that x,s x x,t
  // points along +axis on the reference element.
  const int s = (face.axis + 1) % 3, t = (face.axis + 2) % 3;
  const int n = node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  Eigen::Matrix3d J;
  points.clear();
  weighted_normals.clear();
  for (std::size_t a = 0; a < gauss.size(); ++a)
    for (std::size_t b = 0; b < gauss.size(); ++b) {
      Vec3 xi{};
      xi[face.axis] = face.value;
      xi[s] = gauss[a];
      xi[t] = gauss[b];
      der(xi, N, dN);
      J.noalias() = dN.transpose() * g.X;  // row i = dx / dxi_i
      points.push_back(xi);
      weighted_normals.push_back(weights[a] * weights[b] *
                                 J.row(s).transpose().cross(J.row(t).transpose()));
    }
}

void TElement::complete_strain(const MaterialPoint&, Eigen::Matrix<double, 6, 1>&) const {}

int TElement::section_stations(RuleKind) const { return 0; }

void TElement::section_resultants(const ElementGeometry&, const ElementMaterial&, RuleKind,
                                  const Eigen::Ref<const Eigen::VectorXd>&, Eigen::MatrixXd& forces,
                                  Eigen::MatrixXd& moments) const {
  forces.resize(0, 3);
  moments.resize(0, 3);
}

void TElement::incompatible_bee(const ElementGeometry&, const Vec3&, double,
                                Eigen::Ref<Eigen::MatrixXd>) const {}

void TElement::add_stabilisation(const ElementGeometry&, const Matrix6d&, const ElementOptions&,
                                 Eigen::MatrixXd&) const {}

void TElement::stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                         Eigen::MatrixXd& K, const ElementOptions& options) const {
  check_geometry(g, *this);
  element_detail::ElementSystem system;
  element_detail::integrate_system(*this, g, material, rule(kind), options, false, nullptr, system);
  K = std::move(system.Kuu);
  if (system.Kaa.rows() > 0) {
    // Static condensation of the incompatible modes: K = Kuu - Kua Kaa^-1 Kua^T.
    const Eigen::LDLT<Eigen::MatrixXd> Kaa(system.Kaa);
    K.noalias() -= system.Kua * Kaa.solve(system.Kua.transpose());
  }
  add_stabilisation(g, stabilisation_law(g, material, *this), options, K);
  // The products above are symmetric only up to round-off; solvers (CHOLMOD) want it exact.
  K = 0.5 * (K + K.transpose()).eval();
}

void TElement::eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material,
                                RuleKind kind, Eigen::VectorXd& f, const ElementOptions& options,
                                const Eigen::MatrixXd* initial_stress) const {
  check_geometry(g, *this);
  if (!material.has_thermal_strain() && !initial_stress) {
    f.setZero(3 * node_count());
    return;
  }
  element_detail::ElementSystem system;
  element_detail::integrate_system(*this, g, material, rule(kind), options, true, initial_stress,
                                   system);
  f = std::move(system.fu);
  // The modes are internal: their share of the load goes to the nodes through Kua Kaa^-1.
  if (system.Kaa.rows() > 0)
    f.noalias() -= system.Kua * Eigen::LDLT<Eigen::MatrixXd>(system.Kaa).solve(system.fa);
}

void TElement::thermal_load(const ElementGeometry& g, const Material& material, RuleKind kind,
                            const Eigen::Ref<const Eigen::VectorXd>& nodal_dT, Eigen::VectorXd& f,
                            const ElementOptions& options) const {
  eigenstrain_load(g, with_temperature_change(material, nodal_dT, *this), kind, f, options);
}

void TElement::internal_force(const ElementGeometry& g, const ElementMaterial& material,
                              RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                              Eigen::VectorXd& f, const ElementOptions& options,
                              const Eigen::MatrixXd* initial_stress) const {
  check_displacements(g, *this, u);
  // Linear elasticity: f = K u - f_eigen is exactly the integral of B^T sigma (plus stabilisation
  // forces) with the condensed incompatible modes and B-bar included.
  Eigen::MatrixXd K;
  stiffness(g, material, kind, K, options);
  f.noalias() = K * u;
  if (material.has_thermal_strain() || initial_stress) {
    Eigen::VectorXd f_eigen;
    eigenstrain_load(g, material, kind, f_eigen, options, initial_stress);
    f -= f_eigen;
  }
}

void TElement::internal_force(const ElementGeometry& g, const Material& material, RuleKind kind,
                              const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::VectorXd& f,
                              const ElementOptions& options,
                              const Eigen::VectorXd* nodal_dT) const {
  if (!nodal_dT) {
    internal_force(g, ElementMaterial(material), kind, u, f, options);
    return;
  }
  internal_force(g, with_temperature_change(material, *nodal_dT, *this), kind, u, f, options);
}

void TElement::body_load(const ElementGeometry& g, double density, RuleKind kind,
                         const BodyAcceleration& acceleration, Eigen::VectorXd& f) const {
  check_geometry(g, *this);
  const IntegrationRule r = rule(kind);
  const int n = node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  f.setZero(3 * n);
  for (int k = 0; k < r.size(); ++k) {
    der(r.points[k], N, dN);
    const double dv = r.weights[k] * point_measure(g, N, dN, dNdx, k + 1);
    const Eigen::Vector3d x = g.X.transpose() * N;
    const Vec3 a = acceleration.at({x(0), x(1), x(2)});
    for (int p = 0; p < n; ++p)
      for (int d = 0; d < 3; ++d) f(3 * p + d) += dv * density * N(p) * a[d];
  }
}

void TElement::pressure_load(const ElementGeometry& g, int face, double p,
                             Eigen::VectorXd& f) const {
  check_geometry(g, *this);
  const FaceDef& fd = checked_face(g, *this, face);
  // Area vectors point along +axis on a cube face, outward on any other (face_quadrature()).
  const double orientation = fd.axis < 0 || fd.value > 0.0 ? 1.0 : -1.0;
  f.setZero(3 * node_count());
  for_each_face_point(g, *this, fd, [&](const Eigen::VectorXd& N, const Eigen::Vector3d& dA) {
    // Positive pressure pushes into the element: against the outward normal.
    const Eigen::Vector3d traction = (-p * orientation) * dA;
    for (Eigen::Index a = 0; a < N.size(); ++a) f.segment<3>(3 * a) += N(a) * traction;
  });
}

void TElement::nodal_areas(const ElementGeometry& g, int face, Eigen::VectorXd& area) const {
  check_geometry(g, *this);
  const FaceDef& fd = checked_face(g, *this, face);
  area.setZero(node_count());
  for_each_face_point(g, *this, fd, [&](const Eigen::VectorXd& N, const Eigen::Vector3d& dA) {
    area.noalias() += dA.norm() * N;
  });
}

void TElement::strains_stresses(const ElementGeometry& g, const ElementMaterial& material,
                                RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                                Eigen::MatrixXd& strain, Eigen::MatrixXd& stress,
                                const ElementOptions& options,
                                const Eigen::MatrixXd* initial_stress) const {
  check_geometry(g, *this);
  check_displacements(g, *this, u);
  const IntegrationRule r = rule(kind);
  element_detail::check_initial_stress(*this, r, initial_stress);
  // Incompatible modes from the element equilibrium of the internal dofs: a = Kaa^-1 (fa - Kua^T
  // u).
  Eigen::VectorXd modes;
  if (incompatible_mode_count() > 0) {
    element_detail::ElementSystem system;
    element_detail::integrate_system(*this, g, material, r, options, true, initial_stress, system);
    modes = Eigen::LDLT<Eigen::MatrixXd>(system.Kaa).solve(system.fa - system.Kua.transpose() * u);
  }
  element_detail::PointOperators op(*this, g, r, options);
  element_detail::PointLaws law(*this, g, material);
  strain.resize(r.size(), 6);
  stress.resize(r.size(), 6);
  Eigen::Matrix<double, 6, 1> engineering;
  for (int k = 0; k < r.size(); ++k) {
    op.evaluate(k);
    law.evaluate(op.N());
    engineering.noalias() = op.B() * u;
    if (modes.size() > 0) engineering.noalias() += op.G() * modes;
    // sigma = D (eps - eps_th) + sigma0 = D eps - (D eps_th - sigma0).
    stress.row(k).noalias() =
        (law.D() * engineering - law.prestress(initial_stress, k)).transpose();
    complete_strain(law.point(), engineering);
    strain.row(k) = engineering.transpose();
    strain.row(k).tail<3>() *= 0.5;  // report tensor shear components eps_ij = gamma_ij / 2
  }
}

void TElement::strains_stresses(const ElementGeometry& g, const Material& material, RuleKind kind,
                                const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& strain,
                                Eigen::MatrixXd& stress, const ElementOptions& options,
                                const Eigen::VectorXd* nodal_dT) const {
  if (!nodal_dT) {
    strains_stresses(g, ElementMaterial(material), kind, u, strain, stress, options);
    return;
  }
  strains_stresses(g, with_temperature_change(material, *nodal_dT, *this), kind, u, strain, stress,
                   options);
}

void TElement::point_volumes(const ElementGeometry& g, RuleKind kind, Eigen::VectorXd& dv) const {
  check_geometry(g, *this);
  const IntegrationRule r = rule(kind);
  const int n = node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  dv.resize(r.size());
  for (int k = 0; k < r.size(); ++k) {
    der(r.points[k], N, dN);
    dv(k) = r.weights[k] * point_measure(g, N, dN, dNdx, k + 1);
  }
}

void TElement::point_laws(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                          std::vector<MaterialPoint>& laws) const {
  check_geometry(g, *this);
  const IntegrationRule r = rule(kind);
  const int n = node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  laws.resize(r.size());
  for (int k = 0; k < r.size(); ++k) {
    der(r.points[k], N, dN);
    material.at(N, g.X.transpose() * N, laws[k]);
  }
}

void TElement::point_positions(const ElementGeometry& g, RuleKind kind, Eigen::MatrixXd& x) const {
  check_geometry(g, *this);
  const IntegrationRule r = rule(kind);
  const int n = node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  x.resize(r.size(), 3);
  for (int k = 0; k < r.size(); ++k) {
    der(r.points[k], N, dN);
    x.row(k) = (g.X.transpose() * N).transpose();
  }
}

}  // namespace styk
