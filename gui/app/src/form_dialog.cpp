#include "form_dialog.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>
#include <stdexcept>

#include "session/validation.hpp"

namespace styk::gui {

FormDialog::FormDialog(const QString& title, const QString& intro, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(title);
  auto* layout = new QVBoxLayout(this);
  if (!intro.isEmpty()) {
    auto* label = new QLabel(intro);
    label->setWordWrap(true);
    layout->addWidget(label);
  }
  form_ = new QFormLayout;
  layout->addLayout(form_);
  error_ = new QLabel;
  error_->setObjectName("error");
  error_->setStyleSheet("color: #b00000");
  error_->setWordWrap(true);
  layout->addWidget(error_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  connect(buttons, &QDialogButtonBox::accepted, this, &FormDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &FormDialog::reject);
  layout->addWidget(buttons);
}

void FormDialog::add_text(const QString& key, const QString& label, const QString& value) {
  auto* edit = new QLineEdit(value);
  edit->setObjectName(key);
  form_->addRow(label, edit);
  fields_[key] = edit;
}

void FormDialog::add_choice(const QString& key, const QString& label, const QStringList& items,
                            const QString& value) {
  auto* combo = new QComboBox;
  combo->setObjectName(key);
  combo->addItems(items);
  if (!value.isEmpty()) combo->setCurrentText(value);
  form_->addRow(label, combo);
  fields_[key] = combo;
}

void FormDialog::add_check(const QString& key, const QString& label, bool value) {
  auto* box = new QCheckBox(label);
  box->setObjectName(key);
  box->setChecked(value);
  form_->addRow(QString(), box);
  fields_[key] = box;
}

QWidget* FormDialog::field(const QString& key) const {
  const auto it = fields_.find(key);
  if (it == fields_.end()) throw std::logic_error("no field " + key.toStdString());
  return it->second;
}

std::string FormDialog::text(const QString& key) const {
  QWidget* w = field(key);
  if (auto* edit = qobject_cast<QLineEdit*>(w)) return edit->text().trimmed().toStdString();
  if (auto* combo = qobject_cast<QComboBox*>(w)) return combo->currentText().toStdString();
  return {};
}

bool FormDialog::checked(const QString& key) const {
  auto* box = qobject_cast<QCheckBox*>(field(key));
  return box && box->isChecked();
}

double FormDialog::real(const QString& key, const QString& label) const {
  return parse_real(text(key), label.toStdString());
}

int FormDialog::integer(const QString& key, const QString& label) const {
  return parse_integer(text(key), label.toStdString());
}

QString FormDialog::error_text() const { return error_->text(); }

void FormDialog::accept() {
  try {
    if (accept_) accept_(*this);
  } catch (const InputError& e) {
    error_->setText(QString::fromStdString(e.message()));
    return;
  } catch (const std::exception& e) {
    error_->setText(QString::fromStdString(e.what()));
    return;
  }
  QDialog::accept();
}

}  // namespace styk::gui
