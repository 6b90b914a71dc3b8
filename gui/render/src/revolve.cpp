#include "styk/render/revolve.hpp"

#include <cmath>
#include <map>

#include "styk/core/diagnostics.hpp"

namespace styk::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Local nodes of a sector brick as (section local node, ring: 0 lower, 1 middle, 2 upper), in
// C3D8 and C3D20 numbering: corners below, corners above, then (C3D20) the mid-edge nodes below
// and above and the corners on the middle ring (the vertical mid-edge nodes).
std::vector<std::array<int, 2>> sector_layout(int section_nodes) {
  std::vector<std::array<int, 2>> out;
  for (int ring : {0, 2})
    for (int k = 0; k < 4; ++k) out.push_back({k, ring});
  if (section_nodes == 8) {
    for (int ring : {0, 2})
      for (int k = 4; k < 8; ++k) out.push_back({k, ring});
    for (int k = 0; k < 4; ++k) out.push_back({k, 1});
  }
  return out;
}

}  // namespace

RevolvedModel revolve_axisymmetric(const Model& model, const ElementRegistry& registry,
                                   const IncrementResult* increment, double degrees, int segments) {
  if (!(degrees > 0.0 && degrees <= 360.0))
    throw InputError({},
                     "revolve angle " + std::to_string(degrees) + " degrees is outside (0, 360]");
  if (segments < 1) throw InputError({}, "revolve needs at least 1 segment");
  const bool closed = std::abs(degrees - 360.0) < 1e-9;
  const int positions = 2 * segments + 1;  // corner rings at even, middle rings at odd positions
  const double step = degrees * kPi / 180.0 / (2 * segments);
  double size = 0.0;
  for (const Vec3& x : model.coords) size = std::max({size, std::abs(x[0]), std::abs(x[1])});
  const double on_axis = 1e-9 * std::max(size, 1e-300);
  const bool with_u = increment && increment->U.size() == model.coords.size();

  RevolvedModel out;
  out.model.source = model.source;
  std::map<std::pair<int, int>, int> copy;  // (section node, ring position) -> revolved node
  const auto node_at = [&](int n, int position) {
    const double r = model.coords[n][0];
    // One node for every angle on the axis; the last ring of a full turn is the first.
    if (std::abs(r) < on_axis || (closed && position == positions - 1)) position = 0;
    const auto found = copy.find({n, position});
    if (found != copy.end()) return found->second;
    const double theta = step * position;
    const double c = std::cos(theta), s = std::sin(theta);
    const int index = out.model.add_node(static_cast<Id>(out.model.node_count() + 1),
                                         {r * c, model.coords[n][1], r * s}, {});
    out.source_node.push_back(n);
    if (with_u) {
      const Vec3& u = increment->U[n];
      out.U.push_back({u[0] * c, u[1], u[0] * s});
    }
    copy.emplace(std::make_pair(n, position), index);
    return index;
  };

  for (int e = 0; e < model.element_count(); ++e) {
    const Element& element = model.elements[e];
    const TElement* formulation = registry.find(element.type);
    if (!formulation || formulation->form() != ElementForm::Axisymmetric) continue;
    if (element.node_count != 4 && element.node_count != 8)
      throw InputError(element.where, "element " + std::to_string(element.id) + " (" +
                                          element.type +
                                          ") cannot be revolved: only 4- and 8-node "
                                          "quadrilateral sections are");
    const int* nodes = model.element_nodes(e);
    const std::vector<std::array<int, 2>> layout = sector_layout(element.node_count);
    for (int sector = 0; sector < segments; ++sector) {
      std::vector<int> brick;
      for (const auto& [local, ring] : layout) {
        brick.push_back(node_at(nodes[local], 2 * sector + ring));
        out.source_local.push_back(local);
      }
      out.model.add_element(static_cast<Id>(out.model.element_count() + 1),
                            element.node_count == 4 ? "C3D8" : "C3D20", brick, element.where);
      out.source_element.push_back(e);
    }
  }
  if (out.model.element_count() == 0)
    throw InputError({}, "the model has no axisymmetric elements (CAX4, CAX8, ...) to revolve");
  return out;
}

ScalarField revolve_field(const ScalarField& field, const Model& section,
                          const RevolvedModel& revolved) {
  ScalarField out = field;
  out.values.clear();
  out.defined.clear();
  switch (field.location) {
    case FieldLocation::Node:
      for (int n : revolved.source_node) {
        out.values.push_back(field.values[n]);
        if (!field.defined.empty()) out.defined.push_back(field.defined[n]);
      }
      break;
    case FieldLocation::Element:
      for (int e : revolved.source_element) out.values.push_back(field.values[e]);
      break;
    case FieldLocation::ElementNode:
      for (int e = 0; e < revolved.model.element_count(); ++e) {
        const Element& element = revolved.model.elements[e];
        const Element& source = section.elements[revolved.source_element[e]];
        for (int k = 0; k < element.node_count; ++k)
          out.values.push_back(
              field.values[source.first_node + revolved.source_local[element.first_node + k]]);
      }
      break;
  }
  return out;
}

}  // namespace styk::render
