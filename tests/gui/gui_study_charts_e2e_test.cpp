// styk-gui end to end under xvfb-run: File > Open study charts shows a study's CSV (what
// `styk study accuracy|stability` writes) as interactive Qt Charts: the problems and measures of
// the file, one series per family with its fitted slope in the legend and the Pareto front, the
// axis choices (DOF, wall time, element size, the swept parameter of a stability sweep), the run
// under the mouse read out, a family hidden by clicking its legend entry, a damaged file refused
// with its line. The committed atlas (docs/atlas/accuracy.csv) opens too;
// STYK_GUI_SCREENSHOTS=DIR writes its window (gui-study-charts.png, for docs/gui.md).
#include <QAction>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QLegendMarker>
#include <QLogValueAxis>
#include <QStandardPaths>
#include <QTest>
#include <QXYSeries>
#include <cmath>
#include <fstream>

#include "main_window.hpp"
#include "study_chart_window.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/studies/results/run_record.hpp"

using namespace styk;

namespace {

const QString kOutput = QString(STYK_BINARY_DIR) + "/tests/gui/output";

// A refinement series per family with error = c h^p (DOF ~ h^-2), and a sweep.
std::vector<studies::RunRecord> sample_study() {
  std::vector<studies::RunRecord> out;
  for (const auto& [family, c, p] :
       {std::tuple<const char*, double, double>{"C3D8", 1.0, 1.0}, {"C3D20", 0.2, 2.0}})
    for (int k = 0; k < 4; ++k) {
      studies::RunRecord r;
      r.study = "accuracy";
      r.problem = "lame";
      r.family = family;
      r.level = k;
      r.h = 1.0 / (1 << k);
      r.dof = 100LL << (2 * k);
      r.time_s = 1e-4 * r.dof * (p > 1 ? 3 : 1);
      r.memory_mb = 50;
      r.error[static_cast<int>(studies::Measure::Energy)] = c * std::pow(r.h, p);
      r.error[static_cast<int>(studies::Measure::PointDisplacement)] = c * std::pow(r.h, p + 1);
      out.push_back(r);
    }
  for (double nu : {0.2, 0.01, 1e-4}) {
    studies::RunRecord r;
    r.study = "stability";
    r.problem = "poisson";
    r.family = "C3D8";
    r.parameter = "0.5 - nu";
    r.value = nu;
    r.dof = 300;
    r.time_s = 0.01;
    r.error[static_cast<int>(studies::Measure::PointDisplacement)] = 0.01 / nu;
    r.warnings = nu < 0.05 ? std::vector<std::string>{"locking"} : std::vector<std::string>{};
    out.push_back(r);
  }
  return out;
}

QStringList series_names(QChartView* view) {
  QStringList names;
  for (QAbstractSeries* s : view->chart()->series()) names << s->name();
  return names;
}

QAbstractSeries* series_named(QChartView* view, const QString& name) {
  for (QAbstractSeries* s : view->chart()->series())
    if (s->name() == name) return s;
  return nullptr;
}

}  // namespace

