#include "styk/charts/qt_chart.hpp"

#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPen>
#include <QScatterSeries>
#include <QStringList>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>

namespace styk::charts {
namespace {

QColor colour_of(const Series& s) {
  const unsigned rgb = palette_colour(s.colour);
  QColor c((rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff);
  if (s.highlight) c.setAlphaF(0.35);
  return c;
}

bool plottable(const Point& p, const Chart& chart) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  return (!chart.x.log || p.x > 0) && (!chart.y.log || p.y > 0);
}

QXYSeries* make_series(const Series& s, const Chart& chart) {
  QXYSeries* series = nullptr;
  if (s.style == SeriesStyle::Markers) {
    auto* scatter = new QScatterSeries;
    scatter->setMarkerSize(s.marker);
    scatter->setBorderColor(colour_of(s));
    series = scatter;
  } else {
    auto* line = new QLineSeries;
    if (s.style == SeriesStyle::LineAndMarkers) {
      line->setPointsVisible(true);
      line->setMarkerSize(s.marker);
    }
    series = line;
  }
  QPen pen(colour_of(s));
  pen.setWidthF(s.highlight ? std::max(8.0, 4 * s.width) : s.width);
  if (s.dashed) pen.setStyle(Qt::DashLine);
  pen.setCapStyle(Qt::RoundCap);
  series->setPen(pen);
  series->setColor(colour_of(s));
  series->setName(QString::fromStdString(s.name));
  QStringList tips;
  for (const Point& p : s.points) {
    if (!plottable(p, chart)) continue;
    series->append(p.x, p.y);
    tips << QString::fromStdString(p.tip);
  }
  series->setProperty("tips", tips);
  return series;
}

// The data range of one axis over every plottable point (a log axis gets whole decades).
std::pair<double, double> data_range(const Chart& chart, bool x_axis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : chart.series)
    for (const Point& p : s.points)
      if (plottable(p, chart)) {
        const double v = x_axis ? p.x : p.y;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
  const Axis& axis = x_axis ? chart.x : chart.y;
  if (!std::isfinite(lo)) return axis.log ? std::make_pair(0.1, 10.0) : std::make_pair(0.0, 1.0);
  if (axis.log) {
    // Whole decades, with room for a point that sits on one.
    lo = std::pow(10.0, std::floor(std::log10(lo) - 0.05));
    hi = std::pow(10.0, std::ceil(std::log10(hi) + 0.05));
    if (hi <= lo) hi = lo * 10;
  } else {
    // A little room around the data, but no negative range for data that has none.
    const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1.0, std::abs(lo)) * 0.1;
    lo = lo >= 0 ? std::max(0.0, lo - pad) : lo - pad;
    hi += pad;
  }
  return {axis.min.value_or(lo), axis.max.value_or(hi)};
}

QAbstractAxis* make_axis(const Chart& chart, bool x_axis) {
  const Axis& spec = x_axis ? chart.x : chart.y;
  const auto [lo, hi] = data_range(chart, x_axis);
  QAbstractAxis* axis = nullptr;
  if (spec.log) {
    auto* log = new QLogValueAxis;
    log->setBase(10.0);
    log->setLabelFormat("%g");
    log->setMinorTickCount(-1);  // the 2..9 ticks of every decade
    log->setRange(lo, hi);
    axis = log;
  } else {
    auto* value = new QValueAxis;
    value->setLabelFormat("%g");
    value->setRange(lo, hi);
    value->applyNiceNumbers();
    axis = value;
  }
  axis->setTitleText(QString::fromStdString(spec.title));
  return axis;
}

}  // namespace

QChart* make_qchart(const Chart& chart) {
  auto* q = new QChart;
  q->setTitle(QString::fromStdString(chart.title));
  QFont title_font = q->titleFont();
  title_font.setPointSizeF(title_font.pointSizeF() * 1.2);
  title_font.setBold(true);
  q->setTitleFont(title_font);
  QAbstractAxis* x = make_axis(chart, true);
  QAbstractAxis* y = make_axis(chart, false);
  q->addAxis(x, Qt::AlignBottom);
  q->addAxis(y, Qt::AlignLeft);
  // Highlights first, so they lie behind the data.
  for (int pass = 0; pass < 2; ++pass)
    for (const Series& s : chart.series) {
      if (s.highlight != (pass == 0)) continue;
      QXYSeries* series = make_series(s, chart);
      q->addSeries(series);
      series->attachAxis(x);
      series->attachAxis(y);
      if (s.name.empty())
        for (QLegendMarker* m : q->legend()->markers(series)) m->setVisible(false);
    }
  q->legend()->setAlignment(Qt::AlignRight);
  q->legend()->setShowToolTips(true);
  return q;
}

}  // namespace styk::charts
