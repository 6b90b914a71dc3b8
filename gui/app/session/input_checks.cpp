#include "session/input_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace styk::gui {

void refuse(const std::string& message) { throw InputError({}, message); }

void check_name(const std::string& name, const std::string& what) {
  if (name.empty()) refuse(what + " needs a name");
  if (!std::isalpha(static_cast<unsigned char>(name[0])))
    refuse(what + " name '" + name + "' must start with a letter");
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      refuse(what + " name '" + name + "' may hold only letters, digits, _ - and .");
  if (name.size() > 80) refuse(what + " name '" + name + "' is longer than 80 characters");
}

const NodeSet& existing_nset(const Model& model, const std::string& name) {
  if (name.empty()) refuse("choose a node set");
  const NodeSet* set = model.find_nset(name);
  if (!set) refuse("no node set " + to_upper(name) + " in the model");
  if (set->nodes.empty()) refuse("node set " + set->name + " is empty");
  return *set;
}

const Surface& existing_surface(const Model& model, const std::string& name) {
  if (name.empty()) refuse("choose a surface");
  const auto it = model.surfaces.find(to_upper(name));
  if (it == model.surfaces.end()) refuse("no surface " + to_upper(name) + " in the model");
  const Surface& s = it->second;
  if ((s.kind == Surface::Kind::ElementFaces && s.faces.empty()) ||
      (s.kind == Surface::Kind::Nodes && s.nodes.empty()))
    refuse("surface " + s.name + " is empty");
  return s;
}

void check_step(const Model& model, int step, bool model_level_allowed) {
  if (step < 0 && model_level_allowed) return;
  if (model.steps.empty()) refuse("the model has no step: add a step first");
  if (step < 0 || step >= static_cast<int>(model.steps.size()))
    refuse("no step " + std::to_string(step + 1) + "; the model has " +
           std::to_string(model.steps.size()));
}

void check_dof(int dof, const std::string& label) {
  if (dof < 1 || dof > 3)
    refuse(label + " must be 1, 2 or 3 (x, y, z), not " + std::to_string(dof));
}

bool dof_fits_step(int dof, StepKind kind) {
  switch (kind) {
    case StepKind::Static:
      return dof >= 1 && dof <= 6;
    case StepKind::HeatTransfer:
      return dof == 11;
    case StepKind::ElectricConduction:
      return dof == 9;
  }
  return false;
}

std::string step_kind_name(StepKind kind) {
  switch (kind) {
    case StepKind::Static:
      return "static";
    case StepKind::HeatTransfer:
      return "heat transfer";
    case StepKind::ElectricConduction:
      return "electric conduction";
  }
  return "static";
}

StepKind step_kind_of(const std::string& name) {
  for (StepKind kind : {StepKind::Static, StepKind::HeatTransfer, StepKind::ElectricConduction})
    if (step_kind_name(kind) == name) return kind;
  refuse("step kind '" + name + "' is not one of static, heat transfer, electric conduction");
}

namespace {
std::string takes(StepKind kind) {
  switch (kind) {
    case StepKind::HeatTransfer:
      return "dof 11 (temperature)";
    case StepKind::ElectricConduction:
      return "dof 9 (electric potential)";
    case StepKind::Static:
      break;
  }
  return "dofs 1, 2, 3 (x, y, z) and 4, 5, 6 (rotations about x, y, z)";
}
}  // namespace

void check_field_dof(const Model& model, int step, int dof, const std::string& label) {
  if (!is_flux_dof(dof) && (dof < 1 || dof > 6))
    refuse(label +
           " must be 1, 2, 3 (x, y, z), 4, 5, 6 (rotations), 11 (temperature) or 9 (electric "
           "potential), not " +
           std::to_string(dof));
  for (int s = 0; s < static_cast<int>(model.steps.size()); ++s) {
    if (step >= 0 && s != step) continue;
    const Step& st = model.steps[s];
    if (!dof_fits_step(dof, st.kind))
      refuse(label + " " + std::to_string(dof) + " does not fit the " + step_kind_name(st.kind) +
             " step " + st.name + (step < 0 ? " (held in every step)" : "") + ": it takes " +
             takes(st.kind));
  }
}

bool is_flux_dof(int dof) { return dof == 9 || dof == 11; }

void check_finite(double value, const std::string& label) {
  if (!std::isfinite(value)) refuse(label + " must be a finite number");
}

void check_set_names_free(const Model& model, const std::string& name) {
  if (model.find_nset(name) || model.find_elset(name) || model.surfaces.count(name))
    refuse("a node set, element set or surface " + name + " exists already; choose another name");
}

void append_part(Model& model, const Model& part) {
  Id node_offset = 0, element_offset = 0;
  for (Id id : model.node_ids) node_offset = std::max(node_offset, id);
  for (const Element& e : model.elements) element_offset = std::max(element_offset, e.id);
  const int first_node = model.node_count();
  const int first_element = model.element_count();
  for (int n = 0; n < part.node_count(); ++n)
    model.add_node(node_offset + part.node_ids[n], part.coords[n], {});
  for (int e = 0; e < part.element_count(); ++e) {
    const Element& el = part.elements[e];
    std::vector<int> nodes(part.element_nodes(e), part.element_nodes(e) + el.node_count);
    for (int& n : nodes) n += first_node;
    model.add_element(element_offset + el.id, el.type, nodes, {});
  }
  for (const auto& [name, set] : part.nsets) {
    NodeSet copy = set;
    for (int& n : copy.nodes) n += first_node;
    model.nsets[name] = std::move(copy);
  }
  for (const auto& [name, set] : part.elsets) {
    ElementSet copy = set;
    for (int& e : copy.elements) e += first_element;
    model.elsets[name] = std::move(copy);
  }
}

void append_meshed_part(Model& model, const mesher::Mesh& mesh,
                        const std::vector<std::string>& surfaces, const std::string& elset,
                        const std::string& material) {
  const int first_element = model.element_count();
  append_part(model, mesher::to_model(mesh));
  for (const std::string& name : surfaces) {
    Surface surface;
    surface.name = name;
    for (const mesher::FaceRef& f : mesh.surfaces.at(name))
      surface.faces.push_back({first_element + f.element, f.face + 1});
    std::sort(surface.faces.begin(), surface.faces.end(), [](const auto& a, const auto& b) {
      return a.element != b.element ? a.element < b.element : a.face < b.face;
    });
    model.surfaces[name] = std::move(surface);
  }
  if (material.empty()) return;
  Section section;
  section.elset = elset;
  section.material = to_upper(material);
  section.material_index = model.material_index(section.material);
  const int index = static_cast<int>(model.sections.size());
  model.sections.push_back(section);
  for (int e : model.elsets.at(elset).elements) model.elements[e].section = index;
}

}  // namespace styk::gui
