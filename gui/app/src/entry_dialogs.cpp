#include "entry_dialogs.hpp"

#include "interaction_dialogs.hpp"
#include "load_dialogs.hpp"
#include "model_dialogs.hpp"
#include "session/set_edits.hpp"

namespace styk::gui {

bool has_entry_dialog(const Entry& e) {
  switch (e.kind) {
    case EntryKind::ModelBoundaries:
    case EntryKind::StepBoundaries:
    case EntryKind::StepCloads:
    case EntryKind::StepFluxes:
    case EntryKind::StepDloads:
    case EntryKind::StepDfluxes:
    case EntryKind::StepTemperatures:
    case EntryKind::InitialTemperatures:
      return e.item >= 0;
    default:
      return true;
  }
}

FormDialog* make_set_dialog(Document& doc, const Entry& set, const Selection& selection,
                            QWidget* parent) {
  const QString what = set.kind == EntryKind::NodeSet      ? "node set"
                       : set.kind == EntryKind::ElementSet ? "element set"
                                                           : "surface";
  const QString picks = set.kind == EntryKind::NodeSet      ? "nodes"
                        : set.kind == EntryKind::ElementSet ? "elements"
                                                            : "element faces";
  auto* d = new FormDialog(
      "Edit " + what,
      QString("A new name (what names the %1 follows: transforms, contact pairs, sections, output "
              "requests), and its members from the %2 picked in the view (Select menu): replace "
              "them, add or remove the picked ones. The selection now holds %3 %4s.")
          .arg(what, picks)
          .arg(selection.size())
          .arg(QString::fromStdString(pick_kind_name(selection.kind()))),
      parent);
  d->add_text("name", "Name", QString::fromStdString(set.name));
  QStringList choices;
  for (Membership m : {Membership::Keep, Membership::Replace, Membership::Add, Membership::Remove})
    choices << QString::fromStdString(membership_name(m));
  d->add_choice("members", "Members", choices);
  d->set_accept([&doc, set, &selection](const FormDialog& f) {
    doc.apply(set_edit_command(doc.model(), set, {f.text("name"), membership_of(f.text("members"))},
                               selection));
  });
  return d;
}

FormDialog* make_entry_dialog(Document& doc, const Entry& entry, const Selection& selection,
                              QWidget* parent) {
  if (!has_entry_dialog(entry)) return nullptr;
  switch (entry.kind) {
    case EntryKind::Material:
      return make_material_dialog(doc, parent, entry.index);
    case EntryKind::Section:
      return make_section_dialog(doc, parent, entry.index);
    case EntryKind::Step:
      return make_step_dialog(doc, parent, entry.index);
    case EntryKind::ContactPair:
      return make_contact_dialog(doc, parent, entry.index);
    case EntryKind::ModelBoundaries:
    case EntryKind::StepBoundaries:
      return make_boundary_dialog(doc, parent, entry);
    case EntryKind::StepCloads:
    case EntryKind::StepFluxes:
      return make_cload_dialog(doc, parent, entry);
    case EntryKind::StepDloads:
      return make_pressure_dialog(doc, parent, entry);
    case EntryKind::StepDfluxes:
      return make_flux_dialog(doc, parent, entry);
    case EntryKind::Orientation:
      return make_orientation_dialog(doc, parent, entry.name);
    case EntryKind::StepTemperatures:
    case EntryKind::InitialTemperatures:
      return make_temperature_dialog(doc, parent, entry);
    case EntryKind::Equation:
      return make_equation_dialog(doc, parent, entry.index);
    case EntryKind::Transform:
      return make_transform_dialog(doc, parent, entry.index);
    case EntryKind::NodeSet:
    case EntryKind::ElementSet:
    case EntryKind::Surface:
      return make_set_dialog(doc, entry, selection, parent);
  }
  return nullptr;
}

}  // namespace styk::gui
