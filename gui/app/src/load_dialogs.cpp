#include "load_dialogs.hpp"

#include <optional>

#include "dialog_fields.hpp"
#include "session/flux_input.hpp"
#include "session/load_groups.hpp"
#include "session/validation.hpp"

namespace styk::gui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

// The node set choice: the model's sets, led by "(the same N nodes)" when editing a group no set
// matches; that entry reads back as "" (keep the nodes).
QStringList nset_choices(const Model& m, const std::optional<NodeGroup>& group) {
  QStringList names = node_set_names(m);
  if (group && group->nset.empty())
    names.prepend(QString("(the same %1 nodes)").arg(group->nodes.size()));
  return names;
}
std::string chosen_set(const FormDialog& f, const QString& key) {
  const std::string text = f.text(key);
  return text.rfind("(", 0) == 0 ? std::string() : text;
}

std::optional<NodeGroup> node_group(const Model& m, const Entry* group) {
  if (!group) return std::nullopt;
  return node_groups(m, *group).at(group->item);
}

QString step_choice(const Model& m, int step) {
  if (step < 0) return "0 (all steps)";
  return QString("%1 %2").arg(step + 1).arg(q(m.steps.at(step).name));
}

FormDialog* boundary_dialog(Document& doc, QWidget* parent, const Entry* group) {
  const Model& m = doc.model();
  const std::optional<NodeGroup> g = node_group(m, group);
  const BoundaryInput in = group ? boundary_input_of(m, *group) : BoundaryInput{};
  auto* d = new FormDialog(group ? "Edit boundary condition" : "Boundary condition",
                           "Prescribes dofs first..last of every node of a node set: 1 = x, "
                           "2 = y, 3 = z, 4-6 = rotations about x, y, z (nodes of beams and "
                           "shells) in static steps; 11 = temperature in heat transfer "
                           "steps, 9 = electric potential in electric conduction steps (first = "
                           "last).",
                           parent);
  d->add_choice("nset", "Node set", nset_choices(m, g), q(in.nset));
  d->add_text("first", "First dof", QString::number(in.first_dof));
  d->add_text("last", "Last dof", QString::number(in.last_dof));
  d->add_text("value", "Value", QString::number(in.value));
  d->add_choice("step", "Step", step_names(m, true), step_choice(m, in.step));
  const std::optional<Entry> edited = group ? std::optional<Entry>(*group) : std::nullopt;
  d->set_accept([&doc, edited](const FormDialog& f) {
    const BoundaryInput b{chosen_set(f, "nset"), f.integer("first", "First dof"),
                          f.integer("last", "Last dof"), f.real("value", "Value"),
                          step_index(f.text("step"))};
    doc.apply(edited ? boundary_edit_command(doc.model(), *edited, b)
                     : boundary_command(doc.model(), b));
  });
  return d;
}

FormDialog* cload_dialog(Document& doc, QWidget* parent, const Entry* group) {
  const Model& m = doc.model();
  const std::optional<NodeGroup> g = node_group(m, group);
  CloadInput in{"", 3, -100.0, true, 0};
  if (group) in = cload_input_of(m, *group);
  auto* d = new FormDialog(group ? "Edit concentrated load" : "Concentrated load",
                           "*CLOAD on every node of a node set (direction 1, 2, 3; moments about "
                           "x, y, z: 4, 5, 6 at nodes of beams and shells) in a static step; in a "
                           "heat transfer step direction 11 is a nodal heat flow "
                           "(*CFLUX), in an electric conduction step 9 a nodal current (*CECUR).",
                           parent);
  d->add_choice("nset", "Node set", nset_choices(m, g), q(in.nset));
  d->add_text("dof", "Direction (1, 2, 3; moments 4, 5, 6; 11 heat flow; 9 current)",
              QString::number(in.dof));
  d->add_text("value", "Value", QString::number(in.value));
  d->add_check("split", "Value is the total, divided among the nodes", in.split);
  d->add_choice("step", "Step", step_names(m, false),
                m.steps.empty() ? QString() : step_choice(m, in.step));
  const std::optional<Entry> edited = group ? std::optional<Entry>(*group) : std::nullopt;
  d->set_accept([&doc, edited](const FormDialog& f) {
    const CloadInput c{chosen_set(f, "nset"), f.integer("dof", "Direction"),
                       f.real("value", "Value"), f.checked("split"), step_index(f.text("step"))};
    doc.apply(edited ? cload_edit_command(doc.model(), *edited, c) : cload_command(doc.model(), c));
  });
  return d;
}

