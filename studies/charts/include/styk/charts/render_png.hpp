// Draws a Figure into a PNG file with Qt Charts, off-screen: no window and no display are needed
// (Qt's offscreen platform is chosen when the process has no QApplication and no
// QT_QPA_PLATFORM). No Qt types in this header.
#pragma once

#include <string>

#include "styk/charts/chart_spec.hpp"

namespace styk::charts {

// Writes `figure` to `path` (PNG). Throws std::runtime_error when the file cannot be written.
void write_png(const Figure& figure, const std::string& path);

}  // namespace styk::charts
