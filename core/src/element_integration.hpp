// Private to TElement's template methods: the strain operators at the integration points (with
// B-bar and incompatible modes) and the element system they integrate to. Not installed.
#pragma once

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk::element_detail {

// Evaluates, point by point of one rule, the strain operators of one element:
// B (6 x 3n, from TElement::bee) and G (6 x m, from TElement::incompatible_bee), both with the
// mean-dilatation B-bar correction when the options ask for it, and the shape functions N (n).
class PointOperators {
 public:
  PointOperators(const TElement& element, const ElementGeometry& g, const IntegrationRule& rule,
                 const ElementOptions& options);

  // Evaluates point k (0-based) and returns its volume weight w_k det J_k.
  double evaluate(int k);

  int points() const { return rule_.size(); }
  int modes() const { return modes_; }
  const Eigen::VectorXd& N() const { return N_; }
  const Eigen::MatrixXd& B() const { return B_; }
  const Eigen::MatrixXd& G() const { return G_; }

 private:
  double evaluate_plain(int k);  // B and G without B-bar

  const TElement& element_;
  const ElementGeometry& g_;
  const IntegrationRule& rule_;
  bool b_bar_ = false;
  int modes_ = 0;
  Eigen::VectorXd N_;
  Eigen::MatrixXd dN_, dNdx_, B_, G_;
  // Element averages of the divergence rows (B_11 + B_22 + B_33 and the same of G).
  Eigen::RowVectorXd mean_div_B_, mean_div_G_;
};

// The element equations before the incompatible modes are condensed out:
//   [Kuu  Kua] [u]   [fu]
//   [Kua' Kaa] [a] = [fa]      (f: thermal load, zero without temperatures)
struct ElementSystem {
  Eigen::MatrixXd Kuu, Kua, Kaa;
  Eigen::VectorXd fu, fa;
};

// Integrates the element system over `rule`. alpha_dT (n, may be null) holds alpha * dT at the
// nodes; the thermal strain alpha dT (1,1,1,0,0,0) is interpolated with N.
void integrate_system(const TElement& element, const ElementGeometry& g, const Matrix6d& D,
                      const IntegrationRule& rule, const ElementOptions& options,
                      const Eigen::VectorXd* alpha_dT, ElementSystem& system);

// alpha * dT at the nodes for a material, or an empty vector when there is no temperature
// change; an InputError at the material when dT != 0 and the material has no *EXPANSION.
Eigen::VectorXd nodal_thermal_strain(const Material& material, const TElement& element,
                                     const Eigen::VectorXd* nodal_dT);

}  // namespace styk::element_detail
