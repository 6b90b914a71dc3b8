#include "child_process_solve.hpp"

#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "session/solve_protocol.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/results_file.hpp"

namespace styk::gui {
namespace {

const SourceLoc kHere{"calibration solve", 0};

// The first error line of the solver's stderr, else the last non-empty line.
std::string failure_text(const QString& stderr_text) {
  std::string last;
  for (const QString& line : stderr_text.split('\n', Qt::SkipEmptyParts)) {
    const SolveLine parsed = parse_solve_line(line.toStdString());
    if (parsed.kind == SolveLine::Kind::Error) return parsed.text;
    last = line.toStdString();
  }
  return last;
}

Results solve_in(const QTemporaryDir& directory, const QString& program, const Model& model) {
  const QString deck = directory.filePath("calibration.inp");
  {
    std::ofstream out(deck.toStdString());
    write_inp(model, out);
    if (!out) throw InputError(kHere, "cannot write " + deck.toStdString());
  }
  QStringList arguments;
  for (const std::string& a : solve_arguments(deck.toStdString(), directory.path().toStdString()))
    arguments << QString::fromStdString(a);
  QProcess process;
  process.start(program, arguments);
  if (!process.waitForStarted())
    throw InputError(kHere, "cannot start " + program.toStdString() + ": " +
                                process.errorString().toStdString());
  process.waitForFinished(-1);
  if (process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
    const std::string why = failure_text(QString::fromLocal8Bit(process.readAllStandardError()));
    throw InputError(kHere, "styk solve failed (exit " + std::to_string(process.exitCode()) + ")" +
                                (why.empty() ? "" : ": " + why));
  }
  return read_results_file(directory.filePath("calibration.styk.h5").toStdString()).results;
}

}  // namespace

mesher::StaticSolve child_process_solve(QString styk_program) {
  return [program = std::move(styk_program)](const Model& model) {
    const QTemporaryDir directory;
    if (!directory.isValid())
      throw InputError(
          kHere, "cannot create a temporary directory: " + directory.errorString().toStdString());
    try {
      return solve_in(directory, program, model);
    } catch (const InputError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw InputError(kHere, e.what());  // e.g. an unreadable results file
    }
  };
}

}  // namespace styk::gui
