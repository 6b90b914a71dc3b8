#include "styk/render/color_scale.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "styk/core/diagnostics.hpp"

namespace styk::render {

double ColorScale::normalized(double value) const {
  const double width = max - min;
  if (!(width > 0.0)) return 0.0;
  return std::clamp((value - min) / width, 0.0, 1.0);
}

Rgb ColorScale::band_color(int i) const {
  if (!palette.empty())
    return palette[static_cast<std::size_t>(std::clamp(i, 0, int(palette.size()) - 1))];
  // The first band is pure blue and the last pure red, so the extremes read the same as on the
  // smooth scale.
  return rainbow(bands > 1 ? static_cast<double>(i) / (bands - 1) : 0.0);
}

std::vector<double> ColorScale::limits() const {
  std::vector<double> out(static_cast<std::size_t>(bands) + 1);
  for (int i = 0; i <= bands; ++i) out[i] = min + (max - min) * i / bands;
  out.back() = max;  // exact, whatever the rounding of the line above
  return out;
}

Rgb contact_status_color(int status) {
  switch (status) {
    case 0:
      return {0.0f, 0.35f, 1.0f};  // open
    case 1:
      return {0.0f, 0.75f, 0.0f};  // stick
    default:
      return {1.0f, 0.0f, 0.0f};  // slip
  }
}

Rgb neutral_face_color() { return {0.62f, 0.62f, 0.62f}; }

Rgb rainbow(double t) {
  t = std::clamp(t, 0.0, 1.0);
  const double hue = 4.0 * (1.0 - t);  // sextants of the colour wheel: 4 = blue, 0 = red
  const int sextant = std::min(static_cast<int>(hue), 3);
  const float f = static_cast<float>(hue - sextant);
  switch (sextant) {
    case 0:
      return {1.0f, f, 0.0f};  // red -> yellow
    case 1:
      return {1.0f - f, 1.0f, 0.0f};  // yellow -> green
    case 2:
      return {0.0f, 1.0f, f};  // green -> cyan
    default:
      return {0.0f, 1.0f - f, 1.0f};  // cyan -> blue
  }
}

std::string format_legend_value(double value) {
  if (value == 0.0) value = 0.0;  // no "-0.000E+00"
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3E", value);
  return buffer;
}

namespace {

int decade(double value) { return static_cast<int>(std::floor(std::log10(value))); }

}  // namespace

std::string NumberFormat::operator()(double value) const {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, scientific ? "%.*E" : "%.*f", decimals, value);
  std::string text = buffer;
  // A value that rounds to zero prints without a sign ("0.00", not "-0.00").
  if (text[0] == '-' && std::strtod(text.c_str(), nullptr) == 0.0) text.erase(0, 1);
  return text;
}

double NumberFormat::resolution(double value) const {
  const double unit = std::pow(10.0, -decimals);
  if (!scientific || value == 0.0) return 0.5 * unit;
  return 0.5 * unit * std::pow(10.0, decade(std::abs(value)));
}

NumberFormat number_format(double min, double max, int intervals) {
  NumberFormat format;
  const double magnitude = std::max(std::abs(min), std::abs(max));
  if (!(magnitude > 0) || !std::isfinite(magnitude)) {
    format.decimals = 0;
    return format;
  }
  double step = (max - min) / std::max(1, intervals);
  // A field uniform to 1e-7 (round-off): 4 digits, not the noise.
  if (!(step > 1e-7 * magnitude)) step = 1e-3 * magnitude;
  // The last digit printed: a tenth of the step's leading digit, and never coarser than the third
  // significant digit of the magnitude.
  const int last = std::min(decade(step) - 1, decade(magnitude) - 2);
  format.scientific = magnitude < 1e-3 || magnitude >= 1e6 || last < -6;
  format.decimals =
      format.scientific ? std::clamp(decade(magnitude) - last, 2, 8) : std::max(0, -last);
  return format;
}

NumberFormat number_format(const ColorScale& scale) {
  return number_format(scale.min, scale.max, scale.bands);
}

void check_band_count(int bands) {
  if (bands < kMinBands || bands > kMaxBands)
    throw InputError({}, "the number of contour bands must be " + std::to_string(kMinBands) + ".." +
                             std::to_string(kMaxBands) + ", not " + std::to_string(bands));
}

}  // namespace styk::render
