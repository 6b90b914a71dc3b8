// Stresses and strains away from the integration points (SPEC §5): extrapolated to the element
// nodes (unaveraged), evaluated at the element centre, and averaged at the nodes by the thesis'
// two methods.
//
// Extrapolation. The integration-point values of one element are fitted, in the least-squares
// sense, by a field in a polynomial space on the reference element; that field is then evaluated
// at the element's nodes and at xi = 0 (the centroid value). The space is the first of
//   1. the element's own shape functions (the isoparametric space),
//   2. trilinear {1, xi, eta, zeta, xi eta, eta zeta, zeta xi, xi eta zeta},
//   3. linear {1, xi, eta, zeta},
//   4. constant,
// whose values at the integration points have full column rank (condition number below 1e8).
// Every Styk hexahedron with its full rule takes space 1 (C3D8 2x2x2 = the classic trilinear
// extrapolation; C3D20/C3D21/C3D14 3x3x3 and C3D28 4x4x3: their space lies in the tensor space
// the Gauss grid is unisolvent for); spaces 2-4 serve rules with fewer points than nodes (e.g. a
// reduced rule). Each space contains the linear functions, so a stress field that is linear in
// the natural coordinates (any linear field on an affinely mapped element) is reproduced exactly
// at the nodes and the centre; with as many points as functions the fit interpolates, otherwise
// the centroid value is the fit's, not the middle point's (they agree whenever the point values
// lie in the space).
//
// Averaging at the nodes (unweighted, over every element that uses the node, whatever its
// material or section; averaging within sets only is a later option):
//   method I  = mean of the element-node values of those elements,
//   method II = mean of their centroid values.
// A node no element uses gets zeros.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

// The linear maps from the integration-point values of one element type and rule (n_ip rows of
// one component) to its node values and its centroid value.
struct Extrapolation {
  Eigen::MatrixXd to_nodes;        // n_nodes x n_ip
  Eigen::RowVectorXd to_centroid;  // 1 x n_ip
  std::string space;               // "element", "trilinear", "linear" or "constant"
};

// Builds the extrapolation of `element` for the points of `rule` (see the file comment).
// Throws std::logic_error for a rule without points.
Extrapolation make_extrapolation(const TElement& element, const IntegrationRule& rule);

// The averaging of one analysis: the extrapolation of every element type (computed once, owned
// here) and the node-to-element incidence. The model and the formulations must outlive it.
class StressAveraging {
 public:
  // `formulation[e]` is element e's formulation; `kind` the rule the integration-point values of
  // the increments come from (one for all elements, or `kinds[e]` per element).
  StressAveraging(const Model& model, const std::vector<const TElement*>& formulation,
                  RuleKind kind);
  StressAveraging(const Model& model, const std::vector<const TElement*>& formulation,
                  const std::vector<RuleKind>& kinds);

  // From inc.ip_offset, inc.S and inc.E fills S/E_element_nodes, S/E_centroid, S/E_nodal_I and
  // S/E_nodal_II (a field whose integration-point values are empty stays empty). Threaded over
  // elements, then over nodes. Throws std::logic_error when the increment's integration points do
  // not match the model's rules.
  void apply(int threads, IncrementResult& inc) const;

  // The extrapolation element e uses.
  const Extrapolation& extrapolation(int element) const {
    return operators_[operator_of_element_[element]].extrapolation;
  }

 private:
  void extrapolate(int threads, const std::vector<int>& ip_offset,
                   const std::vector<Tensor6>& ip_values, std::vector<Tensor6>& element_nodes,
                   std::vector<Tensor6>& centroid) const;
  void average(int threads, const std::vector<Tensor6>& element_nodes,
               const std::vector<Tensor6>& centroid, std::vector<Tensor6>& nodal_I,
               std::vector<Tensor6>& nodal_II) const;

  const Model& model_;
  struct Operator {
    const TElement* element;
    RuleKind kind;
    Extrapolation extrapolation;
  };
  std::vector<Operator> operators_;  // one per element type and rule
  std::vector<int> operator_of_element_;
  // Incidence: node n appears at connectivity positions slots_[slot_offset_[n] ..
  // slot_offset_[n+1]-1]; element_of_slot_[c] is the element owning connectivity position c.
  std::vector<int> slot_offset_;
  std::vector<int> slots_;
  std::vector<int> element_of_slot_;
};

}  // namespace styk::solver_detail
