// Editing and deleting one group of a per-node list (load_groups.hpp).
#include <algorithm>
#include <functional>

#include "session/input_checks.hpp"
#include "session/load_groups.hpp"
#include "session/load_groups_detail.hpp"

namespace styk::gui {
namespace {

using detail::group_at;
using detail::nodes_name;

template <typename T>
using ListOf = std::function<std::vector<T>&(Model&)>;

// The lists, for a Model or a const Model (M deduces the constness).
template <typename M>
auto& boundaries_in(M& m, int step) {
  return step < 0 ? m.boundaries : m.steps.at(step).boundaries;
}
template <typename M>
auto& loads_in(M& m, int step, int dof) {
  return !is_flux_dof(dof) ? m.steps.at(step).cloads : m.steps.at(step).cfluxes;
}
template <typename M>
auto& pressures_in(M& m, int step) {
  return m.steps.at(step).dloads;
}
template <typename M>
auto& face_fluxes_in(M& m, int step) {
  return m.steps.at(step).dfluxes;
}
template <typename M>
auto& temperatures_in(M& m, int step) {
  return step < 0 ? m.initial_temperatures : m.steps.at(step).temperatures;
}

ListOf<Boundary> boundary_list(int step) {
  return [step](Model& m) -> std::vector<Boundary>& { return boundaries_in(m, step); };
}
ListOf<ConcentratedLoad> load_list(int step, int dof) {
  return [step, dof](Model& m) -> std::vector<ConcentratedLoad>& { return loads_in(m, step, dof); };
}
ListOf<DistributedLoad> pressure_list(int step) {
  return [step](Model& m) -> std::vector<DistributedLoad>& { return pressures_in(m, step); };
}
ListOf<DistributedLoad> face_flux_list(int step) {
  return [step](Model& m) -> std::vector<DistributedLoad>& { return face_fluxes_in(m, step); };
}
ListOf<NodalTemperature> temperature_list(int step) {
  return [step](Model& m) -> std::vector<NodalTemperature>& { return temperatures_in(m, step); };
}

template <typename T>
std::vector<T> without(const std::vector<T>& list, const std::vector<int>& positions) {
  std::vector<T> kept;
  for (int i = 0; i < static_cast<int>(list.size()); ++i)
    if (!std::binary_search(positions.begin(), positions.end(), i)) kept.push_back(list[i]);
  return kept;
}

// Removes `positions` from the source list and puts `added` into the target list (at the first
// removed position when both are the same list, else at its end); undo restores both exactly.
// `source_now` / `target_now` are the two lists in the model as it is.
template <typename T>
std::unique_ptr<Command> replace_entries(std::string text, ListOf<T> source,
                                         const std::vector<T>& source_now,
                                         const std::vector<int>& positions, ListOf<T> target,
                                         const std::vector<T>& target_now,
                                         const std::vector<T>& added, bool same_list) {
  const std::vector<T> source_before = source_now;
  std::vector<T> source_after = without(source_before, positions);
  const std::vector<T> target_before = same_list ? source_before : target_now;
  std::vector<T> target_after = same_list ? source_after : target_before;
  const auto at = same_list && !positions.empty() ? target_after.begin() + positions.front()
                                                  : target_after.end();
  target_after.insert(at, added.begin(), added.end());
  if (same_list) source_after = target_after;
  return make_model_edit(
      std::move(text),
      [source, target, source_after, target_after, same_list](Model& mm) {
        source(mm) = source_after;
        if (!same_list) target(mm) = target_after;
      },
      [source, target, source_before, target_before, same_list](Model& mm) {
        if (!same_list) target(mm) = target_before;
        source(mm) = source_before;
      });
}

std::vector<int> nodes_for(const Model& model, const std::string& nset, const NodeGroup& group) {
  return nset.empty() ? group.nodes : existing_nset(model, nset).nodes;
}

}  // namespace

std::unique_ptr<Command> boundary_edit_command(const Model& model, const Entry& entry,
                                               const BoundaryInput& in) {
  const NodeGroup g = group_at(node_groups(model, entry), entry);
  const std::vector<int> nodes = nodes_for(model, in.nset, g);
  check_step(model, in.step, true);
  check_field_dof(model, in.step, in.first_dof, "first dof");
  check_field_dof(model, in.step, in.last_dof, "last dof");
  if (in.last_dof < in.first_dof) refuse("last dof must not be below the first dof");
  if (is_flux_dof(in.first_dof) && in.last_dof != in.first_dof)
    refuse("a temperature (11) or potential (9) is one dof: give it as first and last dof");
  check_finite(in.value, "value");
  std::vector<Boundary> added;
  for (int n : nodes)
    for (int dof = in.first_dof; dof <= in.last_dof; ++dof) added.push_back({n, dof, in.value, {}});
  const int from = entry.kind == EntryKind::ModelBoundaries ? -1 : entry.index;
  return replace_entries<Boundary>("Edit boundary condition on " + nodes_name(in.nset, g),
                                   boundary_list(from), boundaries_in(model, from), g.positions,
                                   boundary_list(in.step), boundaries_in(model, in.step), added,
                                   from == in.step);
}

std::unique_ptr<Command> cload_edit_command(const Model& model, const Entry& entry,
                                            const CloadInput& in) {
  const NodeGroup g = group_at(node_groups(model, entry), entry);
  const std::vector<int> nodes = nodes_for(model, in.nset, g);
  check_step(model, in.step, false);
  check_field_dof(model, in.step, in.dof, "direction");
  check_finite(in.value, "load");
  if (in.value == 0.0) refuse("a load of 0 does nothing; enter a value");
  const double each = in.split ? in.value / static_cast<double>(nodes.size()) : in.value;
  std::vector<ConcentratedLoad> added;
  for (int n : nodes) added.push_back({n, in.dof, each, {}});
  const bool was_flux = entry.kind == EntryKind::StepFluxes;
  const bool same = entry.index == in.step && was_flux == is_flux_dof(in.dof);
  const int from_dof = was_flux ? 11 : 1;
  return replace_entries<ConcentratedLoad>(
      "Edit load on " + nodes_name(in.nset, g), load_list(entry.index, from_dof),
      loads_in(model, entry.index, from_dof), g.positions, load_list(in.step, in.dof),
      loads_in(model, in.step, in.dof), added, same);
}

std::unique_ptr<Command> pressure_edit_command(const Model& model, const Entry& entry,
                                               const PressureInput& in) {
  const FaceGroup g = group_at(face_groups(model, entry), entry);
  check_step(model, in.step, false);
  if (model.steps[in.step].kind != StepKind::Static)
    refuse("step " + model.steps[in.step].name + " is a " +
           step_kind_name(model.steps[in.step].kind) +
           " step: a pressure belongs to a static step");
  check_finite(in.magnitude, "pressure");
  if (in.magnitude == 0.0) refuse("a pressure of 0 does nothing; enter a value");
  std::vector<SurfaceFace> faces = g.faces;
  std::string target = g.surface.empty() ? std::to_string(g.faces.size()) + " faces" : g.surface;
  if (!in.surface.empty()) {
    const Surface& s = existing_surface(model, in.surface);
    if (s.kind != Surface::Kind::ElementFaces) refuse("surface " + s.name + " holds no faces");
    faces = s.faces;
    target = s.name;
  } else if (!in.elset.empty()) {
    const ElementSet* set = model.find_elset(in.elset);
    if (!set) refuse("no element set " + to_upper(in.elset) + " in the model");
    if (set->elements.empty()) refuse("element set " + set->name + " is empty");
    if (in.face < 1 || in.face > 6) refuse("face must be 1..6 (S1..S6)");
    faces.clear();
    for (int e : set->elements) faces.push_back({e, in.face});
    target = set->name + " S" + std::to_string(in.face);
  }
  std::vector<DistributedLoad> added;
  for (const SurfaceFace& f : faces) added.push_back({f.element, f.face, in.magnitude, {}});
  return replace_entries<DistributedLoad>("Edit pressure on " + target, pressure_list(entry.index),
                                          pressures_in(model, entry.index), g.positions,
                                          pressure_list(in.step), pressures_in(model, in.step),
                                          added, entry.index == in.step);
}

std::unique_ptr<Command> flux_edit_command(const Model& model, const Entry& entry,
                                           const FluxInput& in) {
  if (entry.kind != EntryKind::StepDfluxes) refuse("this entry is not a list of face fluxes");
  const FaceGroup g = group_at(face_groups(model, entry), entry);
  check_flux_step(model, in.step);
  check_finite(in.magnitude, "flux");
  if (in.magnitude == 0.0) refuse("a flux of 0 does nothing; enter a value");
  // Empty surface and element set: the same faces as now.
  NamedFaces target{g.faces,
                    g.surface.empty() ? std::to_string(g.faces.size()) + " faces" : g.surface};
  if (!in.surface.empty() || !in.elset.empty())
    target = faces_of(model, in.surface, in.elset, in.face);
  std::vector<DistributedLoad> added;
  for (const SurfaceFace& f : target.faces) added.push_back({f.element, f.face, in.magnitude, {}});
  return replace_entries<DistributedLoad>(
      "Edit face flux into " + target.name, face_flux_list(entry.index),
      face_fluxes_in(model, entry.index), g.positions, face_flux_list(in.step),
      face_fluxes_in(model, in.step), added, entry.index == in.step);
}

std::unique_ptr<Command> temperature_edit_command(const Model& model, const Entry& entry,
                                                  const TemperatureInput& in) {
  const NodeGroup g = group_at(node_groups(model, entry), entry);
  const std::vector<int> nodes = nodes_for(model, in.nset, g);
  check_step(model, in.step, true);
  if (in.step >= 0 && model.steps[in.step].kind != StepKind::Static)
    refuse("step " + model.steps[in.step].name + " is a " +
           step_kind_name(model.steps[in.step].kind) +
           " step: *TEMPERATURE is a thermal load of a static step");
  check_finite(in.value, "temperature");
  const int from = entry.kind == EntryKind::InitialTemperatures ? -1 : entry.index;
  // A node given again takes the new value: drop the target's entries of these nodes first.
  std::vector<int> positions = g.positions;
  if (from == in.step) {
    const std::vector<NodalTemperature>& list = temperatures_in(model, from);
    for (int i = 0; i < static_cast<int>(list.size()); ++i)
      if (std::binary_search(nodes.begin(), nodes.end(), list[i].node)) positions.push_back(i);
    std::sort(positions.begin(), positions.end());
    positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
  }
  std::vector<NodalTemperature> added;
  for (int n : nodes) added.push_back({n, in.value, {}});
  const std::string text = "Edit temperature on " + nodes_name(in.nset, g);
  if (from == in.step)
    return replace_entries<NodalTemperature>(
        text, temperature_list(from), temperatures_in(model, from), positions,
        temperature_list(in.step), temperatures_in(model, in.step), added, true);
  // Another list: the target keeps its other nodes and takes these with the new value.
  std::vector<NodalTemperature> target = temperatures_in(model, in.step);
  target.erase(std::remove_if(target.begin(), target.end(),
                              [&](const NodalTemperature& t) {
                                return std::binary_search(nodes.begin(), nodes.end(), t.node);
                              }),
               target.end());
  target.insert(target.end(), added.begin(), added.end());
  const std::vector<NodalTemperature> source_before = temperatures_in(model, from);
  const std::vector<NodalTemperature> target_before = temperatures_in(model, in.step);
  const std::vector<NodalTemperature> source_after = without(source_before, positions);
  return make_model_edit(
      text,
      [from, to = in.step, source_after, target](Model& mm) {
        temperature_list(from)(mm) = source_after;
        temperature_list(to)(mm) = target;
      },
      [from, to = in.step, source_before, target_before](Model& mm) {
        temperature_list(to)(mm) = target_before;
        temperature_list(from)(mm) = source_before;
      });
}

std::unique_ptr<Command> group_delete_command(const Model& model, const Entry& entry) {
  const std::string text = "Delete " + group_labels(model, entry).at(std::max(0, entry.item));
  switch (entry.kind) {
    case EntryKind::StepDloads: {
      const FaceGroup g = group_at(face_groups(model, entry), entry);
      const auto& now = pressures_in(model, entry.index);
      return replace_entries<DistributedLoad>(text, pressure_list(entry.index), now, g.positions,
                                              pressure_list(entry.index), now, {}, true);
    }
    case EntryKind::StepDfluxes: {
      const FaceGroup g = group_at(face_groups(model, entry), entry);
      const auto& now = face_fluxes_in(model, entry.index);
      return replace_entries<DistributedLoad>(text, face_flux_list(entry.index), now, g.positions,
                                              face_flux_list(entry.index), now, {}, true);
    }
    case EntryKind::ModelBoundaries:
    case EntryKind::StepBoundaries: {
      const NodeGroup g = group_at(node_groups(model, entry), entry);
      const int step = entry.kind == EntryKind::ModelBoundaries ? -1 : entry.index;
      const auto& now = boundaries_in(model, step);
      return replace_entries<Boundary>(text, boundary_list(step), now, g.positions,
                                       boundary_list(step), now, {}, true);
    }
    case EntryKind::StepCloads:
    case EntryKind::StepFluxes: {
      const NodeGroup g = group_at(node_groups(model, entry), entry);
      const int dof = entry.kind == EntryKind::StepFluxes ? 11 : 1;
      const auto& now = loads_in(model, entry.index, dof);
      return replace_entries<ConcentratedLoad>(text, load_list(entry.index, dof), now, g.positions,
                                               load_list(entry.index, dof), now, {}, true);
    }
    case EntryKind::StepTemperatures:
    case EntryKind::InitialTemperatures: {
      const NodeGroup g = group_at(node_groups(model, entry), entry);
      const int step = entry.kind == EntryKind::InitialTemperatures ? -1 : entry.index;
      const auto& now = temperatures_in(model, step);
      return replace_entries<NodalTemperature>(text, temperature_list(step), now, g.positions,
                                               temperature_list(step), now, {}, true);
    }
    default:
      refuse("this entry is not a list of nodal values");
  }
}

}  // namespace styk::gui
