// The X-Y chart of a field along a node set (Qt Charts), in its own window.
#pragma once

#include <QDialog>
#include <vector>

#include "session/path_plot.hpp"

namespace styk::gui {

QDialog* make_path_chart(const std::vector<PathPoint>& points, const QString& field,
                         const QString& nset, QWidget* parent);

}  // namespace styk::gui
