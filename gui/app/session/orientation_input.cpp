#include "session/orientation_input.hpp"

#include <algorithm>
#include <cmath>

#include "session/input_checks.hpp"
#include "styk/core/local_axes.hpp"

namespace styk::gui {
namespace {

// The frictions naming `from` name `to` instead (an orientation renamed).
void rename_in_frictions(Model& m, const std::string& from, const std::string& to) {
  for (auto& [name, interaction] : m.surface_interactions)
    if (interaction.friction && interaction.friction->orientation == from)
      interaction.friction->orientation = to;
}

}  // namespace

LocalAxes local_axes(bool cylindrical, const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k) {
    check_finite(a[k], "point a");
    check_finite(b[k], "point b");
  }
  LocalAxes axes;
  axes.system = cylindrical ? CoordinateSystem::Cylindrical : CoordinateSystem::Rectangular;
  axes.a = a;
  axes.b = b;
  if (const std::string defect = axes_defect(axes); !defect.empty()) refuse(defect);
  return axes;
}

Orientation checked_orientation(const Model& model, const OrientationInput& in,
                                const std::string& replacing) {
  check_name(in.name, "the orientation");
  const std::string name = to_upper(in.name);
  if (name != replacing && model.orientations.count(name))
    refuse("orientation " + name + " exists already");
  Orientation o;
  o.name = name;
  o.axes = local_axes(in.cylindrical, in.a, in.b);
  return o;
}

std::unique_ptr<Command> orientation_command(const Model& model, const OrientationInput& in) {
  const Orientation o = checked_orientation(model, in, {});
  return make_model_edit(
      std::string("Add ") + (in.cylindrical ? "cylindrical" : "rectangular") + " orientation " +
          o.name,
      [o](Model& m) { m.orientations[o.name] = o; },
      [name = o.name](Model& m) { m.orientations.erase(name); });
}

OrientationInput orientation_input_of(const Model& model, const std::string& name) {
  const auto it = model.orientations.find(to_upper(name));
  if (it == model.orientations.end()) refuse("no orientation " + to_upper(name) + " in the model");
  const Orientation& o = it->second;
  return {o.name, o.axes.system == CoordinateSystem::Cylindrical, o.axes.a, o.axes.b};
}

std::unique_ptr<Command> orientation_edit_command(const Model& model, const std::string& name,
                                                  const OrientationInput& in) {
  orientation_input_of(model, name);  // checks that it exists
  const Orientation before = model.orientations.at(to_upper(name));
  Orientation after = checked_orientation(model, in, before.name);
  after.where = before.where;
  const auto replace = [](Model& m, const Orientation& old, const Orientation& now) {
    m.orientations.erase(old.name);
    m.orientations[now.name] = now;
    rename_in_frictions(m, old.name, now.name);
  };
  return make_model_edit(
      "Edit orientation " + before.name,
      [replace, before, after](Model& m) { replace(m, before, after); },
      [replace, before, after](Model& m) { replace(m, after, before); });
}

std::string orientation_user(const Model& model, const std::string& name) {
  for (const auto& [interaction, si] : model.surface_interactions)
    if (si.friction && si.friction->orientation == name) return interaction;
  return {};
}

}  // namespace styk::gui
