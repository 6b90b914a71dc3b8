// A small form dialog for the model-creation commands: labelled text fields, choices and check
// boxes, each with an objectName (its key) so tests can fill it. OK runs the `accept` function,
// which reads the fields, checks them (session/validation.hpp) and applies the edit; an InputError
// is shown in red inside the dialog, which stays open.
#pragma once

#include <QDialog>
#include <QStringList>
#include <functional>
#include <map>

class QFormLayout;
class QLabel;
class QWidget;

namespace styk::gui {

class FormDialog : public QDialog {
  Q_OBJECT
 public:
  using Accept = std::function<void(const FormDialog&)>;
  FormDialog(const QString& title, const QString& intro, QWidget* parent = nullptr);

  void add_text(const QString& key, const QString& label, const QString& value);
  void add_choice(const QString& key, const QString& label, const QStringList& items,
                  const QString& value = {});
  void add_check(const QString& key, const QString& label, bool value);
  void set_accept(Accept accept) { accept_ = std::move(accept); }

  std::string text(const QString& key) const;  // text field or current choice
  bool checked(const QString& key) const;
  double real(const QString& key, const QString& label) const;  // parse_real
  int integer(const QString& key, const QString& label) const;  // parse_integer
  QString error_text() const;

 public slots:
  void accept() override;

 private:
  QWidget* field(const QString& key) const;
  QFormLayout* form_ = nullptr;
  QLabel* error_ = nullptr;
  std::map<QString, QWidget*> fields_;
  Accept accept_;
};

}  // namespace styk::gui
