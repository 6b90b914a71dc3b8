#include "geometry_dialogs.hpp"

#include <algorithm>
#include <vector>

#include <QRegularExpression>

#include "dialog_fields.hpp"
#include "session/geometry_objects.hpp"
#include "session/shell_surfaces.hpp"

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

namespace {

// 4 points as "x y" (8 numbers, z = 0) or "x y z" (12 numbers: shells in space).
std::vector<Vec3> points(const FormDialog& f, const QString& key, const QString& label) {
  const QString text = QString::fromStdString(f.text(key)).trimmed();
  const auto fields = text.split(QRegularExpression("[,\\s]+"), Qt::SkipEmptyParts);
  const int per_point = fields.size() == 12 ? 3 : 2;
  const std::vector<double> v = numbers(f, key, label, 4 * per_point);
  std::vector<Vec3> out;
  for (int k = 0; k < 4; ++k)
    out.push_back({v[per_point * k], v[per_point * k + 1], per_point == 3 ? v[3 * k + 2] : 0.0});
  return out;
}

// The registry's types of one kind, sorted: shells (form Shell) or 3D beams with 2 or 3 nodes.
QStringList registry_types(const ElementRegistry& registry, bool shells) {
  QStringList out;
  for (const std::string& name : registry.names()) {
    const TElement* f = registry.find(name);
    const bool fits = shells
                          ? f->form() == ElementForm::Shell
                          : f->section_measure() == SectionMeasure::Beam && f->active_dofs()[2] &&
                                (f->node_count() == 2 || f->node_count() == 3);
    if (fits) out << QString::fromStdString(name);
  }
  out.sort();
  return out;
}

// The fields a Plane and a Shell surface share: divisions and grading along u and v, element
// type, section material, thickness and shell offset.
template <typename Input>
void read_patch_fields(const FormDialog& f, Input& in) {
  const std::vector<int> n = whole_numbers(f, "divisions", "Divisions", 2);
  const std::vector<double> g = numbers(f, "grading", "Grading", 2);
  in.divisions_u = n[0];
  in.divisions_v = n[1];
  in.grading_u = g[0];
  in.grading_v = g[1];
  in.type = f.text("type");
  in.material = f.text("material") == "(none)" ? std::string() : f.text("material");
  in.thickness = f.real("thickness", "Thickness");
  in.offset = f.real("offset", "Shell offset");
}

}  // namespace

FormDialog* make_plane_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Plane",
      "A patch in the x-y plane from 4 corners (counter-clockwise), optionally curved by 4 "
      "mid-side points (sides 1-2, 2-3, 3-4, 4-1), meshed with plane quads: divisions and grading "
      "(last/first element length) along side 1-2 and side 1-4. Creates the element set and node "
      "set NAME; with a material, a section of the given thickness. Shells (S4 ... S9R) may lie "
      "anywhere: give the points as x y z; their section is a *SHELL SECTION with the offset "
      "(-0.5 .. 0.5 thicknesses from the mid-surface), node sets NAME_SIDE1..4 mark the sides.",
      parent);
  d->add_text("name", "Name", "PLATE");
  d->add_text("corners", "Corners x y or x y z (4 points)", "0 0  10 0  10 5  0 5");
  d->add_text("midside", "Mid-side points x y or x y z (4 points, optional)", "");
  d->add_text("divisions", "Divisions side 1-2, side 1-4", "4 2");
  d->add_text("grading", "Grading side 1-2, side 1-4", "1 1");
  d->add_choice("type", "Element type",
                QStringList{"CPS4", "CPE4", "CPS8", "CPE8"} + registry_types(doc.registry(), true));
  d->add_choice("material", "Section material",
                QStringList{"(none)"} + material_names(doc.model()));
  d->add_text("thickness", "Thickness", "1");
  d->add_text("offset", "Shell offset (-0.5 .. 0.5)", "0");
  d->set_accept([&doc](const FormDialog& f) {
    PlaneInput in;
    in.name = f.text("name");
    in.points = points(f, "corners", "Corners");
    if (!f.text("midside").empty()) {
      const std::vector<Vec3> m = points(f, "midside", "Mid-side points");
      in.points.insert(in.points.end(), m.begin(), m.end());
    }
    read_patch_fields(f, in);
    doc.apply(plane_command(doc.model(), in, doc.registry()));
  });
  return d;
}

