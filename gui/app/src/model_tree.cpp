#include "model_tree.hpp"

#include <QColor>
#include <QKeyEvent>
#include <QMenu>
#include <QPixmap>

#include "entry_dialogs.hpp"
#include "session/load_groups.hpp"

namespace styk::gui {
namespace {

constexpr int kKindRole = Qt::UserRole;       // "layer" for layer items
constexpr int kInfoRole = Qt::UserRole + 1;   // property text (HTML)
constexpr int kLayerRole = Qt::UserRole + 2;  // layer name
constexpr int kEntryRole = Qt::UserRole + 3;  // EntryKind + 1 (0: not a model entry)
constexpr int kIndexRole = Qt::UserRole + 4;
constexpr int kNameRole = Qt::UserRole + 5;
constexpr int kItemRole = Qt::UserRole + 6;  // the group of a per-node list, -1: the whole list

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

QTreeWidgetItem* entry(QTreeWidgetItem* item, EntryKind kind, int index,
                       const std::string& name = {}, int group = -1) {
  item->setData(0, kEntryRole, static_cast<int>(kind) + 1);
  item->setData(0, kIndexRole, index);
  item->setData(0, kNameRole, q(name));
  item->setData(0, kItemRole, group);
  return item;
}

// The groups of a per-node list (what one dialog made) as children of its item.
void add_groups(const Model& m, QTreeWidgetItem* list, EntryKind kind, int index) {
  const std::vector<std::string> labels = group_labels(m, Entry{kind, index, {}, -1});
  for (int g = 0; g < static_cast<int>(labels.size()); ++g)
    entry(leaf(list, q(labels[g]),
               QString("%1<br>double-click: edit; Delete: remove").arg(q(labels[g]))),
          kind, index, {}, g);
}

const char* step_kind_text(StepKind kind) {
  switch (kind) {
    case StepKind::HeatTransfer:
      return "steady heat transfer";
    case StepKind::ElectricConduction:
      return "electric conduction";
    case StepKind::Static:
      break;
  }
  return "static";
}

QString conductivity_text(const std::optional<std::array<double, 3>>& k) {
  if (!k) return "-";
  if ((*k)[0] == (*k)[1] && (*k)[1] == (*k)[2]) return QString::number((*k)[0]);
  return QString("%1 %2 %3").arg((*k)[0]).arg((*k)[1]).arg((*k)[2]);
}

QString friction_text(const Model& m, const ContactPair& p) {
  const auto it = m.surface_interactions.find(p.interaction);
  if (it == m.surface_interactions.end() || !it->second.friction) return "frictionless";
  const Friction& f = *it->second.friction;
  if (f.kind == Friction::Kind::Rough) return "rough";
  if (f.kind == Friction::Kind::Anisotropic) return QString("mu1 %1, mu2 %2").arg(f.mu).arg(f.mu2);
  return QString("mu %1").arg(f.mu);
}

void add_step(const Model& m, QTreeWidgetItem* steps, const Step& s, int i) {
  QTreeWidgetItem* item = entry(
      leaf(steps,
           QString("%1 %2 — %3%4 BC, %5 CLOAD, %6 DLOAD%7")
               .arg(i + 1)
               .arg(q(s.name))
               .arg(s.kind == StepKind::Static ? QString() : QString(step_kind_text(s.kind)) + ", ")
               .arg(s.boundaries.size())
               .arg(s.cloads.size() + s.cfluxes.size())
               .arg(s.dloads.size())
               .arg(s.dfluxes.empty() ? QString() : QString(", %1 DFLUX").arg(s.dfluxes.size())),
           QString("<b>Step %1</b><br>%2, initial increment %3, total time %4<br>%5 boundary "
                   "dofs, %6 concentrated loads, %7 face loads, %8 nodal temperatures, %9 nodal "
                   "fluxes, %10 face fluxes")
               .arg(q(s.name))
               .arg(step_kind_text(s.kind))
               .arg(s.procedure.initial_increment)
               .arg(s.procedure.total_time)
               .arg(s.boundaries.size())
               .arg(s.cloads.size())
               .arg(s.dloads.size())
               .arg(s.temperatures.size())
               .arg(s.cfluxes.size())
               .arg(s.dfluxes.size())),
      EntryKind::Step, i);
  const char* fluxes =
      s.kind == StepKind::ElectricConduction ? "nodal currents" : "nodal heat flows";
  const std::pair<EntryKind, std::pair<const char*, std::size_t>> lists[] = {
      {EntryKind::StepBoundaries, {"boundary conditions", s.boundaries.size()}},
      {EntryKind::StepCloads, {"concentrated loads", s.cloads.size()}},
      {EntryKind::StepFluxes, {fluxes, s.cfluxes.size()}},
      {EntryKind::StepDloads, {"pressures", s.dloads.size()}},
      {EntryKind::StepDfluxes, {"face fluxes", s.dfluxes.size()}},
      {EntryKind::StepTemperatures, {"temperatures", s.temperatures.size()}}};
  for (const auto& [kind, what] : lists)
    if (what.second > 0)
      add_groups(m,
                 entry(leaf(item, QString("%1: %2").arg(what.first).arg(what.second),
                            QString("%1 %2 of step %3 (Delete removes them all; the entries "
                                    "below are what each dialog made)")
                                .arg(what.second)
                                .arg(what.first)
                                .arg(q(s.name))),
                       kind, i),
                 kind, i);
}

}  // namespace

ModelTree::ModelTree(QWidget* parent) : QTreeWidget(parent) {
  setHeaderLabel("Model");
  setContextMenuPolicy(Qt::CustomContextMenu);
  connect(this, &QWidget::customContextMenuRequested, this, &ModelTree::show_menu);
  connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int) {
    if (filling_ || item->data(0, kKindRole).toString() != "layer") return;
    emit layer_toggled(item->data(0, kLayerRole).toString(), item->checkState(0) == Qt::Checked);
  });
  connect(this, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item, int) {
    if (item->data(0, kKindRole).toString() == "layer")
      emit layer_color_requested(item->data(0, kLayerRole).toString());
    else if (const auto e = entry_of(item); e && has_entry_dialog(*e))
      emit edit_requested(*e);
  });
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (item) emit properties(item->data(0, kInfoRole).toString());
  });
}

