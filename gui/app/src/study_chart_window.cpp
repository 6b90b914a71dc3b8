#include "study_chart_window.hpp"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QCursor>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QPushButton>
#include <QSignalBlocker>
#include <QToolTip>
#include <QVBoxLayout>
#include <QXYSeries>
#include <algorithm>
#include <cmath>

#include "styk/charts/qt_chart.hpp"
#include "styk/studies/results/atlas_charts.hpp"
#include "styk/studies/results/convergence.hpp"

namespace styk::gui {
namespace {

const char* kDof = "DOF";
const char* kTime = "wall time";
const char* kSize = "element size h";
const char* kParameter = "swept parameter";

bool swept(const std::vector<studies::RunRecord>& records, const std::string& problem) {
  for (const studies::RunRecord& r : records)
    if (r.problem == problem && !r.parameter.empty()) return true;
  return false;
}

// Whether the values of the problem's swept parameter span more than a decade.
bool spans_decades(const std::vector<studies::RunRecord>& records, const std::string& problem) {
  double lo = INFINITY, hi = 0;
  for (const studies::RunRecord& r : records)
    if (r.problem == problem && r.value > 0) lo = std::min(lo, r.value), hi = std::max(hi, r.value);
  return hi > 10 * lo;
}

}  // namespace

StudyChartWindow::StudyChartWindow(std::vector<studies::RunRecord> records, const QString& source,
                                   QWidget* parent)
    : QDialog(parent), records_(std::move(records)) {
  setWindowTitle("Study: " + source);
  setAttribute(Qt::WA_DeleteOnClose);
  setObjectName("study_chart_window");
  families_ = studies::families_of(records_);
  problem_ = new QComboBox;
  problem_->setObjectName("study_problem");
  for (const std::string& p : studies::problems_of(records_))
    problem_->addItem(QString::fromStdString(p));
  measure_ = new QComboBox;
  measure_->setObjectName("study_measure");
  axis_ = new QComboBox;
  axis_->setObjectName("study_axis");
  auto* reset = new QPushButton("Reset zoom");
  reset->setObjectName("study_reset_zoom");
  auto* controls = new QHBoxLayout;
  for (auto [label, box] : {std::pair<const char*, QComboBox*>{"Problem", problem_},
                            {"Error", measure_},
                            {"against", axis_}}) {
    controls->addWidget(new QLabel(label));
    controls->addWidget(box, 1);
  }
  controls->addWidget(reset);
  view_ = new QChartView;
  view_->setObjectName("study_chart_view");
  view_->setRenderHint(QPainter::Antialiasing);
  view_->setRubberBand(QChartView::RectangleRubberBand);  // right click zooms back out
  view_->setMinimumSize(900, 560);
  status_ = new QLabel(
      "Rest the mouse on a point to read its run; click a legend entry to hide "
      "or show a family; drag a rectangle to zoom.");
  status_->setObjectName("study_status");
  status_->setWordWrap(true);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(controls);
  layout->addWidget(view_, 1);
  layout->addWidget(status_);

  connect(problem_, &QComboBox::currentTextChanged, this, [this] {
    fill_measures_and_axes();
    redraw();
  });
  connect(measure_, &QComboBox::currentTextChanged, this, [this] { redraw(); });
  connect(axis_, &QComboBox::currentTextChanged, this, [this] { redraw(); });
  connect(reset, &QPushButton::clicked, this, [this] {
    if (view_->chart()) view_->chart()->zoomReset();
  });
  fill_measures_and_axes();
  redraw();
}

void StudyChartWindow::fill_measures_and_axes() {
  const std::string problem = problem_->currentText().toStdString();
  const QSignalBlocker block_measure(measure_), block_axis(axis_);
  const QString measure = measure_->currentText();
  measure_->clear();
  for (studies::Measure m : studies::kMeasures)
    for (const studies::RunRecord& r : records_)
      if (r.problem == problem && r.ok() && r.error_of(m)) {
        measure_->addItem(studies::measure_label(m), QString(studies::measure_key(m)));
        break;
      }
  const int kept = measure_->findText(measure);
  const int energy = measure_->findText(studies::measure_label(studies::Measure::Energy));
  measure_->setCurrentIndex(kept >= 0 ? kept : std::max(0, energy));
  axis_->clear();
  if (swept(records_, problem)) axis_->addItem(kParameter);
  for (const char* a : {kDof, kTime, kSize}) axis_->addItem(a);
}

void StudyChartWindow::redraw() {
  const std::string problem = problem_->currentText().toStdString();
  const auto measure = studies::measure_from_key(measure_->currentData().toString().toStdString());
  if (problem.empty() || !measure) return;
  const QString axis = axis_->currentText();
  charts::Chart chart;
  if (axis == kParameter) {
    chart = studies::sweep_chart(records_, problem, *measure, families_,
                                 spans_decades(records_, problem));
  } else {
    const studies::Cost cost = axis == kTime   ? studies::Cost::Time
                               : axis == kSize ? studies::Cost::Size
                                               : studies::Cost::Dof;
    chart = studies::convergence_chart(records_, problem, *measure, cost, families_);
  }
  QChart* old = view_->chart();
  view_->setChart(charts::make_qchart(chart));
  delete old;  // setChart releases the previous chart without deleting it
  connect_series();
}

void StudyChartWindow::connect_series() {
  for (QAbstractSeries* s : view_->chart()->series()) {
    auto* xy = qobject_cast<QXYSeries*>(s);
    if (!xy) continue;
    connect(xy, &QXYSeries::hovered, this, [this, xy](const QPointF& p, bool state) {
      if (!state) return;
      const QList<QPointF> points = xy->points();
      const QStringList tips = xy->property("tips").toStringList();
      int nearest = -1;
      double best = INFINITY;
      for (int k = 0; k < points.size(); ++k) {
        const QPointF a = view_->chart()->mapToPosition(points[k], xy);
        const QPointF b = view_->chart()->mapToPosition(p, xy);
        const double d = std::hypot(a.x() - b.x(), a.y() - b.y());
        if (d < best) best = d, nearest = k;
      }
      if (nearest < 0 || nearest >= tips.size()) return;
      status_->setText(tips[nearest]);
      QToolTip::showText(QCursor::pos(), tips[nearest], view_);
    });
    for (QLegendMarker* marker : view_->chart()->legend()->markers(xy))
      connect(marker, &QLegendMarker::clicked, this, [marker, xy] {
        xy->setVisible(!xy->isVisible());
        marker->setVisible(true);  // hiding a series hides its marker: keep it to click again
        QFont font = marker->font();
        font.setStrikeOut(!xy->isVisible());
        marker->setFont(font);
      });
  }
}

bool StudyChartWindow::show_chart(const QString& problem, const QString& measure,
                                  const QString& axis) {
  const int p = problem_->findText(problem);
  if (p < 0) return false;
  problem_->setCurrentIndex(p);
  const int m = measure_->findText(measure), a = axis_->findText(axis);
  if (m < 0 || a < 0) return false;
  measure_->setCurrentIndex(m);
  axis_->setCurrentIndex(a);
  return true;
}

QString StudyChartWindow::hovered_tip() const { return status_->text(); }

QString StudyChartWindow::tip_of(const QString& series, int index) const {
  for (QAbstractSeries* s : view_->chart()->series())
    if (s->name() == series) {
      const QStringList tips = s->property("tips").toStringList();
      return index >= 0 && index < tips.size() ? tips[index] : QString();
    }
  return QString();
}

}  // namespace styk::gui
