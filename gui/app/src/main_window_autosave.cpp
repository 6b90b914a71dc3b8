// MainWindow: autosave of the model being edited and recovery after an interrupted session
// (session/autosave.hpp, docs/gui.md "Autosave and recovery").
#include <QDateTime>
#include <QFileInfo>
#include <QMessageBox>
#include <QTimer>

#include "main_window.hpp"

namespace styk::gui {

void MainWindow::start_autosave() {
  try {
    autosave_ = std::make_unique<Autosave>(default_autosave_directory());
  } catch (const std::exception& e) {
    log(QString("autosave is off: ") + QString::fromUtf8(e.what()));
    return;
  }
  bool given = false;
  const int seconds = qEnvironmentVariableIntValue("STYK_GUI_AUTOSAVE_SECONDS", &given);
  autosave_timer_ = new QTimer(this);
  connect(autosave_timer_, &QTimer::timeout, this, [this] { autosave_now(); });
  autosave_timer_->start(1000 * (given && seconds > 0 ? seconds : 30));
}

bool MainWindow::autosave_now() {
  if (!autosave_) return false;
  try {
    return autosave_->update(document_);
  } catch (const std::exception& e) {
    log(QString("autosave failed: ") + QString::fromUtf8(e.what()));
    return false;
  }
}

std::vector<InterruptedSession> MainWindow::interrupted_sessions() const {
  return autosave_ ? autosave_->interrupted_sessions() : std::vector<InterruptedSession>{};
}

bool MainWindow::recover_session(const InterruptedSession& session) {
  try {
    document_.recover_inp(session.deck, session.original_path);
  } catch (const std::exception& e) {
    show_error("Recover", QString::fromUtf8(e.what()) + "\nThe autosave stays in " +
                              QString::fromStdString(session.deck));
    return false;
  }
  autosave_->forget(session);
  log("recovered the autosave of " + QString::fromStdString(session.original_path.empty()
                                                                ? "a new model"
                                                                : session.original_path));
  refresh_model();
  update_title();
  autosave_now();  // the recovered model is this session's now
  return true;
}

void MainWindow::offer_recovery() {
  const std::vector<InterruptedSession> sessions = interrupted_sessions();
  if (sessions.empty() || qEnvironmentVariableIsSet("STYK_GUI_NO_MESSAGE_BOXES")) return;
  const InterruptedSession& newest = sessions.front();
  const QString what = newest.original_path.empty()
                           ? QString("a new model")
                           : QFileInfo(QString::fromStdString(newest.original_path)).fileName();
  const QString when = QDateTime::fromSecsSinceEpoch(newest.saved_at).toString("yyyy-MM-dd hh:mm");
  const auto answer = QMessageBox::question(this, "Recover unsaved changes",
                                            "styk-gui stopped without saving the changes to " +
                                                what + " (autosaved " + when + "). Recover them?",
                                            QMessageBox::Yes | QMessageBox::No);
  if (answer == QMessageBox::Yes)
    recover_session(newest);
  else
    autosave_->forget(newest);
}

}  // namespace styk::gui