// Pressure (*DLOAD, static steps) and face flux (*DFLUX, heat transfer steps) ask for the same
// faces: a surface, or face S1..S6 of an element set.
FormDialog* face_load_dialog(Document& doc, QWidget* parent, const Entry* group, bool flux) {
  const Model& m = doc.model();
  PressureInput in{"", "", 1, 1.0, 0};
  if (flux) {  // the first heat transfer step, where a flux may go
    for (int s = 0; s < int(m.steps.size()); ++s)
      if (m.steps[s].kind == StepKind::HeatTransfer) {
        in.step = s;
        break;
      }
  }
  if (group) in = flux ? flux_input_of(m, *group) : pressure_input_of(m, *group);
  const QString title = flux ? "Face flux" : "Pressure";
  auto* d = new FormDialog(
      group ? "Edit " + title.toLower() : title,
      flux ? "*DFLUX uniform heat flux per area (positive into the body) on a surface, or on face "
             "S1..S6 of every element of an element set, in a heat transfer step."
           : "*DLOAD pressure (positive pushes into the element) on a surface, or on face S1..S6 "
             "of every element of an element set.",
      parent);
  QStringList surfaces{"(element set below)"};
  if (group && in.surface.empty() && in.elset.empty())
    surfaces.prepend(
        QString("(the same %1 faces)").arg(face_groups(m, *group).at(group->item).faces.size()));
  for (const auto& [name, s] : m.surfaces) surfaces << q(name);
  d->add_choice("surface", "Surface", surfaces, q(in.surface));
  QStringList elsets = element_set_names(m);
  if (group && in.elset.empty()) elsets.prepend("(none)");
  d->add_choice("elset", "Element set", elsets, q(in.elset));
  d->add_text("face", "Face (1..6)", QString::number(in.face));
  d->add_text("magnitude", flux ? "Flux" : "Pressure", QString::number(in.magnitude));
  d->add_choice("step", "Step", step_names(m, false),
                m.steps.empty() ? QString() : step_choice(m, in.step));
  const std::optional<Entry> edited = group ? std::optional<Entry>(*group) : std::nullopt;
  d->set_accept([&doc, edited, flux](const FormDialog& f) {
    const std::string elset = f.text("elset") == "(none)" ? std::string() : f.text("elset");
    const std::string surface = chosen_set(f, "surface");
    // "(the same N faces)": keep them; "(element set below)": the element set's faces.
    const bool keep = f.text("surface").rfind("(the same", 0) == 0;
    const PressureInput p{surface, keep ? std::string() : elset, f.integer("face", "Face"),
                          f.real("magnitude", flux ? "Flux" : "Pressure"),
                          step_index(f.text("step"))};
    if (flux)
      doc.apply(edited ? flux_edit_command(doc.model(), *edited, p) : flux_command(doc.model(), p));
    else
      doc.apply(edited ? pressure_edit_command(doc.model(), *edited, p)
                       : pressure_command(doc.model(), p));
  });
  return d;
}

}  // namespace

FormDialog* make_boundary_dialog(Document& doc, QWidget* parent) {
  return boundary_dialog(doc, parent, nullptr);
}
FormDialog* make_cload_dialog(Document& doc, QWidget* parent) {
  return cload_dialog(doc, parent, nullptr);
}
FormDialog* make_pressure_dialog(Document& doc, QWidget* parent) {
  return face_load_dialog(doc, parent, nullptr, false);
}
FormDialog* make_flux_dialog(Document& doc, QWidget* parent) {
  return face_load_dialog(doc, parent, nullptr, true);
}
FormDialog* make_boundary_dialog(Document& doc, QWidget* parent, const Entry& group) {
  return boundary_dialog(doc, parent, &group);
}
FormDialog* make_cload_dialog(Document& doc, QWidget* parent, const Entry& group) {
  return cload_dialog(doc, parent, &group);
}
FormDialog* make_pressure_dialog(Document& doc, QWidget* parent, const Entry& group) {
  return face_load_dialog(doc, parent, &group, false);
}
FormDialog* make_flux_dialog(Document& doc, QWidget* parent, const Entry& group) {
  return face_load_dialog(doc, parent, &group, true);
}

}  // namespace styk::gui
