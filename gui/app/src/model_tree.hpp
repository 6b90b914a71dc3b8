// The model tree: layers (element groups with show/hide check boxes and colour swatches; double
// click changes the colour), node sets, element sets, surfaces, materials, sections, steps with
// their boundary conditions, loads and temperatures, contact pairs, equations, transforms, and
// the results' increments. Each per-node list (boundary conditions, loads, fluxes, pressures,
// temperatures) lists its groups, what each dialog made (session/load_groups.hpp). Selecting an
// item shows its properties. Model entries can be edited (double-click or context menu
// "Edit...": every entry but a whole list, see entry_dialogs.hpp) and deleted (Delete key or
// context menu); the window does it through session/entry_edits.hpp.
#pragma once

#include <QTreeWidget>
#include <optional>

#include "session/document.hpp"
#include "session/entry_edits.hpp"

namespace styk::gui {

class ModelTree : public QTreeWidget {
  Q_OBJECT
 public:
  explicit ModelTree(QWidget* parent = nullptr);
  void populate(const Document& document);
  // The model entry an item stands for (none for group headings, layers, results).
  static std::optional<Entry> entry_of(const QTreeWidgetItem* item);
  // The first item whose text starts with `text` (tests, scripted walk-throughs).
  QTreeWidgetItem* find_item(const QString& text) const;

 signals:
  void layer_toggled(const QString& name, bool visible);
  void layer_color_requested(const QString& name);
  void properties(const QString& html);
  void edit_requested(const styk::gui::Entry& entry);
  void delete_requested(const styk::gui::Entry& entry);

 protected:
  void keyPressEvent(QKeyEvent* event) override;

 private:
  void show_menu(const QPoint& at);
  bool filling_ = false;
};

}  // namespace styk::gui
