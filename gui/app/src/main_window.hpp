// The main window of styk-gui: model tree (left), 3D view (centre), properties and results
// controls (right), log and progress (bottom); menus for files, edits, the model, the analysis
// and the view. The Document lives here; every model edit goes through it (undoable).
#pragma once

#include <QMainWindow>
#include <memory>

#include "session/autosave.hpp"
#include "session/document.hpp"
#include "session/element_filter.hpp"
#include "session/scene.hpp"
#include "styk/render/frame.hpp"

class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QTextBrowser;
class QAction;
class QMenu;
class QTimer;

namespace styk::gui {

class GlView;
class ModelTree;
class ResultsPanel;
class SolveRunner;
class StudyChartWindow;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  // `registry` (built-in elements and plug-ins) must outlive the window.
  explicit MainWindow(const ElementRegistry& registry, QWidget* parent = nullptr);
  ~MainWindow() override;

  // .inp or .styk.h5; errors go to a message box (and the log). Returns success.
  bool open_file(const QString& path);
  bool save_file(const QString& path);
  bool export_png(const QString& path);  // PNG, or BMP when the path ends in .bmp
  // A study's CSV (`styk study accuracy|stability`) in a chart window of its own; a damaged file
  // goes to a message box (and the log) with its line. Returns the window, or nullptr.
  StudyChartWindow* open_study(const QString& path);
  void start_solve();
  void cancel_solve();
  bool solving() const;
  void set_display_mode(render::DisplayMode mode);
  // View > Numbers: node and element numbers of the seen entities (or of the selection only).
  void set_labels(bool nodes, bool elements, bool selection_only);
  // View > Smooth edges: the model drawn with 4 samples per pixel (slower to orbit).
  void set_smooth_edges(bool on);
  void set_field(const QString& field);  // selects it in the results panel and redraws
  // The selection in the view as a node set / element set / surface (undoable); errors go to
  // a message box. Returns success.
  bool make_set_from_selection(const QString& name);
  // View > Filter: only the passing elements are drawn (an inactive filter draws everything). The
  // document keeps it, so it is saved with the deck.
  void set_filter(ElementDisplayFilter filter);
  const ElementDisplayFilter& filter() const { return document_.filter(); }
  // A user layer (session/layer_edits.hpp) from the filter / the selection (undoable); errors go
  // to a message box. Returns success.
  bool make_layer_from_filter(const QString& name);
  bool make_layer_from_selection(const QString& name);
  // Writes the animation the results panel describes as DIR/STEM_0000.png ... and DIR/STEM.apng.
  bool export_animation(const QString& directory, const QString& stem);
  // The value-vs-increment chart of the first selected node and the field shown.
  void show_node_history();

  // Autosave and recovery (main_window_autosave.cpp, docs/gui.md "Autosave and recovery"): the
  // model with unsaved changes is written every $STYK_GUI_AUTOSAVE_SECONDS (default 30) to the
  // autosave directory; autosave_now() writes it at once (returns whether it wrote). The
  // sessions interrupted before they saved, newest first; recover_session() opens one (unsaved,
  // its original file kept as the document's path) and removes its files; offer_recovery()
  // asks the user about the newest one (a message box; called once the window shows).
  bool autosave_now();
  std::vector<InterruptedSession> interrupted_sessions() const;
  bool recover_session(const InterruptedSession& session);
  void offer_recovery();
  const Autosave* autosave() const { return autosave_.get(); }

  Document& document() { return document_; }
  GlView* view() const { return view_; }
  ResultsPanel* results_panel() const { return results_; }
  QString last_message() const { return last_message_; }  // last error shown to the user
  QString log_text() const;

 signals:
  void solve_finished(bool ok);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  bool ask_planar_elements(GmshImportOptions& options);
  void build_menus();  // main_window_menus.cpp: one builder per menu
  void build_file_menu();
  void build_edit_menu();
  void build_model_menu();
  void build_select_menu();
  void build_analysis_menu();
  void build_view_menu();
  void refresh_model();                      // after any model or results change
  void refresh_scene();                      // after a display setting change
  DisplaySettings display_settings() const;  // the results panel's, with the filter
  void log(const QString& line);
  void show_error(const QString& title, const QString& message);
  void run_dialog(QDialog* dialog);
  bool maybe_save();
  void add_recent(const QString& path);
  void update_recent_menu();
  void update_title();
  void show_selection();  // status bar and properties panel
  void start_autosave();
  void on_solve_finished(bool ok, const QString& results, const QString& error, int line,
                         const QString& text);

  Document document_;
  GlView* view_ = nullptr;
  ModelTree* tree_ = nullptr;
  ResultsPanel* results_ = nullptr;
  QTextBrowser* properties_ = nullptr;
  QPlainTextEdit* log_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* probe_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  QAction* undo_ = nullptr;
  QAction* redo_ = nullptr;
  QAction* cancel_ = nullptr;
  std::unique_ptr<SolveRunner> solver_;
  render::DisplayMode mode_ = render::DisplayMode::Shaded;
  render::LabelRequest labels_;
  bool labels_of_selection_ = false;
  bool smooth_edges_ = false;
  QAction* node_numbers_ = nullptr;
  QAction* element_numbers_ = nullptr;
  QAction* numbers_of_selection_ = nullptr;
  QString last_message_;
  std::unique_ptr<Autosave> autosave_;  // null when the autosave directory is unusable
  QTimer* autosave_timer_ = nullptr;
};

}  // namespace styk::gui
