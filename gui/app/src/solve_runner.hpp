// Solving from the window without freezing it: the model is written to a deck in a temporary
// directory and `styk solve` runs on it as a child process (QProcess). Its stderr progress lines
// drive the progress bar and the log; Cancel kills the process, which is a real cancel (the solver
// cannot be interrupted inside a phase, e.g. a CHOLMOD factorisation, when run in a thread).
#pragma once

#include <QObject>
#include <QProcess>
#include <QString>
#include <QTemporaryDir>
#include <memory>

#include "styk/core/model.hpp"

namespace styk::gui {

class SolveRunner : public QObject {
  Q_OBJECT
 public:
  // `styk_program`: the `styk` executable (see locate_styk_program()).
  explicit SolveRunner(QString styk_program, QObject* parent = nullptr);
  ~SolveRunner() override;

  // Writes `model` as <tmp>/<job>.inp and starts the solve; false (with `error`) if it cannot.
  bool start(const Model& model, const QString& job, QString* error);
  void cancel();
  bool running() const;
  QString deck_path() const { return deck_; }
  // The solver's warnings of the last run (locking, hourglassing, distortion), each in the log.
  int warnings() const { return warnings_; }

  // STYK_CLI from the environment, else `styk` next to this program, else the build tree's, else
  // `styk` on PATH.
  static QString locate_styk_program();

 signals:
  void progress(int percent, const QString& phase);
  void log(const QString& line);
  // ok: results in `results_path`. Otherwise `error` is the message, `deck_line` the line of the
  // written deck it points to (0 when none) and `deck_text` that line's text.
  void finished(bool ok, const QString& results_path, const QString& error, int deck_line,
                const QString& deck_text);

 private:
  void read_stderr();
  void on_finished(int exit_code, QProcess::ExitStatus status);

  QString program_;
  std::unique_ptr<QTemporaryDir> directory_;
  std::unique_ptr<QProcess> process_;
  QString deck_;
  QString pending_;
  QString first_error_;
  int error_line_ = 0;
  QString results_path_;  // from the protocol's done event
  int warnings_ = 0;
  bool cancelled_ = false;
};

}  // namespace styk::gui
