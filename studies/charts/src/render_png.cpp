#include "styk/charts/render_png.hpp"

#include <QApplication>
#include <QGraphicsScene>
#include <QImage>
#include <QPainter>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "styk/charts/qt_chart.hpp"

namespace styk::charts {
namespace {

// Qt Charts draws through QGraphicsWidget, which needs a QApplication. A process without one
// (the `styk` command line) gets one for the drawing, on the offscreen platform unless the caller
// chose another; a process with one (the desktop program, GUI tests) keeps its own.
class ApplicationScope {
 public:
  ApplicationScope() {
    if (QCoreApplication::instance()) return;
    if (!std::getenv("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    previous_ = qInstallMessageHandler(&quiet_runtime_dir);
    app_ = std::make_unique<QApplication>(argc_, argv_);
  }
  ~ApplicationScope() {
    if (!app_) return;
    app_.reset();
    qInstallMessageHandler(previous_);
  }
  ApplicationScope(const ApplicationScope&) = delete;
  ApplicationScope& operator=(const ApplicationScope&) = delete;

 private:
  // A command-line process has no session, hence no XDG_RUNTIME_DIR; the offscreen platform
  // says so once per QApplication, which tells a `styk study` user nothing.
  static void quiet_runtime_dir(QtMsgType type, const QMessageLogContext& context,
                                const QString& message) {
    if (message.startsWith("QStandardPaths: XDG_RUNTIME_DIR not set")) return;
    qt_message_output(type, context, message);
  }

  QtMessageHandler previous_ = nullptr;
  int argc_ = 1;
  char name_[5] = "styk";
  char* argv_[2] = {name_, nullptr};
  std::unique_ptr<QApplication> app_;
};

}  // namespace

void write_png(const Figure& figure, const std::string& path) {
  const ApplicationScope application;
  const int columns = std::max(1, figure.columns);
  const int rows =
      std::max<int>(1, (static_cast<int>(figure.charts.size()) + columns - 1) / columns);
  const double cell_w = static_cast<double>(figure.width) / columns;
  const double cell_h = static_cast<double>(figure.height) / rows;
  QImage image(figure.width, figure.height, QImage::Format_ARGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setRenderHint(QPainter::TextAntialiasing);
  for (std::size_t k = 0; k < figure.charts.size(); ++k) {
    QGraphicsScene scene;
    QChart* chart = make_qchart(figure.charts[k]);
    scene.addItem(chart);  // the scene owns it
    chart->setGeometry(0, 0, cell_w, cell_h);
    const QRectF target((k % columns) * cell_w, (k / columns) * cell_h, cell_w, cell_h);
    scene.render(&painter, target, QRectF(0, 0, cell_w, cell_h));
  }
  painter.end();
  if (!image.save(QString::fromStdString(path), "PNG"))
    throw std::runtime_error(path + ": cannot write the chart picture");
}

}  // namespace styk::charts
