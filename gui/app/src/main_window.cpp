#include "main_window.hpp"

#include <QCloseEvent>
#include <QColorDialog>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QTextBrowser>
#include <fstream>

#include "entry_dialogs.hpp"
#include "gl_view.hpp"
#include "model_tree.hpp"
#include "path_chart.hpp"
#include "results_panel.hpp"
#include "session/layer_edits.hpp"
#include "session/results_navigation.hpp"
#include "session/selection_info.hpp"
#include "session/selection_sets.hpp"
#include "solve_runner.hpp"
#include "study_chart_window.hpp"
#include "styk/io/results_file.hpp"
#include "styk/studies/results/run_record.hpp"

namespace styk::gui {

MainWindow::MainWindow(const ElementRegistry& registry, QWidget* parent)
    : QMainWindow(parent), document_(registry) {
  view_ = new GlView;
  setCentralWidget(view_);
  tree_ = new ModelTree;
  auto* tree_dock = new QDockWidget("Model", this);
  tree_dock->setObjectName("model_dock");
  tree_dock->setWidget(tree_);
  addDockWidget(Qt::LeftDockWidgetArea, tree_dock);
  properties_ = new QTextBrowser;
  auto* properties_dock = new QDockWidget("Properties", this);
  properties_dock->setObjectName("properties_dock");
  properties_dock->setWidget(properties_);
  addDockWidget(Qt::RightDockWidgetArea, properties_dock);
  results_ = new ResultsPanel;
  auto* results_dock = new QDockWidget("Results", this);
  results_dock->setObjectName("results_dock");
  results_dock->setWidget(results_);
  addDockWidget(Qt::RightDockWidgetArea, results_dock);
  log_ = new QPlainTextEdit;
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(5000);
  auto* log_dock = new QDockWidget("Log", this);
  log_dock->setObjectName("log_dock");
  log_dock->setWidget(log_);
  addDockWidget(Qt::BottomDockWidgetArea, log_dock);
  progress_ = new QProgressBar;
  progress_->setRange(0, 100);
  progress_->setMaximumWidth(220);
  probe_ = new QLabel;
  statusBar()->addWidget(probe_, 1);
  statusBar()->addPermanentWidget(progress_);

  solver_ = std::make_unique<SolveRunner>(SolveRunner::locate_styk_program());
  connect(solver_.get(), &SolveRunner::log, this, &MainWindow::log);
  connect(solver_.get(), &SolveRunner::progress, this, [this](int percent, const QString& phase) {
    progress_->setValue(percent);
    progress_->setFormat(phase + " %p%");
  });
  connect(solver_.get(), &SolveRunner::finished, this, &MainWindow::on_solve_finished);
  connect(view_, &GlView::probed, probe_, &QLabel::setText);
  connect(view_, &GlView::selection_changed, this, &MainWindow::show_selection);
  connect(view_, &GlView::animation_frame, probe_, &QLabel::setText);
  connect(results_, &ResultsPanel::history_requested, this, &MainWindow::show_node_history);
  connect(results_, &ResultsPanel::animate_toggled, this, [this](bool on) {
    view_->stop_animation();
    if (on) try {
        view_->play_animation(std::make_unique<SceneAnimation>(document_, display_settings(),
                                                               results_->animation_kind(),
                                                               results_->animation_frames()),
                              100);
      } catch (const InputError& e) {
        results_->set_animating(false);
        show_error("Animate", QString::fromStdString(e.message()));
      }
    if (!on) refresh_scene();
  });
  connect(tree_, &ModelTree::properties, properties_, &QTextBrowser::setHtml);
  connect(tree_, &ModelTree::edit_requested, this, [this](const Entry& entry) {
    run_dialog(make_entry_dialog(document_, entry, view_->scene().selection(), this));
  });
  connect(tree_, &ModelTree::delete_requested, this, [this](const Entry& entry) {
    try {
      document_.apply(delete_command(document_.model(), entry));
    } catch (const InputError& e) {
      show_error("Delete", QString::fromStdString(e.message()));
      return;
    }
    refresh_model();
  });
  connect(tree_, &ModelTree::layer_toggled, this, [this](const QString& name, bool visible) {
    document_.layers().set_visible(name.toStdString(), visible);
    refresh_scene();
  });
  connect(tree_, &ModelTree::layer_color_requested, this, [this](const QString& name) {
    const render::Rgb c = document_.layers().layer(name.toStdString()).color;
    const QColor chosen = QColorDialog::getColor(QColor::fromRgbF(c.r, c.g, c.b), this);
    if (!chosen.isValid()) return;
    document_.layers().set_color(
        name.toStdString(), {float(chosen.redF()), float(chosen.greenF()), float(chosen.blueF())});
    tree_->populate(document_);
    refresh_scene();
  });
  connect(results_, &ResultsPanel::changed, this, &MainWindow::refresh_scene);
  connect(results_, &ResultsPanel::chart_requested, this, [this](const QString& nset) {
    try {
      const auto points =
          field_along_node_set(view_->scene(), document_.model(), nset.toStdString());
      QDialog* chart =
          make_path_chart(points, QString::fromStdString(view_->scene().field()->name), nset, this);
      chart->show();
    } catch (const InputError& e) {
      show_error("X-Y chart", QString::fromStdString(e.message()));
    }
  });
  build_menus();
  resize(1280, 820);
  refresh_model();
  start_autosave();
}

MainWindow::~MainWindow() = default;

void MainWindow::run_dialog(QDialog* dialog) {
  if (!dialog) return;
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, &MainWindow::refresh_model);
  dialog->open();
}

