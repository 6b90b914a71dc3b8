#include "styk/contact/penetration.hpp"

#include <algorithm>
#include <map>

#include "styk/core/cyclic_symmetry.hpp"

namespace styk::contact {
namespace {

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Slave node -> constraint of pair `pair`; a cyclic copy of a node (joined with its image, see
// constraints.cpp) maps to the image's constraint.
std::map<int, int> constraint_of_node(const std::vector<ContactConstraint>& constraints, int pair,
                                      const std::vector<ResolvedCyclicSymmetry>& cyclic) {
  std::map<int, int> out;
  for (std::size_t j = 0; j < constraints.size(); ++j)
    if (constraints[j].pair == pair) out[constraints[j].slave] = static_cast<int>(j);
  for (const ResolvedCyclicSymmetry& tie : cyclic)
    for (const CyclicNodePair& p : tie.pairs) {
      const auto image = out.find(p.master);
      if (image != out.end() && out.count(p.slave) == 0) out[p.slave] = image->second;
    }
  return out;
}

}  // namespace

PenetrationLayout layout_penetrations(const Model& model, const ElementRegistry& registry,
                                      const std::vector<ContactConstraint>& constraints,
                                      const std::vector<const PressurePenetration*>& definitions) {
  PenetrationLayout out;
  if (definitions.empty()) return out;
  const std::size_t m = constraints.size();
  out.neighbours.assign(m, {});
  out.entry.assign(m, 0);
  const std::vector<ResolvedCyclicSymmetry> cyclic = resolve_cyclic_symmetries(model, registry);
  for (const PressurePenetration* pp : definitions) {
    const auto pair = std::find_if(
        model.contact_pairs.begin(), model.contact_pairs.end(),
        [&](const ContactPair& p) { return p.slave == pp->slave && p.master == pp->master; });
    if (pair == model.contact_pairs.end())
      throw InputError(pp->where, "*PRESSURE PENETRATION: no *CONTACT PAIR has slave " + pp->slave +
                                      " and master " + pp->master);
    const int p = static_cast<int>(pair - model.contact_pairs.begin());
    const Surface& slave = model.surfaces.at(pp->slave);
    if (slave.kind != Surface::Kind::ElementFaces)
      throw InputError(pp->where, "*PRESSURE PENETRATION: slave surface " + pp->slave +
                                      " is a node surface; the fluid's path is traced over the "
                                      "slave's element faces");
    const std::map<int, int> of_node = constraint_of_node(constraints, p, cyclic);
    PenetrationZone zone;
    zone.definition = pp;
    zone.label = pp->slave + "/" + pp->master;
    zone.leak.assign(m, 0);
    for (const auto& entry : of_node) zone.constraints.push_back(entry.second);
    sort_unique(zone.constraints);
    // Neighbours: the constrained nodes of every slave face, pairwise.
    for (const SurfaceFace& f : slave.faces) {
      const TElement* element = registry.find(model.elements[f.element].type);
      if (element == nullptr) continue;  // the constraints' own build names it
      const int* nodes = model.element_nodes(f.element);
      std::vector<int> on_face;
      for (int local : element->faces().at(f.face - 1).nodes) {
        const auto it = of_node.find(nodes[local]);
        if (it != of_node.end()) on_face.push_back(it->second);
      }
      for (int a : on_face)
        for (int b : on_face)
          if (a != b) out.neighbours[a].push_back(b);
    }
    int entries = 0;
    for (int node : pp->exposed_slave) {
      const auto it = of_node.find(node);
      if (it == of_node.end()) continue;
      out.entry[it->second] = 1;
      ++entries;
    }
    if (entries == 0)
      throw InputError(pp->where, "*PRESSURE PENETRATION " + zone.label +
                                      ": none of the exposed slave nodes is a constrained contact "
                                      "node (are they beyond the master surface?)");
    if (!pp->leak_nset.empty()) {
      zone.has_leak_set = true;
      for (int node : model.nsets.at(pp->leak_nset).nodes) {
        const auto it = of_node.find(node);
        if (it != of_node.end()) zone.leak[it->second] = 1;
      }
    }
    out.zones.push_back(std::move(zone));
  }
  for (std::vector<int>& list : out.neighbours) sort_unique(list);
  return out;
}

FluidPenetration fluid_loads(const PenetrationLayout& layout,
                             const std::vector<ContactConstraint>& constraints,
                             const std::vector<double>& pressures) {
  FluidPenetration fluid;
  if (layout.zones.empty()) return fluid;
  const std::size_t m = constraints.size();
  fluid.force.assign(m, 0.0);
  fluid.critical.assign(m, 0.0);
  fluid.neighbours = layout.neighbours;
  fluid.entry = layout.entry;
  for (std::size_t z = 0; z < layout.zones.size(); ++z) {
    const PenetrationZone& zone = layout.zones[z];
    for (int j : zone.constraints) {
      fluid.force[j] = std::max(pressures[z], 0.0) * constraints[j].area;
      fluid.critical[j] = zone.definition->critical * constraints[j].area;
    }
  }
  return fluid;
}

bool leaks(const PenetrationZone& zone, const ContactState& state) {
  if (!zone.has_leak_set) return false;
  for (int j : zone.constraints)
    if (zone.leak[j] && state.nodes[j].penetrated) return true;
  return false;
}

int penetrated_count(const PenetrationZone& zone, const ContactState& state) {
  int count = 0;
  for (int j : zone.constraints) count += state.nodes[j].penetrated ? 1 : 0;
  return count;
}

}  // namespace styk::contact
