// The results controls (issue priority 5, issue 7): increment ("step 2, increment 3, time 0.6"),
// the fields that increment holds, averaging, bands or smooth colours, values at the integration
// points, which faces show a contact field and its unrolled map, deformed shape with an editable
// scale, the path chart, the value-vs-increment chart of the picked node, and the animation
// (kind, frames, play). Emits changed() on every display edit.
#pragma once

#include <QWidget>

#include "session/animation.hpp"
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
  // Fills the increment list and the node sets for the chart, and the fields of the increment.
  void set_document(const Document& document);
  DisplaySettings settings(render::DisplayMode mode) const;
  // e.g. "S.mises"; "" = none. Remembered: when the increment shown lacks it (CPRESS before
  // contact), "(none)" is shown until an increment that holds it is chosen again.
  void set_field(const QString& field);
  void set_increment(int index);  // index into Results::increments
  AnimationKind animation_kind() const;
  int animation_frames() const;
  void set_animating(bool on);  // the Animate button's state, without signals

 signals:
  void changed();
  void chart_requested(const QString& nset);
  void history_requested();
  void animate_toggled(bool on);

 private:
  void fill_fields();

  const Document* document_ = nullptr;
  QString wanted_field_;
  QComboBox* increment_ = nullptr;
  QComboBox* field_ = nullptr;
  QComboBox* fibre_ = nullptr;  // the shells' fibre: top, middle, bottom
  QComboBox* averaging_ = nullptr;
  QSpinBox* bands_ = nullptr;
  QCheckBox* smooth_ = nullptr;
  QCheckBox* deformed_ = nullptr;
  QCheckBox* auto_scale_ = nullptr;
  QLineEdit* scale_ = nullptr;
  QComboBox* path_ = nullptr;
  QPushButton* chart_ = nullptr;
  QPushButton* history_ = nullptr;
  QCheckBox* ip_values_ = nullptr;
  QComboBox* contact_faces_ = nullptr;
  QCheckBox* unrolled_ = nullptr;
  QComboBox* animation_kind_ = nullptr;
  QSpinBox* animation_frames_ = nullptr;
  QPushButton* animate_ = nullptr;
};

}  // namespace styk::gui
