// styk-gui end to end under xvfb-run (a QOpenGLWidget needs X): open the sample cantilever, mesh a
// block through its dialog (a bad entry first: refused with a message), fix it and load it, solve
// through `styk solve`, show Mises, grab the view and compare it with the committed baseline
// (tests/gui/baselines, the renderer's image tolerance: a pixel differs when a channel differs by
// more than 24/255, at most 0.5 % may differ). Also: the path chart, PNG export, undo dropping
// stale results, a solve error pointing at its deck line, and cancel.
#include <QAction>
#include <QApplication>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>
#include <QTimer>
#include <functional>

#include "form_dialog.hpp"
#include "gl_view.hpp"
#include "image_compare.hpp"
#include "main_window.hpp"
#include "results_panel.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/render/image.hpp"

using namespace styk;

namespace {

const QString kSource = STYK_SOURCE_DIR;
const QString kOutput = QString(STYK_BINARY_DIR) + "/tests/gui/output";

// Triggers a menu action and fills the dialog it opens: `fill` sets fields, then OK is pressed.
gui::FormDialog* open_dialog(gui::MainWindow& w, const QString& action) {
  auto* a = w.findChild<QAction*>(action);
  if (!a) return nullptr;
  a->trigger();
  QApplication::processEvents();
  const auto dialogs = w.findChildren<gui::FormDialog*>();
  for (gui::FormDialog* d : dialogs)
    if (d->isVisible()) return d;
  return nullptr;
}

void set_text(gui::FormDialog* d, const QString& key, const QString& value) {
  if (auto* e = d->findChild<QLineEdit*>(key))
    e->setText(value);
  else if (auto* c = d->findChild<QComboBox*>(key))
    c->setCurrentText(value);
}

render::Image to_image(const QImage& picture) {
  const QImage rgba = picture.convertToFormat(QImage::Format_RGBA8888);
  render::Image image(rgba.width(), rgba.height());
  for (int y = 0; y < rgba.height(); ++y)
    std::copy_n(rgba.constScanLine(y), std::size_t(rgba.width()) * 4,
                image.rgba.data() + std::size_t(y) * rgba.width() * 4);
  return image;
}

}  // namespace