bool MainWindow::open_file(const QString& path) {
  try {
    if (path.endsWith(".h5")) {
      document_.open_results(path.toStdString());
    } else if (path.endsWith(".msh")) {
      GmshImportOptions options;
      if (gmsh_mesh_dimension(path.toStdString()) == 2 && !ask_planar_elements(options))
        return false;
      document_.open_msh(path.toStdString(), options);
    } else {
      document_.open_inp(path.toStdString());
    }
  } catch (const std::exception& e) {
    show_error("Open " + QFileInfo(path).fileName(), QString::fromUtf8(e.what()));
    return false;
  }
  log("opened " + path);
  for (const std::string& warning : document_.open_warnings())
    log("view: " + QString::fromStdString(warning));
  if (!document_.results_notice().empty()) {  // an older results file: opened, not verified
    const QString notice = QString::fromStdString(document_.results_notice());
    log(notice);
    statusBar()->showMessage(notice);
  }
  add_recent(path);
  view_->set_named_view("iso");
  if (document_.results()) results_->set_field("S.mises");
  refresh_model();
  return true;
}

// A surface mesh from Gmsh does not say what its elements are: the user picks, as `styk import
// --planar` asks.
bool MainWindow::ask_planar_elements(GmshImportOptions& options) {
  const QStringList kinds{"shell (S4, S8, S9, STRI3)", "plane stress (CPS4, CPS8)",
                          "plane strain (CPE4, CPE8)", "axisymmetric (CAX4, CAX8)"};
  bool ok = false;
  const QString kind = QInputDialog::getItem(
      this, "Open Gmsh mesh", "A surface mesh: its elements are", kinds, 0, false, &ok);
  if (!ok) return false;
  const PlanarElements choices[] = {PlanarElements::Shell, PlanarElements::PlaneStress,
                                    PlanarElements::PlaneStrain, PlanarElements::Axisymmetric};
  options.planar = choices[kinds.indexOf(kind)];
  return true;
}

bool MainWindow::save_file(const QString& path) {
  try {
    document_.save_inp(path.toStdString());
  } catch (const std::exception& e) {
    show_error("Save", QString::fromUtf8(e.what()));
    return false;
  }
  log("saved " + path);
  if (autosave_) autosave_->discard();
  add_recent(path);
  update_title();
  return true;
}

