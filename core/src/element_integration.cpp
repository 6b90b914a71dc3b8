#include "element_integration.hpp"

#include <stdexcept>
#include <string>

namespace styk::element_detail {

PointOperators::PointOperators(const TElement& element, const ElementGeometry& g,
                               const IntegrationRule& rule, const ElementOptions& options)
    : element_(element), g_(g), rule_(rule), modes_(element.incompatible_mode_count()) {
  const int n = element.node_count();
  N_.resize(n);
  dN_.resize(n, 3);
  dNdx_.resize(n, 3);
  B_.resize(6, 3 * n);
  G_.resize(6, modes_);
  // A one-point rule has nothing to average: B-bar would return B itself.
  b_bar_ = options.selective_volumetric && rule.size() > 1;
  if (!b_bar_) return;
  // Mean dilatation: the volume averages of the divergence rows, integrated with the same rule.
  mean_div_B_.setZero(3 * n);
  mean_div_G_.setZero(modes_);
  double volume = 0.0;
  for (int k = 0; k < rule.size(); ++k) {
    const double dv = evaluate_plain(k);
    volume += dv;
    mean_div_B_.noalias() += dv * B_.topRows<3>().colwise().sum();
    if (modes_ > 0) mean_div_G_.noalias() += dv * G_.topRows<3>().colwise().sum();
  }
  mean_div_B_ /= volume;
  mean_div_G_ /= volume;
}

double PointOperators::evaluate_plain(int k) {
  element_.der(rule_.points[k], N_, dN_);
  const double detJ = element_.point_measure(g_, N_, dN_, dNdx_, k + 1);
  element_.strain_operator(g_, N_, dNdx_, B_);
  if (modes_ > 0) element_.incompatible_bee(g_, rule_.points[k], detJ, G_);
  return rule_.weights[k] * detJ;
}

double PointOperators::evaluate(int k) {
  const double dv = evaluate_plain(k);
  if (b_bar_) {
    // Replace the volumetric third of each normal-strain row, (div B)/3, by its element average:
    // the deviatoric strain stays pointwise, the dilatation becomes constant over the element.
    const Eigen::RowVectorXd shift_B = (mean_div_B_ - B_.topRows<3>().colwise().sum()) / 3.0;
    B_.topRows<3>().rowwise() += shift_B;
    if (modes_ > 0) {
      const Eigen::RowVectorXd shift_G = (mean_div_G_ - G_.topRows<3>().colwise().sum()) / 3.0;
      G_.topRows<3>().rowwise() += shift_G;
    }
  }
  return dv;
}

PointLaws::PointLaws(const TElement& element, const ElementGeometry& g,
                     const ElementMaterial& material)
    : element_(element), g_(g), material_(material) {}

void PointLaws::evaluate(const Eigen::VectorXd& N) {
  if (done_ && !material_.varies()) return;
  const Eigen::Vector3d x = g_.X.transpose() * N;
  material_.at(N, x, point_);
  element_.dee(point_, D_);
  done_ = true;
}

Vector6d PointLaws::prestress(const Eigen::MatrixXd* sigma0, int k) const {
  Vector6d s = Vector6d::Zero();
  if (material_.has_thermal_strain()) s.noalias() = D_ * point_.thermal_strain;
  if (sigma0) s -= sigma0->row(k).transpose();
  return s;
}

void check_initial_stress(const TElement& element, const IntegrationRule& rule,
                          const Eigen::MatrixXd* sigma0) {
  if (sigma0 && (sigma0->rows() != rule.size() || sigma0->cols() != 6))
    throw std::invalid_argument(element.name() + ": initial stresses for " +
                                std::to_string(sigma0->rows()) + " points given, the rule has " +
                                std::to_string(rule.size()));
}

void integrate_system(const TElement& element, const ElementGeometry& g,
                      const ElementMaterial& material, const IntegrationRule& rule,
                      const ElementOptions& options, bool eigenstrains,
                      const Eigen::MatrixXd* sigma0, ElementSystem& system) {
  check_initial_stress(element, rule, sigma0);
  const int n = element.node_count();
  PointOperators op(element, g, rule, options);
  PointLaws law(element, g, material);
  const int m = op.modes();
  system.Kuu.setZero(3 * n, 3 * n);
  system.Kua.setZero(3 * n, m);
  system.Kaa.setZero(m, m);
  system.fu.setZero(3 * n);
  system.fa.setZero(m);
  const bool loaded = eigenstrains && (material.has_thermal_strain() || sigma0 != nullptr);
  Eigen::MatrixXd DB(6, 3 * n), DG(6, m);
  for (int k = 0; k < op.points(); ++k) {
    const double dv = op.evaluate(k);
    law.evaluate(op.N());
    const Matrix6d& D = law.D();
    DB.noalias() = D * op.B();
    system.Kuu.noalias() += dv * op.B().transpose() * DB;
    if (m > 0) {
      DG.noalias() = D * op.G();
      system.Kua.noalias() += dv * op.B().transpose() * DG;
      system.Kaa.noalias() += dv * op.G().transpose() * DG;
    }
    if (loaded) {
      const Vector6d prestress = law.prestress(sigma0, k);
      system.fu.noalias() += dv * op.B().transpose() * prestress;
      if (m > 0) system.fa.noalias() += dv * op.G().transpose() * prestress;
    }
  }
}

}  // namespace styk::element_detail
