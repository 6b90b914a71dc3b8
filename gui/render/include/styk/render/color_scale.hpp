// The contour colour scale (SPEC §5): blue (minimum) to red (maximum), smooth or in 2..24 bands
// (default 12), and the numbers the legend prints at the band limits.
#pragma once

#include <string>
#include <vector>

#include "styk/render/color.hpp"

namespace styk::render {

constexpr int kMinBands = 2;
constexpr int kMaxBands = 24;
constexpr int kDefaultBands = 12;

struct ColorScale {
  ColorScale() = default;
  ColorScale(double min_value, double max_value, int band_count, bool smooth_colors)
      : min(min_value), max(max_value), bands(band_count), smooth(smooth_colors) {}

  double min = 0.0;
  double max = 1.0;
  int bands = kDefaultBands;  // number of colours of a banded scale; the legend's intervals
  bool smooth = false;        // continuous colours instead of bands
  // A discrete scale (CSTATUS): band i has colour palette[i] and is named labels[i]; the legend
  // prints the names instead of limits. Empty: the rainbow with numeric limits.
  std::vector<Rgb> palette;
  std::vector<std::string> labels;

  // Position of a value on the scale, 0 at min and 1 at max (clamped). A scale of zero width puts
  // everything at 0.
  double normalized(double value) const;
  // The colour of band i (0 = lowest) and the continuous colour at position t.
  Rgb band_color(int i) const;
  // bands + 1 limits from min to max.
  std::vector<double> limits() const;
};

// The colours of the contact status categories: open, stick, slip (blue, green, red; none of
// them grey, the colour of the faces without contact output).
Rgb contact_status_color(int status);
// The neutral grey of faces where a field has no value (e.g. away from the contact surfaces).
Rgb neutral_face_color();

// Continuous rainbow from blue (t = 0) over cyan, green and yellow to red (t = 1): the hue runs
// linearly from 240 to 0 degrees at full saturation, so equal steps in t give distinct colours.
Rgb rainbow(double t);

// How a single value is printed where no scale gives a precision (probe, title block's scale
// factor): 4 significant digits in scientific notation, "-1.235E+02".
std::string format_legend_value(double value);

// How the numbers of one colour scale are printed: as many digits as tell neighbouring band limits
// apart (the band width resolved to 2 significant digits, at least 3 significant digits in all),
// every number of the scale with the same digits after the point; fixed notation ("203.6",
// "0.0125") for magnitudes from 1e-3 to below 1e6, scientific ("2.04E+07") otherwise.
struct NumberFormat {
  bool scientific = false;
  int decimals = 3;  // after the point (of the mantissa when scientific)
  std::string operator()(double value) const;
  // Half a unit of the last printed digit at `value`: how far a printed number may lie from the
  // value it stands for.
  double resolution(double value) const;
};
// The format of a scale running from `min` to `max` in `intervals` equal steps.
NumberFormat number_format(double min, double max, int intervals);
// The format of this scale's limits (its bands; for a discrete scale unused).
NumberFormat number_format(const ColorScale& scale);

// Throws InputError when bands is outside kMinBands..kMaxBands.
void check_band_count(int bands);

}  // namespace styk::render
