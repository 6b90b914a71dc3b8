#include "interaction_dialogs.hpp"

#include <algorithm>
#include <optional>

#include "dialog_fields.hpp"
#include "session/constraint_input.hpp"
#include "session/contact_input.hpp"
#include "session/load_groups.hpp"
#include "session/orientation_input.hpp"
#include "session/thermal_input.hpp"

namespace styk::gui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

FormDialog* temperature_dialog(Document& doc, QWidget* parent, bool initial, const Entry* group) {
  const Model& m = doc.model();
  TemperatureInput in{"", initial ? 0.0 : 100.0, initial ? -1 : 0};
  QStringList sets = node_set_names(m);
  if (group) {
    in = temperature_input_of(m, *group);
    if (in.nset.empty())
      sets.prepend(
          QString("(the same %1 nodes)").arg(node_groups(m, *group).at(group->item).nodes.size()));
  }
  auto* d = new FormDialog(
      QString(group ? "Edit " : "") + (initial ? "Initial temperature" : "Temperature"),
      initial ? "*INITIAL CONDITIONS, TYPE=TEMPERATURE: the temperature every node of the set "
                "starts at (nodes not given start at 0)."
              : "*TEMPERATURE in a static step: the set's nodes reach this temperature at the "
                "step's end (ramped with the step time; later steps keep it). The material's "
                "expansion coefficient turns the change into a thermal load.",
      parent);
  d->add_choice("nset", "Node set", sets, q(in.nset));
  d->add_text("value", "Temperature", QString::number(in.value));
  if (!initial)
    d->add_choice("step", "Step", step_names(m, false),
                  in.step >= 0 && in.step < int(m.steps.size())
                      ? QString("%1 %2").arg(in.step + 1).arg(q(m.steps[in.step].name))
                      : QString());
  const std::optional<Entry> edited = group ? std::optional<Entry>(*group) : std::nullopt;
  d->set_accept([&doc, initial, edited](const FormDialog& f) {
    const std::string nset = f.text("nset").rfind("(", 0) == 0 ? std::string() : f.text("nset");
    const TemperatureInput t{nset, f.real("value", "Temperature"),
                             initial ? -1 : std::max(0, step_index(f.text("step")))};
    doc.apply(edited ? temperature_edit_command(doc.model(), *edited, t)
                     : temperature_command(doc.model(), t));
  });
  return d;
}

}  // namespace

FormDialog* make_contact_dialog(Document& doc, QWidget* parent, int pair) {
  const Model& m = doc.model();
  ContactInput in;
  in.interaction = "CONTACT-" + std::to_string(m.contact_pairs.size() + 1);
  if (pair >= 0) in = contact_input_of(m, pair);
  auto* d = new FormDialog(
      pair >= 0 ? "Edit contact pair" : "Contact pair",
      "Slave nodes against master faces (*CONTACT PAIR), enforced exactly; coincident nodes pair "
      "node to node. Friction: Coulomb with mu (isotropic), mu1/mu2 along the axes of an "
      "orientation (anisotropic), or rough (no slip). A clearance replaces the geometric gap "
      "(negative: interference).",
      parent);
  d->add_choice("slave", "Slave surface", surface_names(m), q(in.slave));
  d->add_choice("master", "Master surface", surface_names(m), q(in.master));
  d->add_text("interaction", "Interaction name", q(in.interaction));
  d->add_choice("friction", "Friction", {"isotropic", "frictionless", "anisotropic", "rough"},
                q(in.friction));
  d->add_text("mu", "mu (mu1)", QString::number(in.mu));
  d->add_text("mu2", "mu2 (anisotropic)", QString::number(in.mu2));
  QStringList orientations{"(none)"};
  for (const auto& [name, o] : m.orientations) orientations << q(name);
  d->add_choice("orientation", "Orientation (anisotropic)", orientations, q(in.orientation));
  d->add_choice("type", "Type", {"node to surface", "surface to surface", "mortar"},
                in.type == ContactPair::Type::Mortar             ? "mortar"
                : in.type == ContactPair::Type::SurfaceToSurface ? "surface to surface"
                                                                 : "node to surface");
  d->add_check("has_clearance", "Clearance (replaces the geometric gap)", in.has_clearance);
  d->add_text("clearance", "Clearance (< 0: interference)", QString::number(in.clearance));
  d->set_accept([&doc, pair](const FormDialog& f) {
    ContactInput c;
    c.slave = f.text("slave");
    c.master = f.text("master");
    c.interaction = f.text("interaction");
    c.friction = f.text("friction");
    c.mu = f.real("mu", "mu");
    c.mu2 = f.real("mu2", "mu2");
    c.orientation = f.text("orientation") == "(none)" ? std::string() : f.text("orientation");
    const std::string type = f.text("type");
    c.type = type == "mortar"               ? ContactPair::Type::Mortar
             : type == "surface to surface" ? ContactPair::Type::SurfaceToSurface
                                            : ContactPair::Type::NodeToSurface;
    c.has_clearance = f.checked("has_clearance");
    if (c.has_clearance) c.clearance = f.real("clearance", "Clearance");
    doc.apply(contact_command(doc.model(), c, pair));
  });
  return d;
}

FormDialog* make_new_contact_dialog(Document& doc, QWidget* parent) {
  return make_contact_dialog(doc, parent, -1);
}

FormDialog* make_initial_temperature_dialog(Document& doc, QWidget* parent) {
  return temperature_dialog(doc, parent, true, nullptr);
}

FormDialog* make_temperature_dialog(Document& doc, QWidget* parent) {
  return temperature_dialog(doc, parent, false, nullptr);
}

