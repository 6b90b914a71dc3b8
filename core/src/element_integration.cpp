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

void integrate_system(const TElement& element, const ElementGeometry& g, const Matrix6d& D,
                      const IntegrationRule& rule, const ElementOptions& options,
                      const Eigen::VectorXd* alpha_dT, ElementSystem& system) {
  const int n = element.node_count();
  PointOperators op(element, g, rule, options);
  const int m = op.modes();
  system.Kuu.setZero(3 * n, 3 * n);
  system.Kua.setZero(3 * n, m);
  system.Kaa.setZero(m, m);
  system.fu.setZero(3 * n);
  system.fa.setZero(m);
  Eigen::MatrixXd DB(6, 3 * n), DG(6, m);
  Eigen::Matrix<double, 6, 1> sigma_th;
  for (int k = 0; k < op.points(); ++k) {
    const double dv = op.evaluate(k);
    DB.noalias() = D * op.B();
    system.Kuu.noalias() += dv * op.B().transpose() * DB;
    if (m > 0) {
      DG.noalias() = D * op.G();
      system.Kua.noalias() += dv * op.B().transpose() * DG;
      system.Kaa.noalias() += dv * op.G().transpose() * DG;
    }
    if (alpha_dT && alpha_dT->size() > 0) {
      // D eps_th with eps_th = alpha dT (1, 1, 1, 0, 0, 0): the sum of D's first three columns.
      const double strain = op.N().dot(*alpha_dT);
      sigma_th = strain * D.leftCols<3>().rowwise().sum();
      system.fu.noalias() += dv * op.B().transpose() * sigma_th;
      if (m > 0) system.fa.noalias() += dv * op.G().transpose() * sigma_th;
    }
  }
}

Eigen::VectorXd nodal_thermal_strain(const Material& material, const TElement& element,
                                     const Eigen::VectorXd* nodal_dT) {
  if (!nodal_dT) return {};
  if (nodal_dT->size() != element.node_count())
    throw std::invalid_argument(element.name() + ": " + std::to_string(nodal_dT->size()) +
                                " nodal temperatures given, expected " +
                                std::to_string(element.node_count()));
  if (nodal_dT->cwiseAbs().maxCoeff() == 0.0) return {};
  if (!material.expansion)
    throw InputError(material.where, "material " + material.name +
                                         ": *EXPANSION (thermal expansion coefficient) is "
                                         "required for a temperature change");
  return *material.expansion * *nodal_dT;
}

}  // namespace styk::element_detail
