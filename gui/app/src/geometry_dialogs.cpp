#include "geometry_dialogs.hpp"

#include <algorithm>

#include "dialog_fields.hpp"
#include "session/geometry_objects.hpp"

namespace styk::gui {

FormDialog* make_filter_dialog(const Model& model, const ElementDisplayFilter& current,
                               std::function<void(ElementDisplayFilter)> apply, QWidget* parent) {
  auto* d = new FormDialog(
      "Filter elements",
      "Only the elements whose id lies in the ranges and whose type is ticked are drawn; the "
      "faces of the cut show. Ids like 1-500, 700 (empty: every id). No type ticked: every type. "
      "View > Clear filter draws everything again.",
      parent);
  d->add_text("ids", "Element ids", QString::fromStdString(format_id_ranges(current.ranges)));
  const std::vector<std::string> types = element_types_present(model);
  for (const std::string& type : types) {
    const bool ticked =
        std::find(current.types.begin(), current.types.end(), type) != current.types.end();
    d->add_check("type_" + QString::fromStdString(type), QString::fromStdString(type), ticked);
  }
  d->set_accept([&model, types, apply = std::move(apply)](const FormDialog& f) {
    std::vector<std::string> chosen;
    for (const std::string& type : types)
      if (f.checked("type_" + QString::fromStdString(type))) chosen.push_back(type);
    apply(make_element_filter(model, f.text("ids"), chosen));
  });
  return d;
}

FormDialog* make_plane_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Plane",
      "A patch in the x-y plane from 4 corners (counter-clockwise), optionally curved by 4 "
      "mid-side points (sides 1-2, 2-3, 3-4, 4-1), meshed with plane quads: divisions and grading "
      "(last/first element length) along side 1-2 and side 1-4. Creates the element set and node "
      "set NAME; with a material, a section of the given thickness.",
      parent);
  d->add_text("name", "Name", "PLATE");
  d->add_text("corners", "Corners x y (4 points)", "0 0  10 0  10 5  0 5");
  d->add_text("midside", "Mid-side points x y (4 points, optional)", "");
  d->add_text("divisions", "Divisions side 1-2, side 1-4", "4 2");
  d->add_text("grading", "Grading side 1-2, side 1-4", "1 1");
  d->add_choice("type", "Element type", {"CPS4", "CPE4", "CPS8", "CPE8"});
  d->add_choice("material", "Section material",
                QStringList{"(none)"} + material_names(doc.model()));
  d->add_text("thickness", "Thickness", "1");
  d->set_accept([&doc](const FormDialog& f) {
    PlaneInput in;
    in.name = f.text("name");
    const std::vector<double> c = numbers(f, "corners", "Corners", 8);
    for (int k = 0; k < 4; ++k) in.points.push_back({c[2 * k], c[2 * k + 1], 0.0});
    if (!f.text("midside").empty()) {
      const std::vector<double> m = numbers(f, "midside", "Mid-side points", 8);
      for (int k = 0; k < 4; ++k) in.points.push_back({m[2 * k], m[2 * k + 1], 0.0});
    }
    const std::vector<int> n = whole_numbers(f, "divisions", "Divisions", 2);
    const std::vector<double> g = numbers(f, "grading", "Grading", 2);
    in.divisions_u = n[0];
    in.divisions_v = n[1];
    in.grading_u = g[0];
    in.grading_v = g[1];
    in.type = f.text("type");
    in.material = f.text("material") == "(none)" ? std::string() : f.text("material");
    in.thickness = f.real("thickness", "Thickness");
    doc.apply(plane_command(doc.model(), in, doc.registry()));
  });
  return d;
}

FormDialog* make_line_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Line",
      "A straight line from the start to the end point divided into graded T3D2 trusses (grading: "
      "last/first element length). Creates the element set and node set NAME; with a material, "
      "a section of the given cross-section area.",
      parent);
  d->add_text("name", "Name", "BAR");
  d->add_text("start", "Start point x y z", "0 0 0");
  d->add_text("end", "End point x y z", "10 0 0");
  d->add_text("divisions", "Divisions", "4");
  d->add_text("grading", "Grading (last/first)", "1");
  d->add_choice("material", "Section material",
                QStringList{"(none)"} + material_names(doc.model()));
  d->add_text("area", "Cross-section area", "1");
  d->set_accept([&doc](const FormDialog& f) {
    LineInput in;
    in.name = f.text("name");
    const std::vector<double> a = numbers(f, "start", "Start point", 3);
    const std::vector<double> b = numbers(f, "end", "End point", 3);
    in.a = {a[0], a[1], a[2]};
    in.b = {b[0], b[1], b[2]};
    in.divisions = f.integer("divisions", "Divisions");
    in.grading = f.real("grading", "Grading");
    in.material = f.text("material") == "(none)" ? std::string() : f.text("material");
    in.area = f.real("area", "Cross-section area");
    doc.apply(line_command(doc.model(), in, doc.registry()));
  });
  return d;
}

}  // namespace styk::gui
