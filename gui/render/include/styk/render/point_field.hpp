// Values at the integration points (SPEC §5: "stresses at Gauss points"): what the solver stored
// per point, before any extrapolation or averaging, and where the points lie. The renderer draws
// them as dots coloured by value (`styk render --ip-values`); the desktop program's probe lists
// them for the element under the cursor.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk::render {

struct PointField {
  std::string name;            // canonical, e.g. "S.mises"
  std::vector<double> values;  // per integration point
  std::vector<int> offset;     // element e owns values[offset[e] .. offset[e + 1] - 1]
  int count(int element) const { return offset[element + 1] - offset[element]; }
};

// The integration-point values of field `name`: S.* and E.* (the components, Mises, Tresca and
// principal values of IncrementResult::S / E) and HFL.* / ECD.* (the flux of a heat or
// electric-potential increment). InputError for a field that has no values at the points (U, RF,
// contact output, NT, ...) naming those that have, and for an increment that stored none.
PointField evaluate_point_field(const Model& model, const IncrementResult& increment,
                                const std::string& name);

// Natural coordinates of a formulation's integration points: its full rule (RuleKind::Full, the
// rule the solver stores values at).
std::vector<Vec3> point_coordinates(const TElement& formulation);
// InputError when the values stored for `element` are not one per point of its rule.
void check_point_count(const Model& model, const PointField& field, int element,
                       std::size_t rule_points);

// One integration point of an element, for the probe: its number (1-based, the rule's order, as
// CalculiX numbers them), natural coordinates, position (undeformed) and value.
struct PointValue {
  int number = 0;
  Vec3 natural{};
  Vec3 position{};
  double value = 0.0;
};
std::vector<PointValue> element_point_values(const Model& model, const TElement& formulation,
                                             const PointField& field, int element);

// Where a natural point of an element lies, given where its nodes are drawn.
Vec3 map_natural_point(const TElement& formulation, const Vec3& xi,
                       const std::vector<Vec3>& node_positions);

}  // namespace styk::render