bool MainWindow::export_png(const QString& path) {
  const QImage picture = view_->grab_picture();
  // PNG, or BMP (the thesis' picture format) by the file's extension.
  const char* format = path.endsWith(".bmp", Qt::CaseInsensitive) ? "BMP" : "PNG";
  if (picture.isNull() || !picture.save(path, format)) {
    show_error("Export picture", "cannot write " + path);
    return false;
  }
  log("view written to " + path);
  return true;
}

void MainWindow::start_solve() {
  if (document_.model().elements.empty()) {
    show_error("Solve", "the model has no elements");
    return;
  }
  QString job = QFileInfo(QString::fromStdString(document_.path())).completeBaseName();
  if (job.isEmpty() || job.endsWith(".styk")) job = "model";
  QString error;
  if (!solver_->start(document_.model(), job, &error)) {
    show_error("Solve", error);
    return;
  }
  progress_->setValue(0);
  cancel_->setEnabled(true);
}

void MainWindow::cancel_solve() { solver_->cancel(); }

bool MainWindow::solving() const { return solver_->running(); }

void MainWindow::on_solve_finished(bool ok, const QString& results, const QString& error, int line,
                                   const QString& text) {
  cancel_->setEnabled(false);
  progress_->setValue(ok ? 100 : 0);
  progress_->setFormat(ok ? "solved" : "%p%");
  if (!ok) {
    QString message = error;
    if (line > 0)
      message += QString("\n\nat line %1 of the deck written for the solver (%2):\n%3")
                     .arg(line)
                     .arg(solver_->deck_path(), text);
    if (error == "cancelled")
      log("solve cancelled");
    else
      show_error("Solve", message);
    emit solve_finished(false);
    return;
  }
  try {
    ResultsFileContents contents = read_results_file(results.toStdString());
    document_.attach_results(std::move(contents.results), results.toStdString());
  } catch (const std::exception& e) {
    show_error("Solve", QString::fromUtf8(e.what()));
    emit solve_finished(false);
    return;
  }
  log("results: " + results);
  if (solver_->warnings() > 0) {  // solved, but the answer may be poor: say so where it is seen
    const QString note = QString("solved with %1 warning%2 (see the log)")
                             .arg(solver_->warnings())
                             .arg(solver_->warnings() == 1 ? "" : "s");
    progress_->setFormat(note);
    statusBar()->showMessage(note);
  }
  if (results_->settings(mode_).field.empty()) results_->set_field("S.mises");
  refresh_model();
  emit solve_finished(true);
}

void MainWindow::set_display_mode(render::DisplayMode mode) {
  mode_ = mode;
  refresh_scene();
}

void MainWindow::set_field(const QString& field) {
  results_->set_field(field);
  refresh_scene();
}

bool MainWindow::make_set_from_selection(const QString& name) {
  try {
    document_.apply(set_from_selection_command(document_.model(), view_->scene().selection(),
                                               name.toStdString()));
  } catch (const InputError& e) {
    show_error("Make set", QString::fromStdString(e.message()));
    return false;
  }
  log(QString::fromStdString(document_.history().undo_text()));
  refresh_model();
  return true;
}

bool MainWindow::export_animation(const QString& directory, const QString& stem) {
  const bool playing = view_->animating();
  view_->stop_animation();
  try {
    SceneAnimation animation(document_, display_settings(), results_->animation_kind(),
                             results_->animation_frames());
    const QStringList files = view_->export_animation(animation, directory, stem, 100);
    log(QString("animation: %1 frames %2 ... and %3/%4.apng")
            .arg(files.size())
            .arg(files.value(0))
            .arg(directory, stem));
  } catch (const std::exception& e) {
    const auto* input = dynamic_cast<const InputError*>(&e);
    show_error("Export animation",
               input ? QString::fromStdString(input->message()) : QString(e.what()));
    refresh_scene();
    return false;
  }
  results_->set_animating(false);
  if (playing) log("animation stopped for the export");
  refresh_scene();
  return true;
}

