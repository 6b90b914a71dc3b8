#include "session/validation.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>

#include "session/input_checks.hpp"

namespace styk::gui {

double parse_real(const std::string& text, const std::string& label) {
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  while (end && std::isspace(static_cast<unsigned char>(*end))) ++end;
  if (text.empty() || end == text.c_str() || *end != '\0' || errno == ERANGE ||
      !std::isfinite(value))
    refuse(label + ": '" + text + "' is not a number");
  return value;
}

int parse_integer(const std::string& text, const std::string& label) {
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  while (end && std::isspace(static_cast<unsigned char>(*end))) ++end;
  if (text.empty() || end == text.c_str() || *end != '\0' || errno == ERANGE ||
      value < -1000000000L || value > 1000000000L)
    refuse(label + ": '" + text + "' is not a whole number");
  return static_cast<int>(value);
}

Material checked_material(const Model& model, const MaterialInput& in, int replacing) {
  check_name(in.name, "the material");
  const std::string name = to_upper(in.name);
  const int existing = model.material_index(name);
  if (existing >= 0 && existing != replacing) refuse("material " + name + " exists already");
  check_finite(in.young, "Young's modulus");
  check_finite(in.poisson, "Poisson's ratio");
  check_finite(in.density, "density");
  check_finite(in.expansion, "expansion coefficient");
  const auto conductivity = [](const std::vector<double>& k,
                               const std::string& what) -> std::optional<std::array<double, 3>> {
    if (k.empty()) return std::nullopt;
    if (k.size() != 1 && k.size() != 3)
      refuse(what + ": give 1 value (isotropic) or 3 (k11 k22 k33), not " +
             std::to_string(k.size()));
    for (double v : k) {
      check_finite(v, what);
      if (!(v > 0)) refuse(what + " must be > 0 (leave it empty: not given)");
    }
    return k.size() == 1 ? std::array<double, 3>{k[0], k[0], k[0]}
                         : std::array<double, 3>{k[0], k[1], k[2]};
  };
  const auto thermal = conductivity(in.conductivity, "conductivity");
  const auto electrical = conductivity(in.electrical_conductivity, "electrical conductivity");
  const bool elastic = in.young != 0.0 || (!thermal && !electrical);
  if (elastic && !(in.young > 0))
    refuse(
        "Young's modulus must be > 0 (0 only for a heat or electric material with a "
        "conductivity)");
  if (elastic && !(in.poisson > -1.0 && in.poisson < 0.5))
    refuse("Poisson's ratio must lie between -1 and 0.5 (exclusive)");
  if (in.density < 0) refuse("density must be >= 0 (0: not given)");
  if (in.expansion < 0) refuse("expansion coefficient must be >= 0 (0: not given)");
  if (in.expansion > 1e-2)
    refuse("expansion coefficient " + std::to_string(in.expansion) +
           " is not a thermal expansion (1/K); steel is about 1.2e-5");
  Material m;
  m.name = name;
  if (elastic) {
    m.young = in.young;
    m.poisson = in.poisson;
  }
  if (in.density > 0) m.density = in.density;
  if (in.expansion > 0) m.expansion = in.expansion;
  m.conductivity = thermal;
  m.electrical_conductivity = electrical;
  return m;
}

std::unique_ptr<Command> material_command(const Model& model, const MaterialInput& in) {
  return make_add_material(checked_material(model, in));
}

std::unique_ptr<Command> section_command(const Model& model, const SectionInput& in) {
  if (in.elset.empty()) refuse("choose an element set");
  const ElementSet* set = model.find_elset(in.elset);
  if (!set) refuse("no element set " + to_upper(in.elset) + " in the model");
  if (set->elements.empty()) refuse("element set " + set->name + " is empty");
  if (in.material.empty()) refuse("choose a material");
  if (model.material_index(to_upper(in.material)) < 0)
    refuse("no material " + to_upper(in.material) + " in the model");
  for (int e : set->elements)
    if (model.elements[e].section >= 0)
      refuse("element " + std::to_string(model.elements[e].id) + " of " + set->name +
             " has a section already (on " + model.sections[model.elements[e].section].elset +
             "); an element belongs to one section only");
  Section s;
  s.elset = set->name;
  s.material = to_upper(in.material);
  return make_add_section(std::move(s));
}

std::unique_ptr<Command> step_command(const Model& model, const StepInput& in) {
  check_name(in.name, "the step");
  for (const Step& s : model.steps)
    if (to_upper(s.name) == to_upper(in.name)) refuse("step " + in.name + " exists already");
  check_finite(in.initial_increment, "initial increment");
  check_finite(in.total_time, "total time");
  if (!(in.total_time > 0)) refuse("total time must be > 0");
  if (!(in.initial_increment > 0) || in.initial_increment > in.total_time)
    refuse("initial increment must be > 0 and not above the total time");
  Step step;
  step.name = in.name;
  step.kind = in.kind;
  step.has_procedure = true;
  step.procedure.initial_increment = in.initial_increment;
  step.procedure.total_time = in.total_time;
  return make_add_step(std::move(step));
}

std::unique_ptr<Command> boundary_command(const Model& model, const BoundaryInput& in) {
  const NodeSet& set = existing_nset(model, in.nset);
  check_step(model, in.step, true);
  check_field_dof(model, in.step, in.first_dof, "first dof");
  check_field_dof(model, in.step, in.last_dof, "last dof");
  if (in.last_dof < in.first_dof) refuse("last dof must not be below the first dof");
  if (is_flux_dof(in.first_dof) && in.last_dof != in.first_dof)
    refuse("a temperature (11) or potential (9) is one dof: give it as first and last dof");
  check_finite(in.value, "value");
  std::vector<Boundary> entries;
  for (int n : set.nodes)
    for (int dof = in.first_dof; dof <= in.last_dof; ++dof)
      entries.push_back({n, dof, in.value, {}});
  return make_add_boundaries(in.step, std::move(entries),
                             "Fix " + set.name + " dofs " + std::to_string(in.first_dof) + "-" +
                                 std::to_string(in.last_dof));
}

std::unique_ptr<Command> cload_command(const Model& model, const CloadInput& in) {
  const NodeSet& set = existing_nset(model, in.nset);
  check_step(model, in.step, false);
  check_field_dof(model, in.step, in.dof, "direction");
  check_finite(in.value, "load");
  if (in.value == 0.0) refuse("a load of 0 does nothing; enter a value");
  const double each = in.split ? in.value / static_cast<double>(set.nodes.size()) : in.value;
  std::vector<ConcentratedLoad> loads;
  for (int n : set.nodes) loads.push_back({n, in.dof, each, {}});
  if (!is_flux_dof(in.dof)) return make_add_cloads(in.step, std::move(loads), "Load " + set.name);
  const std::string what = in.dof == 11 ? "Heat flow" : "Current";
  return make_model_edit(
      what + " into " + set.name,
      [step = in.step, loads](Model& m) {
        auto& v = m.steps.at(step).cfluxes;
        v.insert(v.end(), loads.begin(), loads.end());
      },
      [step = in.step, count = loads.size()](Model& m) {
        auto& v = m.steps.at(step).cfluxes;
        v.resize(v.size() - count);
      });
}

std::unique_ptr<Command> pressure_command(const Model& model, const PressureInput& in) {
  check_step(model, in.step, false);
  if (model.steps[in.step].kind != StepKind::Static)
    refuse("step " + model.steps[in.step].name + " is a " +
           step_kind_name(model.steps[in.step].kind) +
           " step: a pressure belongs to a static step (a heat flux into a face: Model > Face "
           "flux)");
  check_finite(in.magnitude, "pressure");
  if (in.magnitude == 0.0) refuse("a pressure of 0 does nothing; enter a value");
  std::vector<DistributedLoad> loads;
  std::string target;
  if (!in.surface.empty()) {
    const auto it = model.surfaces.find(to_upper(in.surface));
    if (it == model.surfaces.end()) refuse("no surface " + to_upper(in.surface) + " in the model");
    if (it->second.kind != Surface::Kind::ElementFaces || it->second.faces.empty())
      refuse("surface " + it->second.name + " holds no element faces");
    for (const SurfaceFace& f : it->second.faces)
      loads.push_back({f.element, f.face, in.magnitude, {}});
    target = it->second.name;
  } else {
    if (in.elset.empty()) refuse("choose a surface or an element set");
    const ElementSet* set = model.find_elset(in.elset);
    if (!set) refuse("no element set " + to_upper(in.elset) + " in the model");
    if (set->elements.empty()) refuse("element set " + set->name + " is empty");
    if (in.face < 1 || in.face > 6) refuse("face must be 1..6 (S1..S6)");
    for (int e : set->elements) loads.push_back({e, in.face, in.magnitude, {}});
    target = set->name + " S" + std::to_string(in.face);
  }
  return make_add_dloads(in.step, std::move(loads), "Pressure on " + target);
}

}  // namespace styk::gui
