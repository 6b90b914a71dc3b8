// The dialogs of the per-node lists: boundary conditions (dofs 1-3, or 11 temperature / 9
// potential in heat / electric steps), concentrated loads (or nodal heat flows / currents),
// pressures and face fluxes. With a group entry (session/load_groups.hpp) the dialog edits that
// group, filled with its values; its set choice then starts with "(the same N nodes)" when no set
// matches.
#pragma once

#include <QWidget>

#include "form_dialog.hpp"
#include "session/document.hpp"
#include "session/entry_edits.hpp"

namespace styk::gui {

FormDialog* make_boundary_dialog(Document& document, QWidget* parent);
FormDialog* make_cload_dialog(Document& document, QWidget* parent);
FormDialog* make_pressure_dialog(Document& document, QWidget* parent);
// *DFLUX face flux on a surface or an element set's face, in a heat transfer step.
FormDialog* make_flux_dialog(Document& document, QWidget* parent);
// `group` names one group of a list (Entry::item >= 0): edit it.
FormDialog* make_boundary_dialog(Document& document, QWidget* parent, const Entry& group);
FormDialog* make_cload_dialog(Document& document, QWidget* parent, const Entry& group);
FormDialog* make_pressure_dialog(Document& document, QWidget* parent, const Entry& group);
FormDialog* make_flux_dialog(Document& document, QWidget* parent, const Entry& group);

}  // namespace styk::gui
