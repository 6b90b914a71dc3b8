#include "solve_runner.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTextStream>
#include <fstream>

#include "session/solve_protocol.hpp"
#include "styk/core/progress_protocol.hpp"
#include "styk/inp/writer.hpp"

namespace styk::gui {

SolveRunner::SolveRunner(QString styk_program, QObject* parent)
    : QObject(parent), program_(std::move(styk_program)) {}

SolveRunner::~SolveRunner() {
  if (process_ && process_->state() != QProcess::NotRunning) {
    process_->disconnect(this);
    process_->kill();
    process_->waitForFinished(3000);
  }
}

QString SolveRunner::locate_styk_program() {
  const QString env = qEnvironmentVariable("STYK_CLI");
  if (!env.isEmpty()) return env;
  const QString beside = QCoreApplication::applicationDirPath() + "/styk";
  if (QFileInfo(beside).isExecutable()) return beside;
#ifdef STYK_CLI_BUILD_PATH
  if (QFileInfo(QStringLiteral(STYK_CLI_BUILD_PATH)).isExecutable())
    return QStringLiteral(STYK_CLI_BUILD_PATH);
#endif
  const QString on_path = QStandardPaths::findExecutable("styk");
  return on_path.isEmpty() ? QStringLiteral("styk") : on_path;
}

bool SolveRunner::running() const { return process_ && process_->state() != QProcess::NotRunning; }

bool SolveRunner::start(const Model& model, const QString& job, QString* error) {
  if (running()) {
    *error = "a solve is running already";
    return false;
  }
  directory_ = std::make_unique<QTemporaryDir>();
  if (!directory_->isValid()) {
    *error = "cannot create a temporary directory: " + directory_->errorString();
    return false;
  }
  deck_ = directory_->filePath(job + ".inp");
  {
    std::ofstream out(deck_.toStdString());
    write_inp(model, out);
    if (!out) {
      *error = "cannot write " + deck_;
      return false;
    }
  }
  cancelled_ = false;
  first_error_.clear();
  error_line_ = 0;
  results_path_.clear();
  warnings_ = 0;
  pending_.clear();
  process_ = std::make_unique<QProcess>();
  QStringList arguments;
  for (const std::string& a :
       solve_arguments(deck_.toStdString(), directory_->path().toStdString()))
    arguments << QString::fromStdString(a);
  connect(process_.get(), &QProcess::readyReadStandardError, this, &SolveRunner::read_stderr);
  connect(process_.get(), &QProcess::finished, this, &SolveRunner::on_finished);
  connect(process_.get(), &QProcess::errorOccurred, this, [this](QProcess::ProcessError e) {
    if (e == QProcess::FailedToStart)
      emit finished(false, {}, "cannot start " + program_ + ": " + process_->errorString(), 0, {});
  });
  emit log("solve: " + program_ + " " + arguments.join(' '));
  process_->start(program_, arguments);
  return true;
}

void SolveRunner::cancel() {
  if (!running()) return;
  cancelled_ = true;
  process_->kill();
}

void SolveRunner::read_stderr() {
  pending_ += QString::fromLocal8Bit(process_->readAllStandardError());
  int newline;
  while ((newline = pending_.indexOf('\n')) >= 0) {
    const QString line = pending_.left(newline);
    pending_.remove(0, newline + 1);
    const SolveLine parsed = parse_solve_line(line.toStdString());
    switch (parsed.kind) {
      case SolveLine::Kind::PhaseBegin: {
        const int percent = phase_progress(parsed.phase);
        if (percent >= 0) emit progress(percent, QString::fromStdString(parsed.phase));
        emit log(QString::fromStdString(parsed.phase) + " ...");
        break;
      }
      case SolveLine::Kind::PhaseEnd:
        emit log(QString("%1 done in %2 s")
                     .arg(QString::fromStdString(parsed.phase))
                     .arg(parsed.seconds, 0, 'f', 3));
        break;
      case SolveLine::Kind::Error:
        if (first_error_.isEmpty()) {
          first_error_ = QString::fromStdString(parsed.text);
          error_line_ = parsed.where.line;
        }
        emit log(QString::fromStdString(
            parsed.where.file.empty() ? parsed.text : parsed.where.str() + ": " + parsed.text));
        break;
      case SolveLine::Kind::Warning:
        ++warnings_;
        emit log("warning: " + QString::fromStdString(parsed.text));
        break;
      case SolveLine::Kind::Done:
        results_path_ = QString::fromStdString(parsed.results);
        break;
      default:
        emit log(QString::fromStdString(parsed.text));
    }
  }
}

void SolveRunner::on_finished(int exit_code, QProcess::ExitStatus status) {
  read_stderr();
  if (!pending_.isEmpty()) {
    pending_ += '\n';
    read_stderr();
  }
  if (cancelled_) {
    emit finished(false, {}, "cancelled", 0, {});
    return;
  }
  if (status == QProcess::NormalExit && exit_code == 0) {
    if (results_path_.isEmpty())  // a solver that does not speak this protocol version
      emit finished(false, {},
                    program_ +
                        " ended without naming its results file in the progress "
                        "protocol (version " +
                        QString::number(progress_protocol::kVersion) + ")",
                    0, {});
    else
      emit finished(true, results_path_, {}, 0, {});
    return;
  }
  QString deck_text;
  if (error_line_ > 0) {
    QFile file(deck_);
    if (file.open(QIODevice::ReadOnly | QIODevice::Text)) {
      QTextStream in(&file);
      for (int n = 1; !in.atEnd(); ++n) {
        const QString l = in.readLine();
        if (n == error_line_) {
          deck_text = l;
          break;
        }
      }
    }
  }
  QString message = first_error_.isEmpty()
                        ? QString("styk solve stopped (exit code %1)").arg(exit_code)
                        : first_error_;
  emit finished(false, {}, message, error_line_, deck_text);
}

}  // namespace styk::gui
