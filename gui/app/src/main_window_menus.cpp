// The menus of the main window, one builder per menu, and the File menu's recent files.
#include <QActionGroup>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenuBar>
#include <QSettings>

#include "entry_dialogs.hpp"
#include "geometry_dialogs.hpp"
#include "gl_view.hpp"
#include "interaction_dialogs.hpp"
#include "load_dialogs.hpp"
#include "main_window.hpp"
#include "model_dialogs.hpp"
#include "revolve_dialog.hpp"
#include "styk/mesher/builders.hpp"

namespace styk::gui {

void MainWindow::build_menus() {
  build_file_menu();
  build_edit_menu();
  build_model_menu();
  build_select_menu();
  build_analysis_menu();
  build_view_menu();
}

void MainWindow::build_file_menu() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("&New", QKeySequence::New, this, [this] {
    if (!maybe_save()) return;
    document_.new_model();
    refresh_model();
  });
  file->addAction("&Open...", QKeySequence::Open, this, [this] {
    if (!maybe_save()) return;
    const QString path = QFileDialog::getOpenFileName(
        this, "Open", QString(),
        "Models, results and Gmsh meshes (*.inp *.styk.h5 *.h5 *.msh);;All files (*)");
    if (!path.isEmpty()) open_file(path);
  });
  recent_menu_ = file->addMenu("Open &recent");
  file->addAction("&Save", QKeySequence::Save, this, [this] {
    const QString path = QString::fromStdString(document_.path());
    if (path.endsWith(".inp"))
      save_file(path);
    else {
      const QString chosen =
          QFileDialog::getSaveFileName(this, "Save deck", QString(), "Decks (*.inp)");
      if (!chosen.isEmpty()) save_file(chosen);
    }
  });
  file->addAction("Save &as...", QKeySequence::SaveAs, this, [this] {
    const QString chosen =
        QFileDialog::getSaveFileName(this, "Save deck", QString(), "Decks (*.inp)");
    if (!chosen.isEmpty()) save_file(chosen);
  });
  file->addAction("Open study &charts...", this,
                  [this] {
                    const QString path = QFileDialog::getOpenFileName(
                        this, "Open a study's CSV", QString(), "Study CSV (*.csv);;All files (*)");
                    if (!path.isEmpty()) open_study(path);
                  })
      ->setObjectName("action_open_study");
  file->addAction("&Export view as PNG or BMP...", this, [this] {
    const QString chosen = QFileDialog::getSaveFileName(this, "Export picture", "view.png",
                                                        "PNG (*.png);;BMP (*.bmp)");
    if (!chosen.isEmpty()) export_png(chosen);
  });
  file->addAction("Export &animation...", this,
                  [this] {
                    const QString chosen = QFileDialog::getSaveFileName(
                        this, "Export animation (frames NAME_0000.png ..., NAME.apng)", "anim",
                        "PNG frames (*)");
                    if (!chosen.isEmpty())
                      export_animation(QFileInfo(chosen).absolutePath(),
                                       QFileInfo(chosen).completeBaseName());
                  })
      ->setObjectName("action_export_animation");
  file->addSeparator();
  file->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);
  update_recent_menu();
}

void MainWindow::build_edit_menu() {
  QMenu* edit = menuBar()->addMenu("&Edit");
  undo_ = edit->addAction("&Undo", QKeySequence::Undo, this, [this] {
    document_.undo();
    refresh_model();
  });
  undo_->setObjectName("action_undo");
  redo_ = edit->addAction("&Redo", QKeySequence::Redo, this, [this] {
    document_.redo();
    refresh_model();
  });
  redo_->setObjectName("action_redo");
}