FormDialog* make_shell_surface_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Shell surface",
      "A curved surface meshed with shells (S4 ... S9R). Cylindrical panel: radius R about the y "
      "axis, length along y from y = 0, the angle of arc symmetric about +z (360: a closed "
      "cylinder). Hemisphere: radius R about the origin, pole on +z, a hole of the given angle "
      "about the pole, over the sweep of longitude from +x (90: a quarter). Divisions: round the "
      "arc or longitude (u) and along the panel or from the equator to the hole (v). Creates the "
      "element set and node set NAME and the side sets NAME_SIDE1..4 (SIDE1: y = 0 or the "
      "equator, SIDE3: y = length or the hole's rim); with a material, a *SHELL SECTION.",
      parent);
  const ShellSurfaceInput defaults;
  d->add_text("name", "Name", "ROOF");
  d->add_choice(
      "kind", "Surface",
      QStringList{
          QString::fromStdString(shell_surface_kind_name(ShellSurfaceKind::CylindricalPanel)),
          QString::fromStdString(shell_surface_kind_name(ShellSurfaceKind::Hemisphere))});
  d->add_text("radius", "Radius", QString::number(defaults.radius));
  d->add_text("length", "Panel: length along y", QString::number(defaults.length));
  d->add_text("angle", "Panel: angle of arc (degrees)", QString::number(defaults.angle));
  d->add_text("hole", "Hemisphere: hole about the pole (degrees)", QString::number(defaults.hole));
  d->add_text("sweep", "Hemisphere: sweep of longitude (degrees)", QString::number(defaults.sweep));
  d->add_text("divisions", "Divisions u, v", "8 8");
  d->add_text("grading", "Grading u, v", "1 1");
  d->add_choice("type", "Element type", registry_types(doc.registry(), true));
  d->add_choice("material", "Section material",
                QStringList{"(none)"} + material_names(doc.model()));
  d->add_text("thickness", "Thickness", QString::number(defaults.thickness));
  d->add_text("offset", "Shell offset (-0.5 .. 0.5)", "0");
  d->set_accept([&doc](const FormDialog& f) {
    ShellSurfaceInput in;
    in.name = f.text("name");
    in.kind = shell_surface_kind_of(f.text("kind"));
    in.radius = f.real("radius", "Radius");
    in.length = f.real("length", "Panel length");
    in.angle = f.real("angle", "Panel angle");
    in.hole = f.real("hole", "Hemisphere hole");
    in.sweep = f.real("sweep", "Hemisphere sweep");
    read_patch_fields(f, in);
    doc.apply(shell_surface_command(doc.model(), in, doc.registry()));
  });
  return d;
}

FormDialog* make_line_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Line",
      "A straight line from the start to the end point divided into graded T3D2 trusses or beams "
      "(grading: last/first element length). Creates the element set and node set NAME; with a "
      "material, a section: the cross-section area of a truss, or a *BEAM SECTION (RECT: a b; "
      "CIRC: r; PIPE: r t; BOX: a b t1 t2 t3 t4) with its first section axis.",
      parent);
  d->add_text("name", "Name", "BAR");
  d->add_text("start", "Start point x y z", "0 0 0");
  d->add_text("end", "End point x y z", "10 0 0");
  d->add_text("divisions", "Divisions", "4");
  d->add_text("grading", "Grading (last/first)", "1");
  d->add_choice("material", "Section material",
                QStringList{"(none)"} + material_names(doc.model()));
  d->add_text("area", "Cross-section area (trusses)", "1");
  d->add_choice("type", "Element type",
                QStringList{"T3D2"} + registry_types(doc.registry(), false));
  d->add_choice("shape", "Beam section", {"RECT", "CIRC", "PIPE", "BOX"});
  d->add_text("dimensions", "Beam section dimensions", "1 1");
  d->add_text("direction", "First section axis x y z", "0 0 -1");
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
    in.type = f.text("type");
    in.shape = f.text("shape");
    if (in.type != "T3D2") {
      const QString dims = QString::fromStdString(f.text("dimensions")).trimmed();
      const int count =
          static_cast<int>(dims.split(QRegularExpression("[,\\s]+"), Qt::SkipEmptyParts).size());
      in.dimensions = numbers(f, "dimensions", "Beam section dimensions", std::max(count, 1));
      const std::vector<double> n = numbers(f, "direction", "First section axis", 3);
      in.direction = {n[0], n[1], n[2]};
    }
    doc.apply(line_command(doc.model(), in, doc.registry()));
  });
  return d;
}

}  // namespace styk::gui