class GuiStudyCharts : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    qputenv("STYK_GUI_NO_MESSAGE_BOXES", "1");
    QDir().mkpath(kOutput);
    styk::setup_element_registry(registry_, libraries_, {styk::build_plugin_directory()});
    window_ = std::make_unique<gui::MainWindow>(registry_);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    path_ = kOutput + "/study-sample.csv";
    std::ofstream out(path_.toStdString());
    studies::write_csv(out, sample_study());
  }

  void theMenuOffersIt() { QVERIFY(window_->findChild<QAction*>("action_open_study") != nullptr); }

  void opensTheConvergenceCharts() {
    chart_ = window_->open_study(path_);
    QVERIFY(chart_ != nullptr);
    QVERIFY(QTest::qWaitForWindowExposed(chart_));
    auto* problem = chart_->findChild<QComboBox*>("study_problem");
    auto* measure = chart_->findChild<QComboBox*>("study_measure");
    auto* axis = chart_->findChild<QComboBox*>("study_axis");
    QCOMPARE(problem->count(), 2);
    QCOMPARE(problem->currentText(), QString("lame"));
    QCOMPARE(measure->currentText(), QString("energy-norm error"));
    QCOMPARE(measure->count(), 2);  // energy and the point displacement: what the file has
    QCOMPARE(axis->currentText(), QString("DOF"));
    QCOMPARE(series_names(chart_->chart_view()),
             QStringList({"Pareto front", "C3D8  slope -0.50", "C3D20  slope -1.00"}));
    const auto axes = chart_->chart_view()->chart()->axes(Qt::Horizontal);
    QCOMPARE(axes.size(), 1);
    QVERIFY(qobject_cast<QLogValueAxis*>(axes[0]) != nullptr);
  }

  void switchesAxisAndMeasure() {
    QVERIFY(chart_->show_chart("lame", "L2 displacement error", "DOF") == false);  // not in file
    QVERIFY(chart_->show_chart("lame", "displacement error at the named point", "element size h"));
    QCOMPARE(series_names(chart_->chart_view()),
             QStringList({"C3D8  order 2.00", "C3D20  order 3.00"}));
    QVERIFY(chart_->show_chart("lame", "energy-norm error", "wall time"));
    QVERIFY(series_names(chart_->chart_view()).contains("Pareto front"));
  }

  void readsTheRunUnderTheMouse() {
    QVERIFY(chart_->show_chart("lame", "energy-norm error", "DOF"));
    QChartView* view = chart_->chart_view();
    auto* series = qobject_cast<QXYSeries*>(series_named(view, "C3D20  slope -1.00"));
    QVERIFY(series != nullptr);
    const QPointF at = view->chart()->mapToPosition(series->at(2), series);
    const QPoint pixel = view->mapFromScene(at);
    QTest::mouseMove(view->viewport(), pixel + QPoint(5, 5));
    QTest::qWait(50);
    QTest::mouseMove(view->viewport(), pixel);
    QTRY_COMPARE_WITH_TIMEOUT(chart_->hovered_tip(), chart_->tip_of("C3D20  slope -1.00", 2), 2000);
    QVERIFY2(chart_->hovered_tip().startsWith("C3D20, level 2: 1 600 DOF"),
             qPrintable(chart_->hovered_tip()));
  }

  void legendClickHidesAFamily() {
    QChartView* view = chart_->chart_view();
    QAbstractSeries* series = series_named(view, "C3D8  slope -0.50");
    QVERIFY(series && series->isVisible());
    const QList<QLegendMarker*> markers = view->chart()->legend()->markers(series);
    QCOMPARE(markers.size(), 1);
    emit markers[0]->clicked();
    QVERIFY(!series->isVisible());
    QVERIFY(markers[0]->isVisible());  // still there to click again
    emit markers[0]->clicked();
    QVERIFY(series->isVisible());
  }

  void sweepsChartAgainstTheirParameter() {
    QVERIFY(
        chart_->show_chart("poisson", "displacement error at the named point", "swept parameter"));
    QCOMPARE(series_names(chart_->chart_view()), QStringList({"C3D8", "10 % error"}));
    const auto axes = chart_->chart_view()->chart()->axes(Qt::Horizontal);
    QCOMPARE(axes[0]->titleText(), QString("0.5 - nu"));
    QVERIFY(qobject_cast<QLogValueAxis*>(axes[0]) != nullptr);  // the values span decades
    QVERIFY(chart_->tip_of("C3D8", 0).contains("warned: locking"));
  }

  void refusesADamagedFile() {
    const QString bad = kOutput + "/study-bad.csv";
    std::ofstream(bad.toStdString()) << studies::csv_header() << "\naccuracy,lame\n";
    QVERIFY(window_->open_study(bad) == nullptr);
    QVERIFY2(window_->log_text().contains("study-bad.csv:2: expected 20 columns, found 2"),
             qPrintable(window_->log_text()));
  }

  void opensTheCommittedAtlas() {
    gui::StudyChartWindow* atlas =
        window_->open_study(QString(STYK_SOURCE_DIR) + "/docs/atlas/accuracy.csv");
    QVERIFY(atlas != nullptr);
    QVERIFY(atlas->findChild<QComboBox*>("study_problem")->count() >= 5);
    QVERIFY(series_names(atlas->chart_view()).size() >= 9);  // the families and the front
    QVERIFY(atlas->show_chart("curved-beam", "energy-norm error", "wall time"));
    atlas->resize(1200, 760);
    QTest::qWait(100);
    atlas->grab().save(kOutput + "/study-charts.png");
    const QString shots = qEnvironmentVariable("STYK_GUI_SCREENSHOTS");
    if (!shots.isEmpty()) atlas->grab().save(shots + "/gui-study-charts.png");
    atlas->close();
  }

  void cleanupTestCase() {
    if (chart_) chart_->close();
    window_.reset();
  }

 private:
  PluginLibraries libraries_;
  ElementRegistry registry_;
  std::unique_ptr<gui::MainWindow> window_;
  gui::StudyChartWindow* chart_ = nullptr;
  QString path_;
};

QTEST_MAIN(GuiStudyCharts)
#include "gui_study_charts_e2e_test.moc"