void MainWindow::build_model_menu() {
  QMenu* model = menuBar()->addMenu("&Model");
  const auto dialog_action = [this, model](const QString& text, const QString& name,
                                           FormDialog* (*make)(Document&, QWidget*)) {
    QAction* a = model->addAction(text, this, [this, make] { run_dialog(make(document_, this)); });
    a->setObjectName(name);
  };
  dialog_action("Mesh &block...", "action_block", &make_block_dialog);
  QAction* builder = model->addAction("Model from &builder...", this, [this] {
    QStringList names;
    for (const mesher::BuilderInfo& b : mesher::builder_catalogue())
      names << QString::fromStdString(b.name + "  (" + b.section + " " + b.title + ")");
    bool ok = false;
    const QString chosen = QInputDialog::getItem(this, "Builder", "Model", names, 0, false, &ok);
    if (ok)
      run_dialog(make_builder_dialog(document_, chosen.section(' ', 0, 0).toStdString(), this));
  });
  builder->setObjectName("action_builder");
  model->addSeparator();
  dialog_action("&Material...", "action_material", &make_material_dialog);
  dialog_action("&Section...", "action_section", &make_section_dialog);
  dialog_action("S&tep...", "action_step", &make_step_dialog);
  dialog_action("&Boundary condition...", "action_boundary", &make_boundary_dialog);
  dialog_action("&Concentrated load...", "action_cload", &make_cload_dialog);
  dialog_action("&Pressure...", "action_pressure", &make_pressure_dialog);
  dialog_action("Face fl&ux...", "action_flux", &make_flux_dialog);
  dialog_action("&Revolve...", "action_revolve", &make_revolve_dialog);
  dialog_action("P&lane...", "action_plane", &make_plane_dialog);
  dialog_action("L&ine...", "action_line", &make_line_dialog);
  dialog_action("Shell s&urface...", "action_shell_surface", &make_shell_surface_dialog);
  model->addSeparator();
  dialog_action("C&ontact pair...", "action_contact", &make_new_contact_dialog);
  dialog_action("&Initial temperature...", "action_initial_temperature",
                &make_initial_temperature_dialog);
  dialog_action("&Temperature...", "action_temperature", &make_temperature_dialog);
  dialog_action("&Equation...", "action_equation", &make_equation_dialog);
  dialog_action("Trans&form...", "action_transform", &make_transform_dialog);
  dialog_action("Orient&ation...", "action_orientation", &make_orientation_dialog);
  dialog_action("&Node set from two sets...", "action_common_nodes", &make_common_nodes_dialog);
}

void MainWindow::build_select_menu() {
  QMenu* select = menuBar()->addMenu("Se&lect");
  auto* kinds = new QActionGroup(this);
  const std::pair<const char*, PickKind> kind_list[] = {{"Pick &nodes", PickKind::Node},
                                                        {"Pick &elements", PickKind::Element},
                                                        {"Pick element &faces", PickKind::Face}};
  for (const auto& [text, kind] : kind_list) {
    QAction* a = select->addAction(text, this, [this, k = kind] { view_->set_pick_kind(k); });
    a->setCheckable(true);
    a->setChecked(kind == view_->pick_kind());
    a->setObjectName(QString("action_pick_") + QString::fromStdString(pick_kind_name(kind)));
    kinds->addAction(a);
  }
  select->addAction("&Clear selection", QKeySequence(Qt::Key_Escape), this,
                    [this] { view_->clear_selection(); });
  select
      ->addAction("&Make set from selection...", QKeySequence(Qt::CTRL | Qt::Key_M), this,
                  [this] {
                    bool ok = false;
                    const QString name = QInputDialog::getText(
                        this, "Make set from selection", "Name", QLineEdit::Normal, QString(), &ok);
                    if (ok) make_set_from_selection(name);
                  })
      ->setObjectName("action_make_set");
  select
      ->addAction("New &layer from selection...", this,
                  [this] {
                    bool ok = false;
                    const QString name =
                        QInputDialog::getText(this, "New layer from selection", "Name",
                                              QLineEdit::Normal, QString(), &ok);
                    if (ok) make_layer_from_selection(name);
                  })
      ->setObjectName("action_layer_from_selection");
}

void MainWindow::build_analysis_menu() {
  QMenu* analysis = menuBar()->addMenu("&Analysis");
  analysis->addAction("&Solve", QKeySequence(Qt::Key_F5), this, &MainWindow::start_solve);
  cancel_ = analysis->addAction("&Cancel solve", this, &MainWindow::cancel_solve);
  cancel_->setEnabled(false);
}

