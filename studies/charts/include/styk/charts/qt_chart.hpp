// The Qt Charts chart of a Chart description: what write_png draws, and what the desktop program
// shows in a QChartView (zoom, hover tips). For Qt code only (the GUI and styk_charts itself).
#pragma once

#include <QChart>
#include <QString>

#include "styk/charts/chart_spec.hpp"

namespace styk::charts {

// A new QChart (the caller owns it, or hands it to a QChartView). Series keep the Point::tip
// texts as the "tips" property (a QStringList in point order) for hover tool tips.
QChart* make_qchart(const Chart& chart);

}  // namespace styk::charts
