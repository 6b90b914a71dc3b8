#include "results_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>

#include "session/results_navigation.hpp"
#include "styk/render/field.hpp"

namespace styk::gui {

ResultsPanel::ResultsPanel(QWidget* parent) : QWidget(parent) {
  auto* form = new QFormLayout(this);
  increment_ = new QComboBox;
  increment_->setObjectName("increment");
  field_ = new QComboBox;
  field_->setObjectName("field");
  averaging_ = new QComboBox;
  averaging_->setObjectName("averaging");
  averaging_->addItems({"II", "I", "none", "centroid"});
  fibre_ = new QComboBox;
  fibre_->setObjectName("fibre");
  fibre_->addItems({"top", "middle", "bottom"});
  bands_ = new QSpinBox;
  bands_->setObjectName("bands");
  bands_->setRange(render::kMinBands, render::kMaxBands);
  bands_->setValue(render::kDefaultBands);
  smooth_ = new QCheckBox("Smooth colours");
  ip_values_ = new QCheckBox("Values at integration points");
  ip_values_->setObjectName("ip_values");
  contact_faces_ = new QComboBox;
  contact_faces_->setObjectName("contact_faces");
  // The order of render::FieldFaces.
  contact_faces_->addItems({"automatic", "contact faces only", "all faces"});
  unrolled_ = new QCheckBox("Unrolled contact map");
  unrolled_->setObjectName("unrolled");
  deformed_ = new QCheckBox("Deformed shape");
  deformed_->setChecked(true);
  auto_scale_ = new QCheckBox("Automatic scale");
  auto_scale_->setChecked(true);
  scale_ = new QLineEdit("1");
  scale_->setObjectName("scale");
  path_ = new QComboBox;
  path_->setObjectName("path");
  chart_ = new QPushButton("X-Y chart along node set");
  chart_->setObjectName("chart");
  history_ = new QPushButton("Value vs increment at picked node");
  history_->setObjectName("history");
  animation_kind_ = new QComboBox;
  animation_kind_->setObjectName("animation_kind");
  animation_kind_->addItems({"deformation scale 0 to s", "over the increments"});
  animation_frames_ = new QSpinBox;
  animation_frames_->setObjectName("animation_frames");
  animation_frames_->setRange(kMinAnimationFrames, kMaxAnimationFrames);
  animation_frames_->setValue(12);
  animate_ = new QPushButton("Animate");
  animate_->setObjectName("animate");
  animate_->setCheckable(true);
  form->addRow("Increment", increment_);
  form->addRow("Field", field_);
  form->addRow("Averaging", averaging_);
  form->addRow("Shell fibre", fibre_);
  form->addRow("Colours", bands_);
  form->addRow(QString(), smooth_);
  form->addRow(QString(), ip_values_);
  form->addRow("Contact faces", contact_faces_);
  form->addRow(QString(), unrolled_);
  form->addRow(QString(), deformed_);
  form->addRow(QString(), auto_scale_);
  form->addRow("Scale factor", scale_);
  form->addRow("Path", path_);
  form->addRow(QString(), chart_);
  form->addRow(QString(), history_);
  form->addRow("Animation", animation_kind_);
  form->addRow("Frames", animation_frames_);
  form->addRow(QString(), animate_);
  fill_fields();
  connect(increment_, &QComboBox::currentIndexChanged, this, [this] {
    fill_fields();
    emit changed();
  });
  connect(field_, &QComboBox::currentIndexChanged, this, [this] {
    wanted_field_ = field_->currentIndex() <= 0 ? QString() : field_->currentText();
    emit changed();
  });
  connect(averaging_, &QComboBox::currentIndexChanged, this, &ResultsPanel::changed);
  connect(fibre_, &QComboBox::currentIndexChanged, this, &ResultsPanel::changed);
  connect(bands_, &QSpinBox::valueChanged, this, &ResultsPanel::changed);
  for (QCheckBox* c : {smooth_, deformed_, auto_scale_, ip_values_, unrolled_})
    connect(c, &QCheckBox::toggled, this, &ResultsPanel::changed);
  connect(contact_faces_, &QComboBox::currentIndexChanged, this, &ResultsPanel::changed);
  connect(scale_, &QLineEdit::editingFinished, this, &ResultsPanel::changed);
  connect(chart_, &QPushButton::clicked, this,
          [this] { emit chart_requested(path_->currentText()); });
  connect(history_, &QPushButton::clicked, this, &ResultsPanel::history_requested);
  connect(animate_, &QPushButton::toggled, this, &ResultsPanel::animate_toggled);
}

void ResultsPanel::set_document(const Document& document) {
  document_ = &document;
  {
    const QSignalBlocker block(increment_);
    increment_->clear();
    if (const Results* results = document.results())
      for (const std::string& label : increment_labels(*results))
        increment_->addItem(QString::fromStdString(label));
    increment_->setCurrentIndex(increment_->count() - 1);
  }
  fill_fields();
  path_->clear();
  for (const auto& [name, set] : document.model().nsets)
    path_->addItem(QString::fromStdString(name));
  setEnabled(document.results() != nullptr);
}

// The fields of the chosen increment (every field without results), keeping the wanted one.
void ResultsPanel::fill_fields() {
  std::vector<std::string> names = render::field_names();
  const Results* results = document_ ? document_->results() : nullptr;
  const int index = increment_->currentIndex();
  if (results && index >= 0 && index < int(results->increments.size()))
    names = available_fields(document_->model(), results->increments[index]);
  const QSignalBlocker block(field_);
  field_->clear();
  field_->addItem("(none)");
  for (const std::string& f : names) field_->addItem(QString::fromStdString(f));
  const int wanted = wanted_field_.isEmpty() ? 0 : field_->findText(wanted_field_);
  field_->setCurrentIndex(std::max(0, wanted));
}

void ResultsPanel::set_field(const QString& field) {
  wanted_field_ = field;
  const QSignalBlocker block(field_);
  field_->setCurrentIndex(std::max(0, field.isEmpty() ? 0 : field_->findText(field)));
}

void ResultsPanel::set_increment(int index) { increment_->setCurrentIndex(index); }

AnimationKind ResultsPanel::animation_kind() const {
  return animation_kind_->currentIndex() == 1 ? AnimationKind::Increments : AnimationKind::Scale;
}

int ResultsPanel::animation_frames() const { return animation_frames_->value(); }

void ResultsPanel::set_animating(bool on) {
  const QSignalBlocker block(animate_);
  animate_->setChecked(on);
}

DisplaySettings ResultsPanel::settings(render::DisplayMode mode) const {
  DisplaySettings s;
  s.mode = mode;
  s.increment = increment_->currentIndex();
  s.field = field_->currentIndex() <= 0 ? std::string() : field_->currentText().toStdString();
  s.averaging = render::parse_averaging(averaging_->currentText().toStdString());
  s.shell_fibre = render::parse_shell_fibre(fibre_->currentText().toStdString());
  s.bands = bands_->value();
  s.smooth = smooth_->isChecked();
  s.ip_values = ip_values_->isChecked();
  s.field_faces = static_cast<render::FieldFaces>(contact_faces_->currentIndex());
  s.unrolled = unrolled_->isChecked();
  s.deformed = deformed_->isChecked();
  s.auto_scale = auto_scale_->isChecked();
  bool ok = false;
  const double factor = scale_->text().toDouble(&ok);
  s.scale = ok && factor >= 0 ? factor : 1.0;
  return s;
}

}  // namespace styk::gui
