#include "session/load_groups.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

#include "session/input_checks.hpp"
#include "session/load_groups_detail.hpp"

namespace styk::gui {
namespace {

using detail::group_at;
using detail::nodes_name;

struct Item {
  int node = 0;
  int dof = 0;
  double value = 0.0;
};

// The (node, dof, value) entries of the list an entry names.
std::vector<Item> items_of(const Model& model, const Entry& entry) {
  std::vector<Item> items;
  const auto step = [&]() -> const Step& {
    if (entry.index < 0 || entry.index >= static_cast<int>(model.steps.size()))
      refuse("no step " + std::to_string(entry.index + 1) + " in the model");
    return model.steps[entry.index];
  };
  const auto add_boundaries = [&](const std::vector<Boundary>& list) {
    for (const Boundary& b : list) items.push_back({b.node, b.dof, b.value});
  };
  const auto add_loads = [&](const std::vector<ConcentratedLoad>& list) {
    for (const ConcentratedLoad& c : list) items.push_back({c.node, c.dof, c.value});
  };
  const auto add_temperatures = [&](const std::vector<NodalTemperature>& list) {
    for (const NodalTemperature& t : list) items.push_back({t.node, 0, t.value});
  };
  switch (entry.kind) {
    case EntryKind::ModelBoundaries:
      add_boundaries(model.boundaries);
      break;
    case EntryKind::StepBoundaries:
      add_boundaries(step().boundaries);
      break;
    case EntryKind::StepCloads:
      add_loads(step().cloads);
      break;
    case EntryKind::StepFluxes:
      add_loads(step().cfluxes);
      break;
    case EntryKind::StepTemperatures:
      add_temperatures(step().temperatures);
      break;
    case EntryKind::InitialTemperatures:
      add_temperatures(model.initial_temperatures);
      break;
    default:
      refuse("this entry is not a list of nodal values");
  }
  return items;
}

// Splits `keys` (one run) into consecutive segments each equal to one candidate (name -> its
// sorted keys), with the fewest segments: [begin, end) and the candidate's name per segment.
// Empty when no split exists.
template <typename Key>
std::vector<std::tuple<int, int, std::string>> split_into_sets(
    const std::vector<Key>& keys,
    const std::vector<std::pair<std::string, std::vector<Key>>>& sets) {
  const int n = static_cast<int>(keys.size());
  std::multimap<Key, int> by_first;  // candidates by their first key
  for (int s = 0; s < static_cast<int>(sets.size()); ++s)
    if (!sets[s].second.empty()) by_first.emplace(sets[s].second.front(), s);
  constexpr int kNone = 1 << 30;
  std::vector<int> fewest(n + 1, kNone), choice(n, -1);
  fewest[n] = 0;
  for (int i = n - 1; i >= 0; --i) {
    const auto [from, to] = by_first.equal_range(keys[i]);
    for (auto it = from; it != to; ++it) {
      const std::vector<Key>& set = sets[it->second].second;
      const int end = i + static_cast<int>(set.size());
      if (end > n || fewest[end] == kNone || fewest[end] + 1 >= fewest[i]) continue;
      if (!std::equal(set.begin(), set.end(), keys.begin() + i)) continue;
      fewest[i] = fewest[end] + 1;
      choice[i] = it->second;
    }
  }
  std::vector<std::tuple<int, int, std::string>> segments;
  if (fewest[0] == kNone) return segments;
  for (int i = 0; i < n;) {
    const int end = i + static_cast<int>(sets[choice[i]].second.size());
    segments.emplace_back(i, end, sets[choice[i]].first);
    i = end;
  }
  return segments;
}

// The runs of a list as one dialog appends them: entries of one value, node after node in
// ascending order, each node with the same consecutive dofs. [begin, end) of each run.
std::vector<std::pair<int, int>> runs_of(const std::vector<Item>& items) {
  std::vector<std::pair<int, int>> runs;
  const int n = static_cast<int>(items.size());
  for (int begin = 0; begin < n;) {
    int width = 1;  // dofs per node: first..last of the first node
    while (begin + width < n && items[begin + width].node == items[begin].node &&
           items[begin + width].dof == items[begin].dof + width &&
           items[begin + width].value == items[begin].value)
      ++width;
    int end = begin + width;
    while (end + width <= n) {
      bool fits = items[end].node > items[end - 1].node;
      for (int k = 0; k < width && fits; ++k)
        fits = items[end + k].node == items[end].node &&
               items[end + k].dof == items[begin + k].dof &&
               items[end + k].value == items[begin].value;
      if (!fits) break;
      end += width;
    }
    runs.emplace_back(begin, end);
    begin = end;
  }
  return runs;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string detail::nodes_name(const std::string& nset, const NodeGroup& group) {
  if (!nset.empty()) return to_upper(nset);
  if (!group.nset.empty()) return group.nset;
  return std::to_string(group.nodes.size()) + " nodes";
}

bool is_load_list(EntryKind kind) {
  return kind == EntryKind::ModelBoundaries || kind == EntryKind::StepBoundaries ||
         kind == EntryKind::StepCloads || kind == EntryKind::StepDloads ||
         kind == EntryKind::StepTemperatures || kind == EntryKind::InitialTemperatures ||
         kind == EntryKind::StepFluxes || kind == EntryKind::StepDfluxes;
}

std::vector<NodeGroup> node_groups(const Model& model, const Entry& entry) {
  const std::vector<Item> items = items_of(model, entry);
  std::vector<std::pair<std::string, std::vector<int>>> sets;
  for (const auto& [name, set] : model.nsets) sets.emplace_back(name, set.nodes);
  std::vector<NodeGroup> groups;
  for (const auto& [begin, end] : runs_of(items)) {
    int width = 1;
    while (begin + width < end && items[begin + width].node == items[begin].node) ++width;
    std::vector<int> nodes;
    for (int i = begin; i < end; i += width) nodes.push_back(items[i].node);
    // Several dialogs in a row with the same value and dofs: split the run into the node sets
    // they were given (one group of "N nodes" when the nodes form no sets).
    std::vector<std::tuple<int, int, std::string>> segments = split_into_sets(nodes, sets);
    if (segments.empty()) segments.emplace_back(0, static_cast<int>(nodes.size()), "");
    for (const auto& [first, last, name] : segments) {
      NodeGroup g;
      g.nodes.assign(nodes.begin() + first, nodes.begin() + last);
      g.first_dof = items[begin].dof;
      g.last_dof = items[begin + width - 1].dof;
      g.value = items[begin].value;
      g.nset = name;
      for (int p = begin + first * width; p < begin + last * width; ++p) g.positions.push_back(p);
      groups.push_back(std::move(g));
    }
  }
  return groups;
}

std::vector<FaceGroup> face_groups(const Model& model, const Entry& entry) {
  if (entry.kind != EntryKind::StepDloads && entry.kind != EntryKind::StepDfluxes)
    refuse("this entry is not a list of pressures or face fluxes");
  if (entry.index < 0 || entry.index >= static_cast<int>(model.steps.size()))
    refuse("no step " + std::to_string(entry.index + 1) + " in the model");
  const Step& step = model.steps[entry.index];
  const std::vector<DistributedLoad>& list =
      entry.kind == EntryKind::StepDloads ? step.dloads : step.dfluxes;
  // Faces as (element, face) keys, so runs and sets compare with <.
  using Key = std::pair<int, int>;
  std::vector<std::pair<std::string, std::vector<Key>>> sets;
  for (const auto& [name, s] : model.surfaces) {
    std::vector<Key> keys;
    for (const SurfaceFace& f : s.faces) keys.emplace_back(f.element, f.face);
    std::sort(keys.begin(), keys.end());
    sets.emplace_back(name, std::move(keys));
  }
  const std::size_t surfaces = sets.size();
  for (const auto& [name, set] : model.elsets)
    for (int face = 1; face <= 6; ++face) {
      std::vector<Key> keys;
      for (int e : set.elements) keys.emplace_back(e, face);
      sets.emplace_back(name + " S" + std::to_string(face), std::move(keys));
    }
  std::vector<FaceGroup> groups;
  const int n = static_cast<int>(list.size());
  for (int begin = 0; begin < n;) {
    int end = begin + 1;
    while (end < n && list[end].magnitude == list[begin].magnitude &&
           Key(list[end].element, list[end].face) > Key(list[end - 1].element, list[end - 1].face))
      ++end;
    std::vector<Key> keys;
    for (int i = begin; i < end; ++i) keys.emplace_back(list[i].element, list[i].face);
    std::vector<std::tuple<int, int, std::string>> segments = split_into_sets(keys, sets);
    if (segments.empty()) segments.emplace_back(0, end - begin, "");
    for (const auto& [first, last, name] : segments) {
      FaceGroup g;
      for (int i = first; i < last; ++i) g.faces.push_back({keys[i].first, keys[i].second});
      g.magnitude = list[begin].magnitude;
      const bool surface = std::any_of(sets.begin(), sets.begin() + surfaces,
                                       [&](const auto& s) { return s.first == name; });
      if (surface) {
        g.surface = name;
      } else if (!name.empty()) {  // "ELSET Sf"
        g.elset = name.substr(0, name.rfind(' '));
        g.face = g.faces.front().face;
      }
      for (int p = begin + first; p < begin + last; ++p) g.positions.push_back(p);
      groups.push_back(std::move(g));
    }
    begin = end;
  }
  return groups;
}

std::vector<std::string> group_labels(const Model& model, const Entry& entry) {
  std::vector<std::string> labels;
  if (entry.kind == EntryKind::StepDloads || entry.kind == EntryKind::StepDfluxes) {
    const char* what = entry.kind == EntryKind::StepDloads ? ": pressure " : ": flux ";
    for (const FaceGroup& g : face_groups(model, entry)) {
      const std::string where = !g.surface.empty() ? g.surface
                                : !g.elset.empty() ? g.elset + " S" + std::to_string(g.face)
                                                   : std::to_string(g.faces.size()) + " faces";
      labels.push_back(where + what + number(g.magnitude));
    }
    return labels;
  }
  for (const NodeGroup& g : node_groups(model, entry)) {
    std::string what;
    if (g.first_dof == 0)
      what = "T = ";
    else if (g.first_dof == g.last_dof)
      what = "dof " + std::to_string(g.first_dof) + " = ";
    else
      what = "dofs " + std::to_string(g.first_dof) + "-" + std::to_string(g.last_dof) + " = ";
    labels.push_back(nodes_name({}, g) + ": " + what + number(g.value));
  }
  return labels;
}

BoundaryInput boundary_input_of(const Model& model, const Entry& entry) {
  const NodeGroup g = group_at(node_groups(model, entry), entry);
  return {g.nset, g.first_dof, g.last_dof, g.value,
          entry.kind == EntryKind::ModelBoundaries ? -1 : entry.index};
}

CloadInput cload_input_of(const Model& model, const Entry& entry) {
  const NodeGroup g = group_at(node_groups(model, entry), entry);
  return {g.nset, g.first_dof, g.value, false, entry.index};
}

PressureInput pressure_input_of(const Model& model, const Entry& entry) {
  const FaceGroup g = group_at(face_groups(model, entry), entry);
  return {g.surface, g.elset, g.face > 0 ? g.face : 1, g.magnitude, entry.index};
}

FluxInput flux_input_of(const Model& model, const Entry& entry) {
  if (entry.kind != EntryKind::StepDfluxes) refuse("this entry is not a list of face fluxes");
  return pressure_input_of(model, entry);  // the same fields, found the same way
}

TemperatureInput temperature_input_of(const Model& model, const Entry& entry) {
  const NodeGroup g = group_at(node_groups(model, entry), entry);
  return {g.nset, g.value, entry.kind == EntryKind::InitialTemperatures ? -1 : entry.index};
}

}  // namespace styk::gui
