// A model checked for a steady scalar-field analysis (docs/solver.md, "Steady heat and electric
// potential"): which field its steps solve, per element the formulation, rule, conductivity and
// extrapolation, one unknown per node used by an element, and per step the prescribed values,
// nodal flows and face fluxes accumulated over the steps as Abaqus does (OP=MOD; OP=NEW resets).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "stress_averaging.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

// True when some step of `model` is a *HEAT TRANSFER or *COUPLED THERMAL-ELECTRICAL step.
bool has_scalar_field_steps(const Model& model);

struct ScalarFieldModel {
  StepKind kind = StepKind::HeatTransfer;
  ScalarFieldResult::Kind field = ScalarFieldResult::Kind::Temperature;
  int dof = 11;                               // the deck's dof number: 11 or 9
  std::vector<const TElement*> formulation;   // per element
  std::vector<Eigen::Vector3d> conductivity;  // per element: diagonal k11, k22, k33
  std::vector<int> rule_of_element;           // index into `rules`
  std::vector<std::pair<const TElement*, IntegrationRule>> rules;  // one per element type
  std::vector<Extrapolation> extrapolations;                       // parallel to `rules`
  std::vector<int> ip_offset;        // integration points per element, CSR
  std::vector<int> unknown_of_node;  // -1 for nodes no element uses
  std::vector<int> node_of_unknown;

  int unknowns() const { return static_cast<int>(node_of_unknown.size()); }
  const IntegrationRule& rule(int e) const { return rules[rule_of_element[e]].second; }
};

// Checks the deck for a scalar-field analysis and prepares it. Throws InputError for: steps of
// different kinds (mechanical and scalar, or heat and electric), contact pairs, *EQUATION,
// *TRANSFORM or initial temperatures in such a deck, unknown element types, elements without a
// section, materials without the conductivity, rules too small for a scalar field (C3D8R).
ScalarFieldModel prepare_scalar_field_model(const Model& model, const ElementRegistry& registry);

struct FaceFlux {
  int element = 0;
  int face = 0;  // 0-based
  double flux = 0.0;
};

struct ScalarStepConditions {
  std::map<int, double> prescribed;   // unknown -> value
  std::vector<double> nodal_flow;     // per unknown: *CFLUX / *CECUR
  std::vector<FaceFlux> face_fluxes;  // *DFLUX
};

// The conditions of every step; InputError for values on nodes no element uses.
std::vector<ScalarStepConditions> accumulate_scalar_conditions(const Model& model,
                                                               const ScalarFieldModel& prepared);

// InputError when a connected part of the mesh has no prescribed value: its steady field would be
// determined only up to a constant (a singular conductance).
void check_every_part_prescribed(const Model& model, const ScalarFieldModel& prepared,
                                 const ScalarStepConditions& conditions, const Step& step);

}  // namespace styk::solver_detail
