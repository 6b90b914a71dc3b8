// The X-Y charts of the results (Qt Charts), each in its own window: a field along a node set,
// and a field at one node over the load history (value vs increment, against the total time).
#pragma once

#include <QDialog>
#include <vector>

#include "session/path_plot.hpp"
#include "session/results_navigation.hpp"

namespace styk::gui {

QDialog* make_path_chart(const std::vector<PathPoint>& points, const QString& field,
                         const QString& nset, QWidget* parent);
// `labels`: one per point, the increment's name (results_navigation.hpp), listed with the values
// below the chart.
QDialog* make_history_chart(const std::vector<HistoryPoint>& points, const QStringList& labels,
                            const QString& field, const QString& node, QWidget* parent);

}  // namespace styk::gui
