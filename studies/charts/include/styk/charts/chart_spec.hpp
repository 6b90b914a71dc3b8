// A chart as plain data: what a study wants drawn (series of points, axes, a legend), free of Qt
// types, so the studies (PNG pictures for the docs) and the desktop program (interactive charts)
// draw the same thing from the same description. Drawing is styk_charts' job (Qt Charts).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace styk::charts {

struct Point {
  double x = 0.0;
  double y = 0.0;
  std::string tip;  // what the desktop program shows when the mouse rests on the point
};

enum class SeriesStyle {
  LineAndMarkers,  // a polyline through the points with a marker on each
  Markers,         // markers only
  Line,            // a plain line (guides, fronts)
};

struct Series {
  std::string name;  // legend text; empty: not listed in the legend
  std::vector<Point> points;
  SeriesStyle style = SeriesStyle::LineAndMarkers;
  int colour = -1;  // index into the palette (palette_colour); -1: grey
  bool dashed = false;
  double width = 2.0;      // line width, pixels
  double marker = 7.0;     // marker diameter, pixels
  bool highlight = false;  // drawn wide and translucent behind the others (a Pareto front)
};

struct Axis {
  std::string title;
  bool log = false;  // log10 axis: points with a value <= 0 are left out
  std::optional<double> min, max;
};

struct Chart {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
};

// Charts side by side (`columns` per row) in one picture of width x height pixels.
struct Figure {
  std::vector<Chart> charts;
  int columns = 1;
  int width = 1600;
  int height = 700;
};

// The palette's colour `index` (wrapping) as 0xRRGGBB: ten colours that stay apart on screen and
// in print (the "tab10" set with black for its grey, which guides and fronts use); grey for a
// negative index.
inline unsigned palette_colour(int index) {
  constexpr unsigned kPalette[10] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                     0x8c564b, 0xe377c2, 0x000000, 0xbcbd22, 0x17becf};
  return index < 0 ? 0x808080u : kPalette[index % 10];
}

}  // namespace styk::charts
