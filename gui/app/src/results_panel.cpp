#include "results_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

#include "styk/render/field.hpp"

namespace styk::gui {

ResultsPanel::ResultsPanel(QWidget* parent) : QWidget(parent) {
  auto* form = new QFormLayout(this);
  increment_ = new QComboBox;
  increment_->setObjectName("increment");
  field_ = new QComboBox;
  field_->setObjectName("field");
  field_->addItem("(none)");
  for (const std::string& f : render::field_names()) field_->addItem(QString::fromStdString(f));
  averaging_ = new QComboBox;
  averaging_->setObjectName("averaging");
  averaging_->addItems({"II", "I", "none", "centroid"});
  bands_ = new QSpinBox;
  bands_->setObjectName("bands");
  bands_->setRange(render::kMinBands, render::kMaxBands);
  bands_->setValue(render::kDefaultBands);
  smooth_ = new QCheckBox("Smooth colours");
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
  form->addRow("Increment", increment_);
  form->addRow("Field", field_);
  form->addRow("Averaging", averaging_);
  form->addRow("Colours", bands_);
  form->addRow(QString(), smooth_);
  form->addRow(QString(), deformed_);
  form->addRow(QString(), auto_scale_);
  form->addRow("Scale factor", scale_);
  form->addRow("Path", path_);
  form->addRow(QString(), chart_);
  for (QComboBox* c : {increment_, field_, averaging_})
    connect(c, &QComboBox::currentIndexChanged, this, &ResultsPanel::changed);
  connect(bands_, &QSpinBox::valueChanged, this, &ResultsPanel::changed);
  for (QCheckBox* c : {smooth_, deformed_, auto_scale_})
    connect(c, &QCheckBox::toggled, this, &ResultsPanel::changed);
  connect(scale_, &QLineEdit::editingFinished, this, &ResultsPanel::changed);
  connect(chart_, &QPushButton::clicked, this,
          [this] { emit chart_requested(path_->currentText()); });
}

void ResultsPanel::set_document(const Document& document) {
  const QSignalBlocker block(increment_);
  increment_->clear();
  if (const Results* results = document.results())
    for (const IncrementResult& inc : results->increments)
      increment_->addItem(QString("step %1 inc %2 (t = %3)")
                              .arg(inc.step)
                              .arg(inc.increment)
                              .arg(inc.total_time));
  increment_->setCurrentIndex(increment_->count() - 1);
  path_->clear();
  for (const auto& [name, set] : document.model().nsets) path_->addItem(QString::fromStdString(name));
  setEnabled(document.results() != nullptr);
}

void ResultsPanel::set_field(const QString& field) {
  field_->setCurrentText(field.isEmpty() ? QString("(none)") : field);
}

DisplaySettings ResultsPanel::settings(render::DisplayMode mode) const {
  DisplaySettings s;
  s.mode = mode;
  s.increment = increment_->currentIndex();
  s.field = field_->currentIndex() <= 0 ? std::string() : field_->currentText().toStdString();
  s.averaging = render::parse_averaging(averaging_->currentText().toStdString());
  s.bands = bands_->value();
  s.smooth = smooth_->isChecked();
  s.deformed = deformed_->isChecked();
  s.auto_scale = auto_scale_->isChecked();
  bool ok = false;
  const double factor = scale_->text().toDouble(&ok);
  s.scale = ok && factor >= 0 ? factor : 1.0;
  return s;
}

}  // namespace styk::gui
