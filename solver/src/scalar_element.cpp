#include "scalar_element.hpp"

#include <stdexcept>

namespace styk::solver_detail {

void scalar_conductance(const TElement& element, const ElementGeometry& g,
                        const IntegrationRule& rule, const Eigen::Vector3d& k, Eigen::MatrixXd& K) {
  const int n = element.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  K.setZero(n, n);
  for (int p = 0; p < rule.size(); ++p) {
    element.der(rule.points[p], N, dN);
    const double measure = element.point_measure(g, N, dN, dNdx, p + 1);
    const Eigen::MatrixXd kdNdx = dNdx * k.asDiagonal();
    K.noalias() += (rule.weights[p] * measure) * kdNdx * dNdx.transpose();
  }
}

void scalar_gradients(const TElement& element, const ElementGeometry& g,
                      const IntegrationRule& rule, const Eigen::Ref<const Eigen::VectorXd>& phi,
                      Eigen::MatrixXd& gradients) {
  const int n = element.node_count();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  gradients.resize(rule.size(), 3);
  for (int p = 0; p < rule.size(); ++p) {
    element.der(rule.points[p], N, dN);
    element.point_measure(g, N, dN, dNdx, p + 1);
    gradients.row(p).noalias() = phi.transpose() * dNdx;
  }
}

void scalar_face_flux(const TElement& element, const ElementGeometry& g, int face, double q,
                      Eigen::VectorXd& f) {
  const std::vector<FaceDef>& faces = element.faces();
  if (face < 0 || face >= static_cast<int>(faces.size()))
    throw std::logic_error("scalar_face_flux: face out of range");
  const int n = element.node_count();
  std::vector<Vec3> points;
  std::vector<Eigen::Vector3d> weighted_normals;
  element.face_quadrature(g, faces[face], points, weighted_normals);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  f.setZero(n);
  for (std::size_t p = 0; p < points.size(); ++p) {
    element.der(points[p], N, dN);
    f.noalias() += (q * weighted_normals[p].norm()) * N;
  }
}

bool rule_resolves_scalar_field(const TElement& element, const IntegrationRule& rule) {
  const DofSet active = element.active_dofs();
  const int dimensions = static_cast<int>(active[0]) + active[1] + active[2];
  return rule.size() * dimensions >= element.node_count() - 1;
}

}  // namespace styk::solver_detail
