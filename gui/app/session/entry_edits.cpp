#include "session/entry_edits.hpp"

#include <algorithm>
#include <utility>

#include "session/input_checks.hpp"
#include "session/load_groups.hpp"
#include "session/orientation_input.hpp"

namespace styk::gui {
namespace {

template <typename T>
void check_index(const std::vector<T>& list, int index, const std::string& what) {
  if (index < 0 || index >= static_cast<int>(list.size()))
    refuse("no " + what + " " + std::to_string(index + 1) + " in the model");
}

// Erases list[index] (a member of Model chosen by `of`) and puts it back on undo.
template <typename T, typename Of>
std::unique_ptr<Command> erase_at(const Model& model, int index, std::string text, Of of) {
  const T item = of(model).at(index);
  return make_model_edit(
      std::move(text), [index, of](Model& m) { of(m).erase(of(m).begin() + index); },
      [index, item, of](Model& m) { of(m).insert(of(m).begin() + index, item); });
}

// Empties a list and gives it back on undo.
template <typename T, typename Of>
std::unique_ptr<Command> clear_list(const Model& model, std::string text, Of of) {
  const std::vector<T> items = of(model);
  if (items.empty()) refuse("there is nothing to delete");
  return make_model_edit(
      std::move(text), [of](Model& m) { of(m).clear(); }, [items, of](Model& m) { of(m) = items; });
}

std::unique_ptr<Command> delete_section(const Model& model, int index) {
  check_index(model.sections, index, "section");
  std::vector<int> members;
  for (int e = 0; e < model.element_count(); ++e)
    if (model.elements[e].section == index) members.push_back(e);
  const Section section = model.sections[index];
  return make_model_edit(
      "Delete section on " + section.elset,
      [index](Model& m) {
        for (Element& e : m.elements)
          if (e.section == index)
            e.section = -1;
          else if (e.section > index)
            --e.section;
        m.sections.erase(m.sections.begin() + index);
      },
      [index, section, members](Model& m) {
        for (Element& e : m.elements)
          if (e.section >= index) ++e.section;
        m.sections.insert(m.sections.begin() + index, section);
        for (int e : members) m.elements[e].section = index;
      });
}

std::unique_ptr<Command> delete_contact_pair(const Model& model, int index) {
  check_index(model.contact_pairs, index, "contact pair");
  const ContactPair pair = model.contact_pairs[index];
  int users = 0;
  for (const ContactPair& p : model.contact_pairs) users += p.interaction == pair.interaction;
  const auto it = model.surface_interactions.find(pair.interaction);
  const bool drop_interaction = users == 1 && it != model.surface_interactions.end();
  const SurfaceInteraction interaction = drop_interaction ? it->second : SurfaceInteraction{};
  return make_model_edit(
      "Delete contact " + pair.slave + " / " + pair.master,
      [index, drop_interaction, name = pair.interaction](Model& m) {
        m.contact_pairs.erase(m.contact_pairs.begin() + index);
        if (drop_interaction) m.surface_interactions.erase(name);
      },
      [index, pair, drop_interaction, interaction](Model& m) {
        m.contact_pairs.insert(m.contact_pairs.begin() + index, pair);
        if (drop_interaction) m.surface_interactions[interaction.name] = interaction;
      });
}

template <typename Map>
std::unique_ptr<Command> erase_named(const Model& model, const std::string& name,
                                     const std::string& what, Map Model::*member) {
  const auto it = (model.*member).find(name);
  if (it == (model.*member).end()) refuse("no " + what + " " + name + " in the model");
  const auto item = it->second;
  return make_model_edit(
      "Delete " + what + " " + name, [name, member](Model& m) { (m.*member).erase(name); },
      [name, item, member](Model& m) { (m.*member)[name] = item; });
}

}  // namespace

std::unique_ptr<Command> delete_command(const Model& model, const Entry& entry) {
  const int i = entry.index;
  const std::string& name = entry.name;
  if (entry.item >= 0 && is_load_list(entry.kind)) return group_delete_command(model, entry);
  switch (entry.kind) {
    case EntryKind::Material: {
      check_index(model.materials, i, "material");
      const std::string material = model.materials[i].name;
      for (const Section& s : model.sections)
        if (s.material == material)
          refuse("material " + material + " is used by the section on " + s.elset +
                 "; delete or change that section first");
      return erase_at<Material>(
          model, i, "Delete material " + material, [](auto& m) -> auto& { return m.materials; });
    }
    case EntryKind::Section:
      return delete_section(model, i);
    case EntryKind::Step:
      check_index(model.steps, i, "step");
      return erase_at<Step>(
          model, i, "Delete step " + model.steps[i].name, [](auto& m) -> auto& { return m.steps; });
    case EntryKind::ModelBoundaries:
      return clear_list<Boundary>(
          model, "Delete the boundary conditions of every step",
          [](auto& m) -> auto& { return m.boundaries; });
    case EntryKind::StepBoundaries:
      check_index(model.steps, i, "step");
      return clear_list<Boundary>(
          model, "Delete the boundary conditions of " + model.steps[i].name, [i](auto& m) -> auto& {
            return m.steps.at(i).boundaries;
          });
    case EntryKind::StepCloads:
      check_index(model.steps, i, "step");
      return clear_list<ConcentratedLoad>(
          model, "Delete the concentrated loads of " + model.steps[i].name, [i](auto& m) -> auto& {
            return m.steps.at(i).cloads;
          });
    case EntryKind::StepDloads:
      check_index(model.steps, i, "step");
      return clear_list<DistributedLoad>(
          model, "Delete the pressures of " + model.steps[i].name, [i](auto& m) -> auto& {
            return m.steps.at(i).dloads;
          });
    case EntryKind::StepTemperatures:
      check_index(model.steps, i, "step");
      return clear_list<NodalTemperature>(
          model, "Delete the temperatures of " + model.steps[i].name, [i](auto& m) -> auto& {
            return m.steps.at(i).temperatures;
          });
    case EntryKind::InitialTemperatures:
      return clear_list<NodalTemperature>(
          model, "Delete the initial temperatures",
          [](auto& m) -> auto& { return m.initial_temperatures; });
    case EntryKind::StepFluxes:
      check_index(model.steps, i, "step");
      return clear_list<ConcentratedLoad>(
          model, "Delete the nodal fluxes of " + model.steps[i].name, [i](auto& m) -> auto& {
            return m.steps.at(i).cfluxes;
          });
    case EntryKind::StepDfluxes:
      check_index(model.steps, i, "step");
      return clear_list<DistributedLoad>(
          model, "Delete the face fluxes of " + model.steps[i].name, [i](auto& m) -> auto& {
            return m.steps.at(i).dfluxes;
          });
    case EntryKind::ContactPair:
      return delete_contact_pair(model, i);
    case EntryKind::Equation:
      check_index(model.equations, i, "equation");
      return erase_at<Equation>(
          model, i, "Delete equation " + std::to_string(i + 1),
          [](auto& m) -> auto& { return m.equations; });
    case EntryKind::Transform:
      check_index(model.transforms, i, "transform");
      return erase_at<Transform>(
          model, i, "Delete transform on " + model.transforms[i].nset,
          [](auto& m) -> auto& { return m.transforms; });
    case EntryKind::NodeSet:
      for (const Transform& t : model.transforms)
        if (t.nset == name)
          refuse("node set " + name + " is used by a *TRANSFORM; delete the transform first");
      return erase_named(model, name, "node set", &Model::nsets);
    case EntryKind::ElementSet:
      for (const Section& s : model.sections)
        if (s.elset == name)
          refuse("element set " + name + " has a section (material " + s.material +
                 "); delete the section first");
      return erase_named(model, name, "element set", &Model::elsets);
    case EntryKind::Surface:
      for (const ContactPair& p : model.contact_pairs)
        if (p.slave == name || p.master == name)
          refuse("surface " + name + " is used by the contact pair " + p.slave + " / " + p.master +
                 "; delete the pair first");
      return erase_named(model, name, "surface", &Model::surfaces);
    case EntryKind::Orientation:
      if (const std::string user = orientation_user(model, name); !user.empty()) {
        std::string pair;
        for (const ContactPair& p : model.contact_pairs)
          if (p.interaction == user) pair = " (contact pair " + p.slave + " / " + p.master + ")";
        refuse("orientation " + name +
               " gives the slip directions of the anisotropic friction of "
               "interaction " +
               user + pair + "; change that friction first");
      }
      return erase_named(model, name, "orientation", &Model::orientations);
  }
  refuse("this entry cannot be deleted");
}

MaterialInput material_input_of(const Model& model, int material) {
  check_index(model.materials, material, "material");
  const Material& m = model.materials[material];
  MaterialInput in{m.name,
                   m.young.value_or(0.0),
                   m.poisson.value_or(0.0),
                   m.density.value_or(0.0),
                   m.expansion.value_or(0.0),
                   {},
                   {}};
  const auto values = [](const std::optional<std::array<double, 3>>& k) {
    if (!k) return std::vector<double>{};
    if ((*k)[0] == (*k)[1] && (*k)[1] == (*k)[2]) return std::vector<double>{(*k)[0]};
    return std::vector<double>{k->begin(), k->end()};
  };
  in.conductivity = values(m.conductivity);
  in.electrical_conductivity = values(m.electrical_conductivity);
  return in;
}

std::unique_ptr<Command> material_edit_command(const Model& model, int material,
                                               const MaterialInput& input) {
  check_index(model.materials, material, "material");
  Material after = checked_material(model, input, material);
  const Material before = model.materials[material];
  after.expansion_reference = before.expansion_reference;
  const auto rename = [material](Model& m, const Material& now) {
    const std::string old = m.materials[material].name;
    for (Section& s : m.sections)
      if (s.material == old) s.material = now.name;
    m.materials[material] = now;
  };
  return make_model_edit(
      "Edit material " + before.name, [rename, after](Model& m) { rename(m, after); },
      [rename, before](Model& m) { rename(m, before); });
}

std::unique_ptr<Command> section_edit_command(const Model& model, int section,
                                              const std::string& material) {
  check_index(model.sections, section, "section");
  const int index = model.material_index(to_upper(material));
  if (material.empty()) refuse("choose a material");
  if (index < 0) refuse("no material " + to_upper(material) + " in the model");
  const Section before = model.sections[section];
  Section after = before;
  after.material = to_upper(material);
  after.material_index = index;
  return make_model_edit(
      "Edit section on " + before.elset,
      [section, after](Model& m) { m.sections[section] = after; },
      [section, before](Model& m) { m.sections[section] = before; });
}

std::unique_ptr<Command> step_edit_command(const Model& model, int step, const StepInput& input) {
  check_index(model.steps, step, "step");
  // The step's own name is not "in use": check against a model without it.
  Model others;
  for (int s = 0; s < static_cast<int>(model.steps.size()); ++s)
    if (s != step) others.steps.push_back(model.steps[s]);
  const std::unique_ptr<Command> checked = step_command(others, input);
  const Step before = model.steps[step];
  if (input.kind != before.kind) {
    // What the step holds must fit its new kind (the dialogs refuse it for a new entry too).
    const bool loads_fit =
        std::all_of(before.boundaries.begin(), before.boundaries.end(),
                    [&](const Boundary& b) { return dof_fits_step(b.dof, input.kind); }) &&
        std::all_of(before.cfluxes.begin(), before.cfluxes.end(),
                    [&](const ConcentratedLoad& c) { return dof_fits_step(c.dof, input.kind); }) &&
        std::all_of(model.boundaries.begin(), model.boundaries.end(),
                    [&](const Boundary& b) { return dof_fits_step(b.dof, input.kind); });
    const bool mechanical_loads =
        !before.cloads.empty() || !before.dloads.empty() || !before.temperatures.empty();
    const bool flux_loads = !before.dfluxes.empty() && input.kind != StepKind::HeatTransfer;
    if (!loads_fit || (input.kind != StepKind::Static && mechanical_loads) || flux_loads)
      refuse("step " + before.name + " holds boundary conditions or loads of a " +
             step_kind_name(before.kind) +
             " step (or every step's boundary conditions do not "
             "fit a " +
             step_kind_name(input.kind) + " step); delete them first");
  }
  Step after = before;
  after.kind = input.kind;
  after.name = input.name;
  after.procedure.initial_increment = input.initial_increment;
  after.procedure.total_time = input.total_time;
  return make_model_edit(
      "Edit step " + before.name, [step, after](Model& m) { m.steps[step] = after; },
      [step, before](Model& m) { m.steps[step] = before; });
}

}  // namespace styk::gui
