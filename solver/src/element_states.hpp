// The material state of every element in one increment, what the elements' template methods
// take beyond geometry and displacements: the law of its section (the material after any
// *CHANGE SOLID SECTION of the steps so far, the *ORIENTATION axes), the nodal temperatures now
// and initially, and the initial stresses (*INITIAL CONDITIONS, TYPE=STRESS).
#pragma once

#include <map>
#include <vector>

#include <Eigen/Core>

#include "prepared_model.hpp"

namespace styk::solver_detail {

// Absolute temperature per model node at the start of the analysis (*INITIAL CONDITIONS,
// TYPE=TEMPERATURE; 0 where not given).
std::vector<double> initial_node_temperatures(const Model& model);

class ElementStates {
 public:
  // The state in step `step` (0-based) with the nodal temperatures `temperature` (absolute, per
  // model node; null: the initial temperatures). Keeps references to its arguments. Throws
  // InputError at a *CHANGE SOLID SECTION naming an element set no section has, and at an
  // initial stress whose point the element's rule does not have.
  ElementStates(const Model& model, const PreparedModel& prepared, std::size_t step,
                const std::vector<double>* temperature);

  // The material of element e in this state (after *CHANGE SOLID SECTION).
  const Material& material_of(int e) const;
  // The law for the stiffness: material, axes, and temperatures where the elastic constants
  // depend on them.
  ElementMaterial stiffness_law(int e) const;
  // The full law: temperatures for the thermal strain too.
  ElementMaterial law(int e) const;
  // Element e's initial stresses (one row per point of its standard rule), or null.
  const Eigen::MatrixXd* initial_stress(int e) const;
  // Element e has an eigenstrain load: a temperature change on its nodes or initial stresses.
  bool loaded(int e) const;
  // The stiffness of this state differs from the one of `other` (materials or temperatures of
  // temperature-dependent elasticity differ).
  bool stiffness_differs(const ElementStates& other) const;

 private:
  Eigen::VectorXd nodal(const std::vector<double>& values, int e) const;

  const Model& model_;
  const PreparedModel& prepared_;
  const std::vector<double>* temperature_;
  std::vector<double> initial_;
  std::vector<const Material*> material_;  // per element
  std::vector<const LocalAxes*> axes_;     // per section (null: global)
  std::map<int, Eigen::MatrixXd> initial_stress_;
};

}  // namespace styk::solver_detail
