#include "model_tree.hpp"

#include <QColor>
#include <QPixmap>

namespace styk::gui {
namespace {

constexpr int kKindRole = Qt::UserRole;      // "layer" for layer items
constexpr int kInfoRole = Qt::UserRole + 1;  // property text (HTML)

QTreeWidgetItem* group(QTreeWidget* tree, const QString& name, int count) {
  auto* item = new QTreeWidgetItem(tree, {QString("%1 (%2)").arg(name).arg(count)});
  item->setExpanded(true);
  return item;
}

QTreeWidgetItem* leaf(QTreeWidgetItem* parent, const QString& text, const QString& info) {
  auto* item = new QTreeWidgetItem(parent, {text});
  item->setData(0, kInfoRole, info);
  return item;
}

QString q(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

ModelTree::ModelTree(QWidget* parent) : QTreeWidget(parent) {
  setHeaderLabel("Model");
  connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int) {
    if (filling_ || item->data(0, kKindRole).toString() != "layer") return;
    emit layer_toggled(item->data(0, kKindRole + 2).toString(), item->checkState(0) == Qt::Checked);
  });
  connect(this, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item, int) {
    if (item->data(0, kKindRole).toString() == "layer")
      emit layer_color_requested(item->data(0, kKindRole + 2).toString());
  });
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (item) emit properties(item->data(0, kInfoRole).toString());
  });
}

void ModelTree::populate(const Document& doc) {
  filling_ = true;
  clear();
  const Model& m = doc.model();
  QTreeWidgetItem* layers = group(this, "Layers", int(doc.layers().layers().size()));
  for (const render::Layer& l : doc.layers().layers()) {
    QPixmap swatch(12, 12);
    swatch.fill(QColor::fromRgbF(l.color.r, l.color.g, l.color.b));
    QTreeWidgetItem* item = leaf(layers, q(l.name) + QString(" — %1 elements").arg(l.elements.size()),
                                 QString("<b>Layer %1</b><br>%2 elements<br>double-click: colour")
                                     .arg(q(l.name)).arg(l.elements.size()));
    item->setIcon(0, swatch);
    item->setData(0, kKindRole, "layer");
    item->setData(0, kKindRole + 2, q(l.name));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(0, l.visible ? Qt::Checked : Qt::Unchecked);
  }
  QTreeWidgetItem* nsets = group(this, "Node sets", int(m.nsets.size()));
  for (const auto& [name, s] : m.nsets)
    leaf(nsets, q(name), QString("<b>Node set %1</b><br>%2 nodes").arg(q(name)).arg(s.nodes.size()));
  QTreeWidgetItem* elsets = group(this, "Element sets", int(m.elsets.size()));
  for (const auto& [name, s] : m.elsets)
    leaf(elsets, q(name),
         QString("<b>Element set %1</b><br>%2 elements").arg(q(name)).arg(s.elements.size()));
  QTreeWidgetItem* surfaces = group(this, "Surfaces", int(m.surfaces.size()));
  for (const auto& [name, s] : m.surfaces)
    leaf(surfaces, q(name),
         QString("<b>Surface %1</b><br>%2 faces, %3 nodes").arg(q(name)).arg(s.faces.size()).arg(s.nodes.size()));
  QTreeWidgetItem* materials = group(this, "Materials", int(m.materials.size()));
  for (const Material& mat : m.materials)
    leaf(materials, q(mat.name),
         QString("<b>Material %1</b><br>E = %2<br>nu = %3<br>density = %4")
             .arg(q(mat.name))
             .arg(mat.young ? QString::number(*mat.young) : QString("-"))
             .arg(mat.poisson ? QString::number(*mat.poisson) : QString("-"))
             .arg(mat.density ? QString::number(*mat.density) : QString("-")));
  QTreeWidgetItem* sections = group(this, "Sections", int(m.sections.size()));
  for (const Section& s : m.sections)
    leaf(sections, q(s.elset) + " → " + q(s.material),
         QString("<b>Solid section</b><br>element set %1<br>material %2").arg(q(s.elset), q(s.material)));
  QTreeWidgetItem* steps = group(this, "Steps", int(m.steps.size()));
  if (!m.boundaries.empty())
    leaf(steps, QString("boundary conditions (all steps): %1").arg(m.boundaries.size()),
         QString("%1 prescribed dofs held in every step").arg(m.boundaries.size()));
  for (std::size_t i = 0; i < m.steps.size(); ++i) {
    const Step& s = m.steps[i];
    leaf(steps,
         QString("%1 %2 — %3 BC, %4 CLOAD, %5 DLOAD")
             .arg(i + 1).arg(q(s.name)).arg(s.boundaries.size()).arg(s.cloads.size()).arg(s.dloads.size()),
         QString("<b>Step %1</b><br>static, initial increment %2, total time %3<br>%4 boundary "
                 "dofs, %5 concentrated loads, %6 face loads")
             .arg(q(s.name)).arg(s.procedure.initial_increment).arg(s.procedure.total_time)
             .arg(s.boundaries.size()).arg(s.cloads.size()).arg(s.dloads.size()));
  }
  const Results* r = doc.results();
  QTreeWidgetItem* results = group(this, "Results increments", r ? int(r->increments.size()) : 0);
  if (r)
    for (const IncrementResult& inc : r->increments)
      leaf(results, QString("step %1 increment %2").arg(inc.step).arg(inc.increment),
           QString("<b>Step %1, increment %2</b><br>step time %3, total time %4<br>file %5")
               .arg(inc.step).arg(inc.increment).arg(inc.step_time).arg(inc.total_time)
               .arg(q(doc.results_path())));
  filling_ = false;
}

}  // namespace styk::gui
