#include "revolve_dialog.hpp"

#include "dialog_fields.hpp"
#include "session/brick_types.hpp"
#include "session/revolve.hpp"

namespace styk::gui {

FormDialog* make_revolve_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Revolve",
      "The rectangle inner..outer radius x z from..to of a half-plane through the axis, revolved "
      "about the axis and meshed with hexahedra. Inner radius 0 gives a solid (an O-grid core; "
      "angle 90, 180, 270 or 360, an even number of divisions around per 90 degrees). Creates "
      "the element set and node set NAME and surfaces + node sets NAME_INNER, _OUTER, _BOTTOM "
      "(z from), _TOP (z to), _CUT0 (angle 0), _CUT1 (end angle). Two revolves sharing a radius "
      "with the same divisions around get coincident, separate nodes there: a contact interface.",
      parent);
  d->add_text("name", "Name", "SHAFT");
  d->add_text("origin", "Axis point x y z", "0 0 0");
  d->add_text("axis", "Axis direction x y z", "0 0 1");
  d->add_text("radii", "Inner, outer radius", "0 10");
  d->add_text("z", "z from, to (along the axis)", "0 60");
  d->add_text("angle", "Angle (degrees)", "90");
  d->add_text("divisions", "Divisions radial, axial, around", "2 12 6");
  d->add_text("grading", "Grading radial, axial (last/first)", "1 1");
  QStringList types;
  for (const std::string& type : brick_types(doc.registry())) types << QString::fromStdString(type);
  d->add_choice("type", "Element type", types);
  d->add_choice("layer_side", "Contact layer (C3D21, C3D28, ...) on side",
                {"OUTER", "INNER", "BOTTOM", "TOP", "CUT0", "CUT1"});
  d->add_choice("material", "Section material",
                QStringList{"(none)"} + material_names(doc.model()));
  d->set_accept([&doc](const FormDialog& f) {
    RevolveInput in;
    in.name = f.text("name");
    const std::vector<double> o = numbers(f, "origin", "Axis point", 3);
    const std::vector<double> a = numbers(f, "axis", "Axis direction", 3);
    const std::vector<double> r = numbers(f, "radii", "Radii", 2);
    const std::vector<double> z = numbers(f, "z", "z", 2);
    const std::vector<int> n = whole_numbers(f, "divisions", "Divisions", 3);
    const std::vector<double> g = numbers(f, "grading", "Grading", 2);
    in.origin = {o[0], o[1], o[2]};
    in.axis = {a[0], a[1], a[2]};
    in.r_inner = r[0];
    in.r_outer = r[1];
    in.z0 = z[0];
    in.z1 = z[1];
    in.angle = f.real("angle", "Angle");
    in.radial = n[0];
    in.axial = n[1];
    in.around = n[2];
    in.radial_grading = g[0];
    in.axial_grading = g[1];
    in.type = f.text("type");
    in.layer_side = f.text("layer_side");
    in.material = f.text("material") == "(none)" ? std::string() : f.text("material");
    doc.apply(revolve_command(doc.model(), in, doc.registry()));
  });
  return d;
}

}  // namespace styk::gui
