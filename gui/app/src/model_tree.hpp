// The model tree: layers (element groups with show/hide check boxes and colour swatches; double
// click changes the colour), node sets, surfaces, materials, sections, steps with their boundary
// conditions and loads, and the results' increments. Selecting an item shows its properties.
#pragma once

#include <QTreeWidget>

#include "session/document.hpp"

namespace styk::gui {

class ModelTree : public QTreeWidget {
  Q_OBJECT
 public:
  explicit ModelTree(QWidget* parent = nullptr);
  void populate(const Document& document);

 signals:
  void layer_toggled(const QString& name, bool visible);
  void layer_color_requested(const QString& name);
  void properties(const QString& html);

 private:
  bool filling_ = false;
};

}  // namespace styk::gui
