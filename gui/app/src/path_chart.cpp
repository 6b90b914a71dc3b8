#include "path_chart.hpp"

#include <QChart>
#include <QChartView>
#include <QLabel>
#include <QLineSeries>
#include <QScatterSeries>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>

namespace styk::gui {

QDialog* make_path_chart(const std::vector<PathPoint>& points, const QString& field,
                         const QString& nset, QWidget* parent) {
  auto* dialog = new QDialog(parent);
  dialog->setWindowTitle(field + " along " + nset);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  auto* line = new QLineSeries;
  line->setName(field);
  auto* marks = new QScatterSeries;
  marks->setMarkerSize(6);
  marks->setName("nodes");
  for (const PathPoint& p : points) {
    line->append(p.distance, p.value);
    marks->append(p.distance, p.value);
  }
  auto* chart = new QChart;
  chart->addSeries(line);
  chart->addSeries(marks);
  chart->setTitle(field + " along node set " + nset);
  auto* x = new QValueAxis;
  x->setTitleText("distance along the path");
  auto* y = new QValueAxis;
  y->setTitleText(field);
  y->setLabelFormat("%.3g");
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  for (QAbstractSeries* s : chart->series()) {
    s->attachAxis(x);
    s->attachAxis(y);
  }
  auto* view = new QChartView(chart);
  view->setObjectName("chart_view");
  view->setMinimumSize(560, 360);
  auto* layout = new QVBoxLayout(dialog);
  layout->addWidget(view);
  return dialog;
}

QDialog* make_history_chart(const std::vector<HistoryPoint>& points, const QStringList& labels,
                            const QString& field, const QString& node, QWidget* parent) {
  auto* dialog = new QDialog(parent);
  dialog->setWindowTitle(field + " at " + node + " over the increments");
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  auto* line = new QLineSeries;
  line->setName(field);
  auto* marks = new QScatterSeries;
  marks->setMarkerSize(6);
  marks->setName("increments");
  for (const HistoryPoint& p : points) {
    line->append(p.time, p.value);
    marks->append(p.time, p.value);
  }
  auto* chart = new QChart;
  chart->addSeries(line);
  chart->addSeries(marks);
  chart->setTitle(field + " at " + node + " vs increment");
  auto* x = new QValueAxis;
  x->setTitleText("total time");
  auto* y = new QValueAxis;
  // The ranges include time 0 and value 0 (the unloaded start), so one increment is a visible
  // point rather than a zero-width axis.
  double t_max = 0, v_min = 0, v_max = 0;
  for (const HistoryPoint& p : points)
    t_max = std::max(t_max, p.time), v_min = std::min(v_min, p.value),
    v_max = std::max(v_max, p.value);
  const double pad = 0.05 * (v_max - v_min);
  x->setRange(0.0, t_max > 0 ? 1.05 * t_max : 1.0);
  y->setRange(pad > 0 ? v_min - pad : -1.0, pad > 0 ? v_max + pad : 1.0);
  y->setTitleText(field);
  y->setLabelFormat("%.3g");
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  for (QAbstractSeries* s : chart->series()) {
    s->attachAxis(x);
    s->attachAxis(y);
  }
  auto* view = new QChartView(chart);
  view->setObjectName("history_view");
  view->setMinimumSize(560, 360);
  QString list;
  for (std::size_t i = 0; i < points.size(); ++i)
    list +=
        QString("%1: %2\n")
            .arg(i < std::size_t(labels.size()) ? labels[int(i)] : QString::number(points[i].time))
            .arg(points[i].value, 0, 'E', 4);
  auto* values = new QLabel(list.trimmed());
  values->setObjectName("history_values");
  values->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* layout = new QVBoxLayout(dialog);
  layout->addWidget(view);
  layout->addWidget(values);
  return dialog;
}

}  // namespace styk::gui