FormDialog* make_temperature_dialog(Document& doc, QWidget* parent, const Entry& group) {
  return temperature_dialog(doc, parent, group.kind == EntryKind::InitialTemperatures, &group);
}

FormDialog* make_equation_dialog(Document& doc, QWidget* parent) {
  return make_equation_dialog(doc, parent, -1);
}

FormDialog* make_equation_dialog(Document& doc, QWidget* parent, int equation) {
  auto* d = new FormDialog(
      equation >= 0 ? "Edit equation" : "Equation",
      "*EQUATION: sum of coefficient x u(node, dof) = 0, enforced exactly. Terms as 'node dof "
      "coefficient', separated by ';'. The first term is the dof the equation eliminates (not "
      "prescribed, not eliminated by another equation).",
      parent);
  d->add_text("terms", "Terms", equation >= 0 ? q(equation_text(doc.model(), equation)) : "");
  d->set_accept([&doc, equation](const FormDialog& f) {
    std::string text = f.text("terms");
    for (char& c : text)
      if (c == ';') c = '\n';
    const std::vector<EquationTermInput> terms = parse_equation_terms(text);
    doc.apply(equation >= 0 ? equation_edit_command(doc.model(), equation, terms)
                            : equation_command(doc.model(), terms));
  });
  return d;
}

FormDialog* make_transform_dialog(Document& doc, QWidget* parent) {
  return make_transform_dialog(doc, parent, -1);
}

FormDialog* make_transform_dialog(Document& doc, QWidget* parent, int transform) {
  const TransformInput in =
      transform >= 0 ? transform_input_of(doc.model(), transform) : TransformInput{};
  const auto point = [](const Vec3& p) {
    return QString("%1 %2 %3").arg(p[0]).arg(p[1]).arg(p[2]);
  };
  auto* d = new FormDialog(
      transform >= 0 ? "Edit transform" : "Transform",
      "*TRANSFORM: boundary conditions, loads and equation terms of the set's nodes act in a "
      "local system. Rectangular: local x along a, local y in the plane of a and b. Cylindrical: "
      "a and b on the axis; 1 radial, 2 tangential, 3 axial.",
      parent);
  d->add_choice("nset", "Node set", node_set_names(doc.model()), q(in.nset));
  d->add_choice("system", "System", {"rectangular", "cylindrical"},
                in.cylindrical ? "cylindrical" : "rectangular");
  d->add_text("a", "Point a x y z", point(in.a));
  d->add_text("b", "Point b x y z", point(in.b));
  d->set_accept([&doc, transform](const FormDialog& f) {
    const std::vector<double> a = numbers(f, "a", "Point a", 3);
    const std::vector<double> b = numbers(f, "b", "Point b", 3);
    const TransformInput t{
        f.text("nset"), f.text("system") == "cylindrical", {a[0], a[1], a[2]}, {b[0], b[1], b[2]}};
    doc.apply(transform >= 0 ? transform_edit_command(doc.model(), transform, t)
                             : transform_command(doc.model(), t));
  });
  return d;
}

FormDialog* make_orientation_dialog(Document& doc, QWidget* parent) {
  return make_orientation_dialog(doc, parent, std::string());
}

FormDialog* make_orientation_dialog(Document& doc, QWidget* parent, const std::string& name) {
  const bool editing = !name.empty();
  OrientationInput in;
  in.name = "ORIENT-" + std::to_string(doc.model().orientations.size() + 1);
  if (editing) in = orientation_input_of(doc.model(), name);
  const auto point = [](const Vec3& p) {
    return QString("%1 %2 %3").arg(p[0]).arg(p[1]).arg(p[2]);
  };
  auto* d = new FormDialog(
      editing ? "Edit orientation" : "Orientation",
      "*ORIENTATION: a named local system; anisotropic friction (Contact pair) slips with mu1 "
      "along its axis 1 and mu2 along axis 2. Rectangular: local x along a, local y in the plane "
      "of a and b. Cylindrical: a and b on the axis; 1 radial, 2 tangential, 3 axial.",
      parent);
  d->add_text("name", "Name", q(in.name));
  d->add_choice("system", "System", {"rectangular", "cylindrical"},
                in.cylindrical ? "cylindrical" : "rectangular");
  d->add_text("a", "Point a x y z", point(in.a));
  d->add_text("b", "Point b x y z", point(in.b));
  d->set_accept([&doc, name](const FormDialog& f) {
    const std::vector<double> a = numbers(f, "a", "Point a", 3);
    const std::vector<double> b = numbers(f, "b", "Point b", 3);
    const OrientationInput o{
        f.text("name"), f.text("system") == "cylindrical", {a[0], a[1], a[2]}, {b[0], b[1], b[2]}};
    doc.apply(name.empty() ? orientation_command(doc.model(), o)
                           : orientation_edit_command(doc.model(), name, o));
  });
  return d;
}

FormDialog* make_common_nodes_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog("Node set from two sets",
                           "A new node set of the nodes both sets hold, e.g. the line where a "
                           "revolve's inner cylinder meets its cut plane (for the X-Y chart).",
                           parent);
  d->add_text("name", "Name", "LINE");
  d->add_choice("first", "First node set", node_set_names(doc.model()));
  d->add_choice("second", "Second node set", node_set_names(doc.model()));
  d->set_accept([&doc](const FormDialog& f) {
    doc.apply(
        common_nodes_command(doc.model(), {f.text("name"), f.text("first"), f.text("second")}));
  });
  return d;
}

}  // namespace styk::gui