std::optional<Entry> ModelTree::entry_of(const QTreeWidgetItem* item) {
  if (!item) return std::nullopt;
  const int kind = item->data(0, kEntryRole).toInt();
  if (kind <= 0) return std::nullopt;
  return Entry{static_cast<EntryKind>(kind - 1), item->data(0, kIndexRole).toInt(),
               item->data(0, kNameRole).toString().toStdString(), item->data(0, kItemRole).toInt()};
}

QTreeWidgetItem* ModelTree::find_item(const QString& text) const {
  for (QTreeWidgetItemIterator it(const_cast<ModelTree*>(this)); *it; ++it)
    if ((*it)->text(0).startsWith(text)) return *it;
  return nullptr;
}

void ModelTree::keyPressEvent(QKeyEvent* event) {
  if (event->key() == Qt::Key_Delete) {
    if (const auto e = entry_of(currentItem())) {
      emit delete_requested(*e);
      return;
    }
  }
  QTreeWidget::keyPressEvent(event);
}

void ModelTree::show_menu(const QPoint& at) {
  const auto e = entry_of(itemAt(at));
  if (!e) return;
  QMenu menu(this);
  if (has_entry_dialog(*e)) menu.addAction("Edit...", this, [this, e] { emit edit_requested(*e); });
  menu.addAction("Delete", this, [this, e] { emit delete_requested(*e); });
  menu.exec(viewport()->mapToGlobal(at));
}

