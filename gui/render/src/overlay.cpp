#include "styk/render/overlay.hpp"

#include <algorithm>
#include <cmath>

namespace styk::render {
namespace {

void add_rect(Overlay& o, float x0, float y0, float x1, float y1, const Rgb& c0, const Rgb& c1) {
  // c0 along the top edge, c1 along the bottom edge (vertical gradients of the smooth legend).
  const OverlayVertex a{x0, y0, {c0.r, c0.g, c0.b}}, b{x1, y0, {c0.r, c0.g, c0.b}},
      c{x1, y1, {c1.r, c1.g, c1.b}}, d{x0, y1, {c1.r, c1.g, c1.b}};
  o.triangles.insert(o.triangles.end(), {a, b, c, a, c, d});
}

// The colour bar of the legend: bands (top = maximum) or the continuous rainbow, with a thin ink
// frame so that the light end colours stand out from the paper.
void add_colour_bar(Overlay& o, const ColorScale& scale, int x, int top, int width,
                    int band_height) {
  const int bands = scale.bands;
  const float frame = 1.0f;
  add_rect(o, float(x) - frame, float(top) - frame, float(x + width) + frame,
           float(top + bands * band_height) + frame, kInk, kInk);
  if (!scale.smooth) {
    for (int i = 0; i < bands; ++i) {
      const int y0 = top + i * band_height;
      const Rgb c = scale.band_color(bands - 1 - i);
      add_rect(o, float(x), float(y0), float(x + width), float(y0 + band_height), c, c);
    }
    return;
  }
  // The rainbow is piecewise linear in RGB with knots at quarters of the scale: slices on a
  // multiple of 4 make the per-vertex interpolation exact.
  const int slices = 96;
  const double total = double(bands) * band_height;
  for (int k = 0; k < slices; ++k) {
    const double y0 = top + total * k / slices, y1 = top + total * (k + 1) / slices;
    add_rect(o, float(x), float(y0), float(x + width), float(y1), rainbow(1.0 - double(k) / slices),
             rainbow(1.0 - double(k + 1) / slices));
  }
}

}  // namespace

int text_pixels_for(int height) {
  return std::max(11, static_cast<int>(std::lround(height / 50.0)));
}

int pixel_scale_for(int height) { return std::max(1, (height + 200) / 400); }

void add_overlay_text(Overlay& o, Typeface& typeface, const TextItem& item, const Rgb& ink) {
  typeface.layout(item.text, item.x, item.y, item.pixels, ink, o.glyphs);
  o.texts.push_back(item);
}

void refresh_atlas(Overlay& o, Typeface& typeface) { o.atlas = typeface.atlas(); }

Overlay build_overlay(const OverlayContent& content, int width, int height, Typeface& typeface) {
  Overlay o;
  const int px = text_pixels_for(height);
  const int line = typeface.line_height(px);
  const int margin = std::max(6, (2 * px) / 3);

  // Title block, bottom-left.
  const int title_lines = static_cast<int>(content.title_lines.size());
  int title_width = 0;
  for (const std::string& text : content.title_lines)
    title_width = std::max(title_width, typeface.text_width(text, px));
  const int title_height = title_lines > 0 ? title_lines * line + margin : 0;
  o.title = PixelRect{margin, height - title_height, title_width, title_height - margin};
  for (int i = 0; i < title_lines; ++i)
    add_overlay_text(o, typeface,
                     TextItem{content.title_lines[i], margin, height - title_height + i * line, px},
                     kInk);

  int legend_width = 0;
  if (content.colors) {
    const ColorScale& scale = *content.colors;
    const int bands = scale.bands;
    const int bar_width = std::max(8, px);
    const int top = margin + (content.legend_heading.empty() ? 0 : line + px / 3);
    const int available = height - title_height - top - margin - line;
    const int band_height = std::max(2, std::min(3 * line / 2, available / bands));
    const int bar_x = margin;
    const int bar_top = top + line / 2;
    if (!content.legend_heading.empty())
      add_overlay_text(o, typeface, TextItem{content.legend_heading, margin, margin, px}, kInk);
    add_colour_bar(o, scale, bar_x, bar_top, bar_width, band_height);
    // Limits: label i at the boundary below band i from the top, i.e. the maximum first. A
    // discrete scale names its bands instead, each name beside the middle of its band.
    const bool named = !scale.labels.empty();
    const std::vector<double> limits = scale.limits();
    const NumberFormat format = number_format(scale);
    const int label_x = bar_x + bar_width + px / 2 + 1;
    int label_width = 0;
    for (int i = 0; i <= bands; ++i) {
      if (named && i == bands) break;
      const int y = bar_top + i * band_height - line / 2 + (named ? band_height / 2 : 0);
      const std::string text =
          named ? scale.labels[static_cast<std::size_t>(bands - 1 - i)] : format(limits[bands - i]);
      const TextItem label{text, label_x, y, px};
      add_overlay_text(o, typeface, label, kInk);
      o.legend_labels.push_back(label);
      label_width = std::max(label_width, typeface.text_width(label.text, px));
    }
    legend_width = label_x + label_width + margin;
    legend_width =
        std::max(legend_width, margin + typeface.text_width(content.legend_heading, px) + margin);
    o.legend = PixelRect{0, 0, legend_width, bar_top + bands * band_height + line};
  }
  o.model = PixelRect{legend_width, 0, std::max(1, width - legend_width),
                      std::max(1, height - title_height)};
  if (content.label_glyphs) {
    o.label_pixels = std::max(10, (px * 5) / 6);
    for (int c = 32; c <= 126; ++c)
      o.label_glyphs[static_cast<std::size_t>(c - 32)] =
          typeface.glyph(char32_t(c), o.label_pixels);
  }
  refresh_atlas(o, typeface);
  return o;
}

}  // namespace styk::render