class GuiEndToEnd : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);  // recent files go to a test settings location
    qputenv("STYK_GUI_NO_MESSAGE_BOXES", "1");
    QDir().mkpath(kOutput);
    warnings_ =
        styk::setup_element_registry(registry_, libraries_, {styk::build_plugin_directory()});
    window_ = std::make_unique<gui::MainWindow>(registry_);
    window_->view()->setFixedSize(640, 480);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }

  void opensTheSample() {
    QVERIFY(window_->open_file(kSource + "/samples/cantilever-c3d20.inp"));
    QCOMPARE(window_->document().model().element_count(), 80);
    QVERIFY(!window_->view()->scene().empty());
    QVERIFY(!window_->open_file(kSource + "/tests/inputs/bad/binary_garbage.inp"));
    QVERIFY(window_->last_message().contains("binary_garbage.inp"));
    QCOMPARE(window_->document().model().element_count(), 80);  // unchanged
  }

  void meshesABlockRefusingBadInputFirst() {
    gui::FormDialog* d = open_dialog(*window_, "action_block");
    QVERIFY(d);
    set_text(d, "name", "BRACKET");
    set_text(d, "origin", "0 2 0");
    set_text(d, "size", "6 1 1");
    set_text(d, "divisions", "-6 1 1");
    set_text(d, "material", "MAT");
    d->accept();
    QVERIFY(d->isVisible());
    QCOMPARE(d->error_text(), QString("divisions along x must be at least 1, not -6"));
    set_text(d, "divisions", "6 1 1");
    d->accept();
    QVERIFY(!d->isVisible());
    QCOMPARE(window_->document().model().element_count(), 86);
    QVERIFY(window_->document().model().find_nset("BRACKET_XMAX"));
  }

  void fixesAndLoadsTheBlock() {
    gui::FormDialog* bc = open_dialog(*window_, "action_boundary");
    QVERIFY(bc);
    set_text(bc, "nset", "BRACKET_XMIN");
    bc->accept();
    QVERIFY2(!bc->isVisible(), qPrintable(bc->error_text()));
    gui::FormDialog* load = open_dialog(*window_, "action_cload");
    QVERIFY(load);
    set_text(load, "nset", "EMPTY-NOT-THERE");
    load->accept();  // the combo holds only existing sets: the text stays a real one
    set_text(load, "nset", "BRACKET_XMAX");
    set_text(load, "value", "abc");
    load->accept();
    QCOMPARE(load->error_text(), QString("Value: 'abc' is not a number"));
    set_text(load, "value", "-0.5");
    load->accept();
    QVERIFY2(!load->isVisible(), qPrintable(load->error_text()));
    QCOMPARE(window_->document().history().undo_text(), std::string("Load BRACKET_XMAX"));
  }

  void solvesAndShowsMises() {
    QSignalSpy done(window_.get(), &gui::MainWindow::solve_finished);
    window_->start_solve();
    QVERIFY(window_->solving());
    QVERIFY(done.wait(120000));
    QCOMPARE(done.takeFirst().at(0).toBool(), true);
    QVERIFY(window_->document().results());
    window_->set_field("S.mises");
    QVERIFY(window_->view()->scene().field());
    QCOMPARE(QString::fromStdString(window_->view()->scene().field()->name), QString("S.mises"));
    QCOMPARE(window_->view()->scene().colors().bands, 12);
    window_->view()->repaint();
    QTest::qWait(50);
    const QImage picture = window_->view()->grab_picture();
    QCOMPARE(picture.size(), QSize(640, 480));
    QVERIFY(window_->export_png(kOutput + "/e2e-mises.png"));
    window_->grab().save(kOutput + "/e2e-window.png");

    const std::string baseline = (kSource + "/tests/gui/baselines/e2e-mises.png").toStdString();
    const render::Image actual = to_image(picture);
    if (qEnvironmentVariableIsSet("STYK_UPDATE_BASELINES")) render::write_png(baseline, actual);
    const render::Image expected = render::read_png(baseline);
    const render_test::CompareResult r = render_test::compare_images(actual, expected, 24);
    if (!r.same_size || r.fraction > 0.005) {
      render::write_png((kOutput + "/e2e-mises.actual.png").toStdString(), actual);
      if (r.same_size)
        render::write_png((kOutput + "/e2e-mises.diff.png").toStdString(), r.difference);
    }
    QVERIFY(r.same_size);
    QVERIFY2(r.fraction <= 0.005,
             qPrintable(QString("%1 % of the pixels differ").arg(100 * r.fraction)));
  }

  void probesAndCharts() {
    // Hover over the middle of every node of the tip face until the probe reports one.
    const auto& scene = window_->view()->scene();
    const auto& frame = const_cast<gui::Scene&>(scene).frame(640, 480, window_->view()->view());
    (void)frame;
    bool probed = false;
    QLabel* status = nullptr;
    for (QLabel* l : window_->findChildren<QLabel*>())
      if (l->parent() && l->parent()->inherits("QStatusBar")) status = l;
    for (int y = 100; y < 400 && !probed; y += 6)
      for (int x = 200; x < 600 && !probed; x += 6) {
        QTest::mouseMove(window_->view(), QPoint(x, y));
        QApplication::processEvents();
        probed = status && status->text().contains("S.mises =");
      }
    QVERIFY(probed);

    auto* path = window_->results_panel()->findChild<QComboBox*>("path");
    QVERIFY(path);
    path->setCurrentText("TIP");
    auto* chart = window_->results_panel()->findChild<QWidget*>("chart");
    QVERIFY(chart);
    QMetaObject::invokeMethod(chart, "click");
    QApplication::processEvents();
    QChartView* view = nullptr;
    for (QWidget* w : QApplication::topLevelWidgets())
      if (auto* v = w->findChild<QChartView*>("chart_view"); v && w->isVisible()) view = v;
    QVERIFY(view);
    QVERIFY(!view->chart()->series().isEmpty());
    view->window()->grab().save(kOutput + "/e2e-chart.png");
    view->window()->close();
  }

  void undoDropsStaleResults() {
    window_->findChild<QAction*>("action_undo")->trigger();  // undoes the load
    QVERIFY(!window_->document().results());
    QCOMPARE(window_->document().history().redo_text(), std::string("Load BRACKET_XMAX"));
    QVERIFY(!window_->view()->scene().field());
  }

  void solveErrorsNameTheDeckLine() {
    window_->document().new_model();
    gui::FormDialog* d = open_dialog(*window_, "action_block");
    QVERIFY(d);
    d->accept();  // a block without section
    QVERIFY(!d->isVisible());
    gui::FormDialog* s = open_dialog(*window_, "action_step");
    QVERIFY(s);
    s->accept();
    QSignalSpy done(window_.get(), &gui::MainWindow::solve_finished);
    window_->start_solve();
    QVERIFY(done.wait(60000));
    QCOMPARE(done.takeFirst().at(0).toBool(), false);
    QVERIFY2(window_->last_message().contains("no section"), qPrintable(window_->last_message()));
    QVERIFY2(window_->last_message().contains("at line "), qPrintable(window_->last_message()));
  }

  void cancelStopsTheSolver() {
    QVERIFY(window_->open_file(kSource + "/samples/cantilever-c3d20.inp"));
    QSignalSpy done(window_.get(), &gui::MainWindow::solve_finished);
    window_->start_solve();
    window_->cancel_solve();
    QVERIFY(done.count() > 0 || done.wait(30000));
    QCOMPARE(done.takeFirst().at(0).toBool(), false);
    QVERIFY(window_->log_text().contains("solve cancelled"));
    QVERIFY(!window_->solving());
  }

  // docs/results.md "Integrity": a results file holding Inf (written by an older Styk) is refused
  // with the reader's message and the view keeps the results shown; an older sound file opens
  // with its notice in the status bar.
  void refusesResultsThatCannotBeTrusted() {
    const QString inputs = kSource + "/tests/inputs/results/";
    QVERIFY(window_->open_file(inputs + "legacy-cube.styk.h5"));
    QVERIFY(window_->document().results());
    QVERIFY2(window_->statusBar()->currentMessage().contains("cannot be verified"),
             qPrintable(window_->statusBar()->currentMessage()));
    QVERIFY(window_->view()->scene().field());
    const std::string field = window_->view()->scene().field()->name;
    QVERIFY(!window_->open_file(inputs + "legacy-overflow.styk.h5"));
    QVERIFY2(window_->last_message().contains(
                 "dataset /steps/step_1/increment_1/S: element 1, integration point 1"),
             qPrintable(window_->last_message()));
    QVERIFY(window_->document().path().find("legacy-cube") != std::string::npos);
    QVERIFY(window_->document().results());
    QVERIFY(window_->view()->scene().field());
    QCOMPARE(window_->view()->scene().field()->name, field);
  }

  void cleanupTestCase() { window_.reset(); }

 private:
  PluginLibraries libraries_;
  ElementRegistry registry_;
  std::vector<styk::PluginDiagnostic> warnings_;
  std::unique_ptr<gui::MainWindow> window_;
};

QTEST_MAIN(GuiEndToEnd)
#include "gui_e2e_test.moc"