void MainWindow::build_view_menu() {
  QMenu* view = menuBar()->addMenu("&View");
  auto* modes = new QActionGroup(this);
  const std::pair<const char*, render::DisplayMode> mode_list[] = {
      {"&Nodes", render::DisplayMode::Points},
      {"&Wireframe", render::DisplayMode::Wireframe},
      {"&Hidden line", render::DisplayMode::HiddenLine},
      {"&Shaded", render::DisplayMode::Shaded},
      {"Shaded with &edges", render::DisplayMode::ShadedEdges}};
  for (const auto& [text, mode] : mode_list) {
    QAction* a = view->addAction(text, this, [this, m = mode] { set_display_mode(m); });
    a->setCheckable(true);
    a->setChecked(mode == mode_);
    modes->addAction(a);
  }
  view->addSeparator();
  for (const char* name : {"iso", "+x", "-x", "+y", "-y", "+z", "-z"})
    view->addAction(QString("View %1").arg(name), this,
                    [this, name] { view_->set_named_view(name); });
  view->addAction("&Fit", QKeySequence(Qt::Key_F), this, [this] { view_->fit(); });
  QAction* perspective =
      view->addAction("&Perspective", this, [this](bool on) { view_->set_perspective(on); });
  perspective->setCheckable(true);
  view->addSeparator();
  // Numbers of the seen nodes / elements (docs/gui.md "Numbers and integration points").
  const auto numbers = [this] {
    set_labels(node_numbers_->isChecked(), element_numbers_->isChecked(),
               numbers_of_selection_->isChecked());
  };
  node_numbers_ = view->addAction("&Node numbers", this, numbers);
  node_numbers_->setObjectName("action_node_numbers");
  element_numbers_ = view->addAction("&Element numbers", this, numbers);
  element_numbers_->setObjectName("action_element_numbers");
  numbers_of_selection_ = view->addAction("Numbers of the selection &only", this, numbers);
  numbers_of_selection_->setObjectName("action_numbers_of_selection");
  for (QAction* a : {node_numbers_, element_numbers_, numbers_of_selection_}) a->setCheckable(true);
  QAction* smooth =
      view->addAction("S&mooth edges", this, [this](bool on) { set_smooth_edges(on); });
  smooth->setObjectName("action_smooth_edges");
  smooth->setCheckable(true);
  view->addSeparator();
  view->addAction("Fi&lter...", this,
                  [this] {
                    FormDialog* dialog = make_filter_dialog(
                        document_.model(), document_.filter(),
                        [this](ElementDisplayFilter f) { set_filter(std::move(f)); }, this);
                    dialog->setAttribute(Qt::WA_DeleteOnClose);
                    dialog->open();
                  })
      ->setObjectName("action_filter");
  view->addAction("&Clear filter", this, [this] { set_filter({}); })
      ->setObjectName("action_clear_filter");
  view->addAction("New layer from &filter...", this,
                  [this] {
                    bool ok = false;
                    const QString name = QInputDialog::getText(
                        this, "New layer from filter", "Name", QLineEdit::Normal, QString(), &ok);
                    if (ok) make_layer_from_filter(name);
                  })
      ->setObjectName("action_layer_from_filter");
}

void MainWindow::add_recent(const QString& path) {
  QSettings settings("Styk", "styk-gui");
  QStringList files = settings.value("recent").toStringList();
  files.removeAll(QFileInfo(path).absoluteFilePath());
  files.prepend(QFileInfo(path).absoluteFilePath());
  while (files.size() > 10) files.removeLast();
  settings.setValue("recent", files);
  update_recent_menu();
}

void MainWindow::update_recent_menu() {
  recent_menu_->clear();
  const QStringList files = QSettings("Styk", "styk-gui").value("recent").toStringList();
  for (const QString& f : files)
    recent_menu_->addAction(f, this, [this, f] {
      if (maybe_save()) open_file(f);
    });
  recent_menu_->setEnabled(!files.isEmpty());
}

}  // namespace styk::gui
