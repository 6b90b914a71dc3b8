// The results controls (issue priority 5): increment, field, averaging, bands or smooth colours,
// deformed shape with an editable scale, and the path chart. Emits changed() on every edit.
#pragma once

#include <QWidget>

#include "session/scene.hpp"

class QComboBox;
class QSpinBox;
class QCheckBox;
class QLineEdit;
class QPushButton;

namespace styk::gui {

class ResultsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ResultsPanel(QWidget* parent = nullptr);
  // Fills the increment list ("step 1 inc 1 (t = 1)") and the node sets for the chart.
  void set_document(const Document& document);
  DisplaySettings settings(render::DisplayMode mode) const;
  void set_field(const QString& field);  // e.g. "S.mises"; "" = none

 signals:
  void changed();
  void chart_requested(const QString& nset);

 private:
  QComboBox* increment_ = nullptr;
  QComboBox* field_ = nullptr;
  QComboBox* averaging_ = nullptr;
  QSpinBox* bands_ = nullptr;
  QCheckBox* smooth_ = nullptr;
  QCheckBox* deformed_ = nullptr;
  QCheckBox* auto_scale_ = nullptr;
  QLineEdit* scale_ = nullptr;
  QComboBox* path_ = nullptr;
  QPushButton* chart_ = nullptr;
};

}  // namespace styk::gui