StudyChartWindow* MainWindow::open_study(const QString& path) {
  std::ifstream in(path.toStdString());
  if (!in) {
    show_error("Open study charts", path + ": cannot read the file");
    return nullptr;
  }
  try {
    std::vector<studies::RunRecord> records = studies::read_csv(in, path.toStdString());
    if (records.empty()) {
      show_error("Open study charts", path + ": the study has no runs");
      return nullptr;
    }
    auto* window = new StudyChartWindow(std::move(records), QFileInfo(path).fileName(), this);
    window->show();
    log("study charts: " + path);
    return window;
  } catch (const std::runtime_error& e) {
    show_error("Open study charts", QString::fromStdString(e.what()));
    return nullptr;
  }
}

void MainWindow::show_node_history() {
  const Results* results = document_.results();
  const Selection& selection = view_->scene().selection();
  const DisplaySettings settings = display_settings();
  if (!results || selection.kind() != PickKind::Node || selection.nodes().empty() ||
      settings.field.empty()) {
    show_error("Value vs increment",
               "pick a node (Select > Pick nodes, click it) and choose a field");
    return;
  }
  const int node = selection.nodes().front();
  try {
    const auto points =
        node_history(document_.model(), *results, node, settings.field, settings.averaging);
    QStringList labels;
    for (const HistoryPoint& p : points)
      labels << QString::fromStdString(increment_label(results->increments[p.increment]));
    make_history_chart(points, labels, QString::fromStdString(settings.field),
                       QString("node %1").arg(document_.model().node_ids[node]), this)
        ->show();
  } catch (const InputError& e) {
    show_error("Value vs increment", QString::fromStdString(e.message()));
  }
}

void MainWindow::show_selection() {
  const Selection& selection = view_->scene().selection();
  probe_->setText(QString::fromStdString(selection_summary(view_->scene(), selection)));
  if (selection.empty()) return;
  QString html = QString("<b>Selection</b> (%1 %2s)<br>")
                     .arg(selection.size())
                     .arg(QString::fromStdString(pick_kind_name(selection.kind())));
  for (const std::string& line : describe_selection(view_->scene(), selection))
    html += QString::fromStdString(line).toHtmlEscaped() + "<br>";
  // With integration-point values shown: those of the (first) selected element.
  int element = selection.elements().empty() ? -1 : selection.elements().front();
  if (element < 0 && !selection.faces().empty()) element = selection.faces().front().element;
  if (const auto probe = view_->scene().element_probe(element)) {
    html += "<br><b>" + QString::fromStdString(element_probe_summary(*probe)).toHtmlEscaped() +
            "</b><br>";
    for (const std::string& line : describe_element_probe(*probe))
      html += QString::fromStdString(line).toHtmlEscaped() + "<br>";
  }
  properties_->setHtml(html);
}

void MainWindow::refresh_model() {
  view_->stop_animation();
  results_->set_animating(false);
  view_->clear_selection();
  tree_->populate(document_);
  properties_->clear();  // it described an item of the tree before the change
  results_->set_document(document_);
  undo_->setEnabled(document_.history().can_undo());
  undo_->setText("&Undo " + QString::fromStdString(document_.history().undo_text()));
  redo_->setEnabled(document_.history().can_redo());
  redo_->setText("&Redo " + QString::fromStdString(document_.history().redo_text()));
  update_title();
  refresh_scene();
}

void MainWindow::set_filter(ElementDisplayFilter filter) {
  document_.set_filter(std::move(filter));
  refresh_scene();
}

bool MainWindow::make_layer_from_filter(const QString& name) {
  try {
    add_layer_from_filter(document_, name.toStdString(), document_.filter());
  } catch (const InputError& e) {
    show_error("New layer from filter", QString::fromStdString(e.message()));
    return false;
  }
  refresh_model();
  return true;
}

