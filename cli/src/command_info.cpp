#include <algorithm>
#include <iostream>
#include <map>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "registry_setup.hpp"
#include "styk/core/beam_section.hpp"
#include "styk/inp/reader.hpp"

namespace styk::cli {
namespace {

int count_active_nodes(const Model& model) {
  std::vector<char> used(model.node_count(), 0);
  for (int idx : model.connectivity) used[idx] = 1;
  int n = 0;
  for (char u : used) n += u;
  return n;
}

// Mechanical dofs before constraints: per used node the most any of its elements carries (3
// displacements; 6 with the rotations of beams), and how many nodes carry rotations.
std::pair<long long, int> count_dofs(const Model& model, const ElementRegistry& registry) {
  std::vector<int> per_node(model.node_count(), 0);
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement* f = registry.find(model.elements[e].type);
    const int dofs = f != nullptr ? f->node_dofs() : 3;
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k)
      per_node[nodes[k]] = std::max(per_node[nodes[k]], dofs);
  }
  long long total = 0;
  int rotating = 0;
  for (int d : per_node) total += d, rotating += d > 3 ? 1 : 0;
  return {total, rotating};
}

const char* solver_name(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::Cholmod:
      return "direct (CHOLMOD)";
    case LinearSolverKind::Iterative:
      return "iterative (CG + AMG)";
    case LinearSolverKind::Automatic:
      break;
  }
  return "automatic";
}

}  // namespace

int info_command(const InfoArgs& args) {
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  const Model model = read_inp(args.deck, registry);

  std::map<std::string, int> by_type;
  for (const Element& e : model.elements) ++by_type[e.type];
  const int active = count_active_nodes(model);

  fmt::print("model:     {}\n", model.source);
  if (!model.heading.empty()) fmt::print("heading:   {}\n", model.heading);
  fmt::print("nodes:     {} ({} used by elements)\n", model.node_count(), active);
  fmt::print("elements:  {}\n", model.element_count());
  for (const auto& [type, n] : by_type) fmt::print("  {:<8} {}\n", type, n);
  bool scalar = false;  // steady heat / electric potential: one unknown per node
  for (const Step& step : model.steps) scalar |= step.kind != StepKind::Static;
  if (scalar)
    fmt::print("dofs:      {} (1 per used node: {}, before boundary conditions)\n", active,
               model.steps.front().kind == StepKind::HeatTransfer ? "temperature" : "potential");
  else if (const auto [dofs, rotating] = count_dofs(model, registry); rotating == 0)
    fmt::print("dofs:      {} (3 per used node, before constraints)\n", dofs);
  else
    fmt::print(
        "dofs:      {} (3 per used node, 6 at the {} nodes of beams, before "
        "constraints)\n",
        dofs, rotating);
  fmt::print("node sets: {}\n", model.nsets.size());
  for (const auto& [name, set] : model.nsets)
    fmt::print("  {:<24} {} nodes\n", name, set.nodes.size());
  fmt::print("element sets: {}\n", model.elsets.size());
  for (const auto& [name, set] : model.elsets)
    fmt::print("  {:<24} {} elements\n", name, set.elements.size());
  fmt::print("materials: {}\n", model.materials.size());
  for (const Material& m : model.materials) {
    // A constant isotropic law prints its constants; a type or a table over temperature says so.
    static const char* const kElastic[] = {"isotropic", "orthotropic", "engineering constants",
                                           "anisotropic"};
    const std::string elastic =
        m.young ? fmt::format("E = {}, nu = {}", *m.young, m.poisson.value_or(0.0))
                : fmt::format("{} elasticity, {} temperature(s)",
                              kElastic[static_cast<int>(m.elastic_type)], m.elastic_table.size());
    const std::string expansion =
        m.expansion ? fmt::format(", alpha = {}", *m.expansion)
        : !m.expansion_table.empty()
            ? fmt::format(", expansion over {} temperature(s)", m.expansion_table.size())
            : std::string();
    fmt::print("  {:<24} {}{}\n", m.name, elastic, expansion);
  }
  fmt::print("sections:  {}\n", model.sections.size());
  for (const Section& s : model.sections) {
    if (!s.beam) {
      fmt::print("  elset {:<18} material {}\n", s.elset, s.material);
      continue;
    }
    std::string dimensions;
    for (double d : s.beam->dimensions)
      dimensions += (dimensions.empty() ? "" : ", ") + fmt::format("{}", d);
    fmt::print("  elset {:<18} material {}, beam {} {}, {} integration\n", s.elset, s.material,
               beam_shape_name(s.beam->shape), dimensions,
               s.beam->integration == BeamIntegration::Full ? "full" : "reduced");
  }
  fmt::print("boundary conditions outside steps: {}\n", model.boundaries.size());
  fmt::print("steps:     {}\n", model.steps.size());
  for (std::size_t k = 0; k < model.steps.size(); ++k) {
    const Step& s = model.steps[k];
    if (s.kind != StepKind::Static) {
      fmt::print(
          "  step {} {}: {} (steady), time {}; {} boundary, {} flow, {} face flux, {} output "
          "requests\n",
          k + 1, s.name, s.kind == StepKind::HeatTransfer ? "heat transfer" : "electric",
          s.procedure.total_time, s.boundaries.size(), s.cfluxes.size(), s.dfluxes.size(),
          s.outputs.size());
      continue;
    }
    fmt::print(
        "  step {} {}: static, time {}, solver {}; {} boundary, {} cload, {} dload, {} output "
        "requests\n",
        k + 1, s.name, s.procedure.total_time, solver_name(s.procedure.solver), s.boundaries.size(),
        s.cloads.size(), s.dloads.size(), s.outputs.size());
  }
  return kOk;
}

}  // namespace styk::cli
