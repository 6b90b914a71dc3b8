#include "interaction_dialogs.hpp"

#include <algorithm>

#include "dialog_fields.hpp"
#include "session/constraint_input.hpp"
#include "session/contact_input.hpp"
#include "session/thermal_input.hpp"

namespace styk::gui {
namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

FormDialog* temperature_dialog(Document& doc, QWidget* parent, bool initial) {
  auto* d = new FormDialog(
      initial ? "Initial temperature" : "Temperature",
      initial ? "*INITIAL CONDITIONS, TYPE=TEMPERATURE: the temperature every node of the set "
                "starts at (nodes not given start at 0)."
              : "*TEMPERATURE in a step: the set's nodes reach this temperature at the step's "
                "end (ramped with the step time; later steps keep it). The material's expansion "
                "coefficient turns the change into a thermal load.",
      parent);
  d->add_choice("nset", "Node set", node_set_names(doc.model()));
  d->add_text("value", "Temperature", initial ? "0" : "100");
  if (!initial) d->add_choice("step", "Step", step_names(doc.model(), false));
  d->set_accept([&doc, initial](const FormDialog& f) {
    doc.apply(
        temperature_command(doc.model(), {f.text("nset"), f.real("value", "Temperature"),
                                          initial ? -1 : std::max(0, step_index(f.text("step")))}));
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
  d->add_choice("type", "Type", {"node to surface", "surface to surface"},
                in.surface_to_surface ? "surface to surface" : "node to surface");
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
    c.surface_to_surface = f.text("type") == "surface to surface";
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
  return temperature_dialog(doc, parent, true);
}

FormDialog* make_temperature_dialog(Document& doc, QWidget* parent) {
  return temperature_dialog(doc, parent, false);
}

FormDialog* make_equation_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Equation",
      "*EQUATION: sum of coefficient x u(node, dof) = 0, enforced exactly. Terms as 'node dof "
      "coefficient', separated by ';'. The first term is the dof the equation eliminates (not "
      "prescribed, not eliminated by another equation).",
      parent);
  d->add_text("terms", "Terms", "");
  d->set_accept([&doc](const FormDialog& f) {
    std::string text = f.text("terms");
    for (char& c : text)
      if (c == ';') c = '\n';
    doc.apply(equation_command(doc.model(), parse_equation_terms(text)));
  });
  return d;
}

FormDialog* make_transform_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog(
      "Transform",
      "*TRANSFORM: boundary conditions, loads and equation terms of the set's nodes act in a "
      "local system. Rectangular: local x along a, local y in the plane of a and b. Cylindrical: "
      "a and b on the axis; 1 radial, 2 tangential, 3 axial.",
      parent);
  d->add_choice("nset", "Node set", node_set_names(doc.model()));
  d->add_choice("system", "System", {"rectangular", "cylindrical"});
  d->add_text("a", "Point a x y z", "1 0 0");
  d->add_text("b", "Point b x y z", "0 1 0");
  d->set_accept([&doc](const FormDialog& f) {
    const std::vector<double> a = numbers(f, "a", "Point a", 3);
    const std::vector<double> b = numbers(f, "b", "Point b", 3);
    doc.apply(transform_command(doc.model(), {f.text("nset"),
                                              f.text("system") == "cylindrical",
                                              {a[0], a[1], a[2]},
                                              {b[0], b[1], b[2]}}));
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