bool MainWindow::make_layer_from_selection(const QString& name) {
  try {
    add_layer_from_selection(document_, name.toStdString(), view_->scene().selection());
  } catch (const InputError& e) {
    show_error("New layer from selection", QString::fromStdString(e.message()));
    return false;
  }
  refresh_model();
  return true;
}

DisplaySettings MainWindow::display_settings() const {
  DisplaySettings settings = results_->settings(mode_);
  settings.filter = document_.filter();
  settings.labels = labels_;
  settings.labels_of_selection = labels_of_selection_;
  settings.samples = smooth_edges_ ? 4 : 1;
  return settings;
}

void MainWindow::set_smooth_edges(bool on) {
  smooth_edges_ = on;
  refresh_scene();
}

void MainWindow::set_labels(bool nodes, bool elements, bool selection_only) {
  labels_.nodes = nodes;
  labels_.elements = elements;
  labels_of_selection_ = selection_only;
  for (auto [action, on] : {std::pair{node_numbers_, nodes}, std::pair{element_numbers_, elements},
                            std::pair{numbers_of_selection_, selection_only}})
    if (action) {
      const QSignalBlocker block(action);
      action->setChecked(on);
    }
  refresh_scene();
}

void MainWindow::refresh_scene() {
  // A filter no element of the model passes any more (another model, an undone edit) is dropped.
  if (document_.filter().active() &&
      filtered_elements(document_.model(), document_.filter()).empty()) {
    document_.set_filter({});
    log("view: the element filter matches no element of this model; cleared");
  }
  DisplaySettings settings = display_settings();
  if (!document_.results()) settings.field.clear();
  try {
    view_->scene().rebuild(document_, settings);
  } catch (const InputError& e) {
    log("view: " + QString::fromStdString(e.message()));
    last_message_ = QString::fromStdString(e.message());
    // An unrolled map of a field that does not live on surfaces: the 3D view of the field;
    // otherwise no field.
    if (settings.unrolled) {
      settings.unrolled = false;
    } else {
      settings.field.clear();
      settings.ip_values = false;
    }
    try {
      view_->scene().rebuild(document_, settings);
    } catch (const InputError&) {
      settings.field.clear();
      view_->scene().rebuild(document_, settings);
    }
  }
  view_->update();
}

void MainWindow::log(const QString& line) { log_->appendPlainText(line); }

QString MainWindow::log_text() const { return log_->toPlainText(); }

void MainWindow::show_error(const QString& title, const QString& message) {
  last_message_ = message;
  log(title + ": " + message);
  if (qEnvironmentVariableIsSet("STYK_GUI_NO_MESSAGE_BOXES")) return;  // tests: no modal boxes
  QMessageBox::warning(this, title, message);
}

bool MainWindow::maybe_save() {
  if (!document_.is_modified() || qEnvironmentVariableIsSet("STYK_GUI_NO_MESSAGE_BOXES"))
    return true;
  const auto answer =
      QMessageBox::question(this, "Unsaved changes", "Save the model first?",
                            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Cancel) return false;
  if (answer == QMessageBox::Save) {
    const QString path =
        QFileDialog::getSaveFileName(this, "Save deck", QString(), "Decks (*.inp)");
    return !path.isEmpty() && save_file(path);
  }
  return true;
}

void MainWindow::update_title() {
  const QString name = document_.path().empty()
                           ? QString("(new model)")
                           : QFileInfo(QString::fromStdString(document_.path())).fileName();
  setWindowTitle(name + (document_.is_modified() ? " *" : "") + " — styk-gui");
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybe_save()) {
    event->ignore();
    return;
  }
  solver_->cancel();
  if (autosave_) autosave_->discard();  // saved, or the changes discarded: nothing to recover
  event->accept();
}

}  // namespace styk::gui
