#include "dialog_fields.hpp"

#include <QRegularExpression>
#include <cstdlib>

#include "session/validation.hpp"

namespace styk::gui {
namespace {

QStringList split_fields(const FormDialog& f, const QString& key, const QString& label, int count) {
  const QStringList parts =
      QString::fromStdString(f.text(key)).split(QRegularExpression("[\\s,;]+"), Qt::SkipEmptyParts);
  if (parts.size() != count)
    throw InputError({}, label.toStdString() + ": give " + std::to_string(count) +
                             " numbers, not " + std::to_string(parts.size()));
  return parts;
}

}  // namespace

QStringList node_set_names(const Model& m) {
  QStringList names;
  for (const auto& [name, set] : m.nsets) names << QString::fromStdString(name);
  return names;
}
QStringList element_set_names(const Model& m) {
  QStringList names;
  for (const auto& [name, set] : m.elsets) names << QString::fromStdString(name);
  return names;
}
QStringList surface_names(const Model& m) {
  QStringList names;
  for (const auto& [name, s] : m.surfaces) names << QString::fromStdString(name);
  return names;
}
QStringList material_names(const Model& m) {
  QStringList names;
  for (const Material& mat : m.materials) names << QString::fromStdString(mat.name);
  return names;
}
QStringList step_names(const Model& m, bool model_level, const QString& model_level_text) {
  QStringList names;
  if (model_level) names << model_level_text;
  for (std::size_t i = 0; i < m.steps.size(); ++i)
    names << QString("%1 %2").arg(i + 1).arg(QString::fromStdString(m.steps[i].name));
  return names;
}
int step_index(const std::string& entry) { return std::atoi(entry.c_str()) - 1; }

std::vector<double> numbers(const FormDialog& f, const QString& key, const QString& label,
                            int count) {
  std::vector<double> v;
  for (const QString& p : split_fields(f, key, label, count))
    v.push_back(parse_real(p.toStdString(), label.toStdString()));
  return v;
}

std::vector<int> whole_numbers(const FormDialog& f, const QString& key, const QString& label,
                               int count) {
  std::vector<int> v;
  for (const QString& p : split_fields(f, key, label, count))
    v.push_back(parse_integer(p.toStdString(), label.toStdString()));
  return v;
}

}  // namespace styk::gui
