#include "path_chart.hpp"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>
#include <QVBoxLayout>

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

}  // namespace styk::gui
