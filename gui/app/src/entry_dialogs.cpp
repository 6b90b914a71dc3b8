#include "entry_dialogs.hpp"

#include "interaction_dialogs.hpp"
#include "model_dialogs.hpp"

namespace styk::gui {

FormDialog* make_entry_dialog(Document& doc, const Entry& entry, QWidget* parent) {
  switch (entry.kind) {
    case EntryKind::Material:
      return make_material_dialog(doc, parent, entry.index);
    case EntryKind::Section:
      return make_section_dialog(doc, parent, entry.index);
    case EntryKind::Step:
      return make_step_dialog(doc, parent, entry.index);
    case EntryKind::ContactPair:
      return make_contact_dialog(doc, parent, entry.index);
    default:
      return nullptr;
  }
}

}  // namespace styk::gui
