// The layout of the step's *PRESSURE PENETRATION definitions on the contact constraints
// (docs/contact.md, "Pressure penetration"): which constraints each fluid can reach, their
// neighbours over the slave faces, the entry nodes and the leak nodes; and the fluid loads of an
// increment (contact::FluidPenetration) at a given fluid pressure.
#pragma once

#include <string>
#include <vector>

#include "styk/contact/active_set.hpp"
#include "styk/contact/constraints.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::contact {

struct PenetrationZone {
  const PressurePenetration* definition = nullptr;
  std::string label;             // "SLAVE/MASTER" for messages
  std::vector<int> constraints;  // the constraints of the pair, sorted
  std::vector<char> leak;        // per constraint of the model: a LEAK= node of this zone
  bool has_leak_set = false;
};

struct PenetrationLayout {
  std::vector<PenetrationZone> zones;
  std::vector<std::vector<int>> neighbours;  // per constraint: constraints sharing a slave face
  std::vector<char> entry;                   // per constraint
};

// Lays out `definitions` (the step's, accumulated) on `constraints`. Throws InputError at a
// definition's line when its slave surface is a node surface (the fluid's path follows the slave
// faces) or none of its entry nodes is constrained.
PenetrationLayout layout_penetrations(const Model& model, const ElementRegistry& registry,
                                      const std::vector<ContactConstraint>& constraints,
                                      const std::vector<const PressurePenetration*>& definitions);

// The fluid loads of an increment: zone z at fluid pressure pressures[z] (its critical contact
// pressure from the definition), forces p A on every constraint of the zone.
FluidPenetration fluid_loads(const PenetrationLayout& layout,
                             const std::vector<ContactConstraint>& constraints,
                             const std::vector<double>& pressures);

// Whether the penetrated zone of `zone` reaches one of its leak nodes in `state`.
bool leaks(const PenetrationZone& zone, const ContactState& state);

// The number of constraints of `zone` in its penetrated zone.
int penetrated_count(const PenetrationZone& zone, const ContactState& state);

}  // namespace styk::contact
