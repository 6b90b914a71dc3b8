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

// The material law of one element at the points of one rule: the MaterialPoint of the
// material (constitutive.hpp) and the element's D from its DEE hook. Evaluated once when the law
// is the same at every point (ElementMaterial::varies() false), else at each point.
class PointLaws {
 public:
  PointLaws(const TElement& element, const ElementGeometry& g, const ElementMaterial& material);
  // The law at the point with shape functions N (evaluate it first with PointOperators).
  void evaluate(const Eigen::VectorXd& N);
  const MaterialPoint& point() const { return point_; }
  const Matrix6d& D() const { return D_; }
  // The stress the eigenstrains leave without displacement, D eps_th - sigma0 (`sigma0` a row
  // of initial stresses, may be null).
  Vector6d prestress(const Eigen::MatrixXd* sigma0, int k) const;

 private:
  const TElement& element_;
  const ElementGeometry& g_;
  const ElementMaterial& material_;
  bool done_ = false;
  MaterialPoint point_;
  Matrix6d D_;
};

// The element equations before the incompatible modes are condensed out:
//   [Kuu  Kua] [u]   [fu]
//   [Kua' Kaa] [a] = [fa]      (f: eigenstrain load, zero without temperatures and sigma0)
struct ElementSystem {
  Eigen::MatrixXd Kuu, Kua, Kaa;
  Eigen::VectorXd fu, fa;
};

// Integrates the element system over `rule`. With `eigenstrains` the load of the thermal strain
// of `material` and of the initial stresses `sigma0` (one row per point, may be null) is
// integrated too: f = integral of B^T (D eps_th - sigma0).
void integrate_system(const TElement& element, const ElementGeometry& g,
                      const ElementMaterial& material, const IntegrationRule& rule,
                      const ElementOptions& options, bool eigenstrains,
                      const Eigen::MatrixXd* sigma0, ElementSystem& system);

// Throws std::invalid_argument when `sigma0` is given with a row count other than the rule's.
void check_initial_stress(const TElement& element, const IntegrationRule& rule,
                          const Eigen::MatrixXd* sigma0);

}  // namespace styk::element_detail