void ModelTree::populate(const Document& doc) {
  filling_ = true;
  clear();
  const Model& m = doc.model();
  QTreeWidgetItem* layers = group(this, "Layers", int(doc.layers().layers().size()));
  for (const render::Layer& l : doc.layers().layers()) {
    QPixmap swatch(12, 12);
    swatch.fill(QColor::fromRgbF(l.color.r, l.color.g, l.color.b));
    QTreeWidgetItem* item =
        leaf(layers, q(l.name) + QString(" — %1 elements").arg(l.elements.size()),
             QString("<b>Layer %1</b><br>%2 elements<br>double-click: colour")
                 .arg(q(l.name))
                 .arg(l.elements.size()));
    item->setIcon(0, swatch);
    item->setData(0, kKindRole, "layer");
    item->setData(0, kLayerRole, q(l.name));
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(0, l.visible ? Qt::Checked : Qt::Unchecked);
  }
  QTreeWidgetItem* nsets = group(this, "Node sets", int(m.nsets.size()));
  for (const auto& [name, s] : m.nsets)
    entry(leaf(nsets, q(name),
               QString("<b>Node set %1</b><br>%2 nodes").arg(q(name)).arg(s.nodes.size())),
          EntryKind::NodeSet, -1, name);
  QTreeWidgetItem* elsets = group(this, "Element sets", int(m.elsets.size()));
  for (const auto& [name, s] : m.elsets)
    entry(leaf(elsets, q(name),
               QString("<b>Element set %1</b><br>%2 elements").arg(q(name)).arg(s.elements.size())),
          EntryKind::ElementSet, -1, name);
  QTreeWidgetItem* surfaces = group(this, "Surfaces", int(m.surfaces.size()));
  for (const auto& [name, s] : m.surfaces)
    entry(leaf(surfaces, q(name),
               QString("<b>Surface %1</b><br>%2 faces, %3 nodes")
                   .arg(q(name))
                   .arg(s.faces.size())
                   .arg(s.nodes.size())),
          EntryKind::Surface, -1, name);
  QTreeWidgetItem* materials = group(this, "Materials", int(m.materials.size()));
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const Material& mat = m.materials[i];
    entry(leaf(materials, q(mat.name),
               QString("<b>Material %1</b><br>E = %2<br>nu = %3<br>density = %4<br>expansion = "
                       "%5<br>conductivity = %6<br>electrical conductivity = %7")
                   .arg(q(mat.name))
                   .arg(mat.young ? QString::number(*mat.young) : QString("-"))
                   .arg(mat.poisson ? QString::number(*mat.poisson) : QString("-"))
                   .arg(mat.density ? QString::number(*mat.density) : QString("-"))
                   .arg(mat.expansion ? QString::number(*mat.expansion) : QString("-"))
                   .arg(conductivity_text(mat.conductivity))
                   .arg(conductivity_text(mat.electrical_conductivity))),
          EntryKind::Material, int(i));
  }
  QTreeWidgetItem* sections = group(this, "Sections", int(m.sections.size()));
  for (std::size_t i = 0; i < m.sections.size(); ++i) {
    const Section& s = m.sections[i];
    entry(leaf(sections, q(s.elset) + " → " + q(s.material),
               QString("<b>Solid section</b><br>element set %1<br>material %2")
                   .arg(q(s.elset), q(s.material))),
          EntryKind::Section, int(i));
  }
  QTreeWidgetItem* steps = group(this, "Steps", int(m.steps.size()));
  if (!m.boundaries.empty())
    add_groups(
        m,
        entry(leaf(steps, QString("boundary conditions (all steps): %1").arg(m.boundaries.size()),
                   QString("%1 prescribed dofs held in every step").arg(m.boundaries.size())),
              EntryKind::ModelBoundaries, -1),
        EntryKind::ModelBoundaries, -1);
  if (!m.initial_temperatures.empty())
    add_groups(
        m,
        entry(leaf(steps, QString("initial temperatures: %1").arg(m.initial_temperatures.size()),
                   QString("*INITIAL CONDITIONS, TYPE=TEMPERATURE at %1 nodes")
                       .arg(m.initial_temperatures.size())),
              EntryKind::InitialTemperatures, -1),
        EntryKind::InitialTemperatures, -1);
  for (std::size_t i = 0; i < m.steps.size(); ++i) add_step(m, steps, m.steps[i], int(i));
  QTreeWidgetItem* contact = group(this, "Contact pairs", int(m.contact_pairs.size()));
  for (std::size_t i = 0; i < m.contact_pairs.size(); ++i) {
    const ContactPair& p = m.contact_pairs[i];
    entry(leaf(contact, q(p.slave) + " / " + q(p.master) + " — " + friction_text(m, p),
               QString("<b>Contact pair</b><br>slave %1<br>master %2<br>interaction %3: %4%5")
                   .arg(q(p.slave), q(p.master), q(p.interaction), friction_text(m, p))
                   .arg(p.clearance ? QString("<br>clearance %1").arg(*p.clearance) : QString())),
          EntryKind::ContactPair, int(i));
  }
  if (!m.orientations.empty()) {
    QTreeWidgetItem* orientations = group(this, "Orientations", int(m.orientations.size()));
    for (const auto& [name, o] : m.orientations) {
      const bool cylindrical = o.axes.system == CoordinateSystem::Cylindrical;
      const auto point = [](const Vec3& p) {
        return QString("(%1, %2, %3)").arg(p[0]).arg(p[1]).arg(p[2]);
      };
      entry(leaf(orientations, q(name) + " — " + (cylindrical ? "cylindrical" : "rectangular"),
                 QString("<b>*ORIENTATION %1</b><br>%2<br>a = %3<br>b = %4")
                     .arg(q(name), cylindrical ? "cylindrical" : "rectangular", point(o.axes.a),
                          point(o.axes.b))),
            EntryKind::Orientation, -1, name);
    }
  }
  if (!m.equations.empty() || !m.transforms.empty()) {
    QTreeWidgetItem* constraints =
        group(this, "Constraints", int(m.equations.size() + m.transforms.size()));
    for (std::size_t i = 0; i < m.equations.size(); ++i)
      entry(leaf(constraints,
                 QString("equation %1 — %2 terms").arg(i + 1).arg(m.equations[i].terms.size()),
                 QString("<b>*EQUATION</b> %1 terms").arg(m.equations[i].terms.size())),
            EntryKind::Equation, int(i));
    for (std::size_t i = 0; i < m.transforms.size(); ++i) {
      const Transform& t = m.transforms[i];
      const QString system =
          t.axes.system == CoordinateSystem::Cylindrical ? "cylindrical" : "rectangular";
      entry(leaf(constraints, "transform " + q(t.nset) + " — " + system,
                 QString("<b>*TRANSFORM</b> on %1, %2").arg(q(t.nset), system)),
            EntryKind::Transform, int(i));
    }
  }
  const Results* r = doc.results();
  QTreeWidgetItem* results = group(this, "Results increments", r ? int(r->increments.size()) : 0);
  if (r)
    for (const IncrementResult& inc : r->increments)
      leaf(results, QString("step %1 increment %2").arg(inc.step).arg(inc.increment),
           QString("<b>Step %1, increment %2</b><br>step time %3, total time %4<br>file %5")
               .arg(inc.step)
               .arg(inc.increment)
               .arg(inc.step_time)
               .arg(inc.total_time)
               .arg(q(doc.results_path())));
  filling_ = false;
}

}  // namespace styk::gui
