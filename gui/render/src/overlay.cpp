#include "styk/render/overlay.hpp"

#include <algorithm>

#include "styk/render/font.hpp"

namespace styk::render {
namespace {

void add_rect(Overlay& o, float x0, float y0, float x1, float y1, const Rgb& c0, const Rgb& c1) {
  // c0 along the top edge, c1 along the bottom edge (vertical gradients of the smooth legend).
  const OverlayVertex a{x0, y0, {c0.r, c0.g, c0.b}}, b{x1, y0, {c0.r, c0.g, c0.b}},
      c{x1, y1, {c1.r, c1.g, c1.b}}, d{x0, y1, {c1.r, c1.g, c1.b}};
  o.triangles.insert(o.triangles.end(), {a, b, c, a, c, d});
}

void add_text(Overlay& o, const TextItem& item, const Rgb& ink) {
  int x = item.x;
  for (char ch : item.text) {
    const auto& rows = glyph(ch);
    for (int r = 0; r < kGlyphHeight; ++r)
      for (int col = 0; col < kGlyphWidth; ++col)
        if (rows[r] & (0x10 >> col)) {
          const float px = float(x + col * item.scale), py = float(item.y + r * item.scale);
          add_rect(o, px, py, px + item.scale, py + item.scale, ink, ink);
        }
    x += kGlyphAdvance * item.scale;
  }
  o.texts.push_back(item);
}

}  // namespace

int text_scale_for(int height) { return std::max(1, (height + 200) / 400); }

Overlay build_overlay(const OverlayContent& content, int width, int height) {
  Overlay o;
  const int s = text_scale_for(height);
  const int margin = 8 * s;
  const int line = kLineAdvance * s;

  // Title block, bottom-left.
  const int title_lines = static_cast<int>(content.title_lines.size());
  int title_width = 0;
  for (const std::string& text : content.title_lines)
    title_width = std::max(title_width, text_width(text, s));
  const int title_height = title_lines > 0 ? title_lines * line + margin : 0;
  o.title = PixelRect{margin, height - title_height, title_width, title_height - margin};
  for (int i = 0; i < title_lines; ++i)
    add_text(o, TextItem{content.title_lines[i], margin, height - title_height + i * line, s},
             kInk);

  int legend_width = 0;
  if (content.colors) {
    const ColorScale& scale = *content.colors;
    const int bands = scale.bands;
    const int bar_width = 6 * s;
    const int top = margin + (content.legend_heading.empty() ? 0 : line + s * 4);
    const int available = height - title_height - top - margin - kGlyphHeight * s;
    const int band_height = std::max(2, std::min(3 * line / 2, available / bands));
    const int bar_x = margin;
    const int bar_top = top + kGlyphHeight * s / 2;
    if (!content.legend_heading.empty())
      add_text(o, TextItem{content.legend_heading, margin, margin, s}, kInk);
    // Bands, top = maximum.
    if (!scale.smooth) {
      for (int i = 0; i < bands; ++i) {
        const int y0 = bar_top + i * band_height;
        const Rgb c = scale.band_color(bands - 1 - i);
        add_rect(o, float(bar_x), float(y0), float(bar_x + bar_width), float(y0 + band_height), c,
                 c);
      }
    } else {
      // The rainbow is piecewise linear in RGB with knots at quarters of the scale: slices on a
      // multiple of 4 make the per-vertex interpolation exact.
      const int slices = 96;
      const double total = double(bands) * band_height;
      for (int k = 0; k < slices; ++k) {
        const double y0 = bar_top + total * k / slices, y1 = bar_top + total * (k + 1) / slices;
        add_rect(o, float(bar_x), float(y0), float(bar_x + bar_width), float(y1),
                 rainbow(1.0 - double(k) / slices), rainbow(1.0 - double(k + 1) / slices));
      }
    }
    // Limits: label i at the boundary below band i from the top, i.e. the maximum first. A
    // discrete scale names its bands instead, each name beside the middle of its band.
    const bool named = !scale.labels.empty();
    const std::vector<double> limits = scale.limits();
    const int label_x = bar_x + bar_width + 3 * s;
    int label_width = 0;
    for (int i = 0; i <= bands; ++i) {
      if (named && i == bands) break;
      const int y =
          bar_top + i * band_height - kGlyphHeight * s / 2 + (named ? band_height / 2 : 0);
      const std::string text = named ? scale.labels[static_cast<std::size_t>(bands - 1 - i)]
                                     : format_legend_value(limits[bands - i]);
      const TextItem label{text, label_x, y, s};
      add_text(o, label, kInk);
      o.legend_labels.push_back(label);
      label_width = std::max(label_width, text_width(label.text, s));
    }
    legend_width = label_x + label_width + margin;
    legend_width = std::max(legend_width, margin + text_width(content.legend_heading, s) + margin);
    o.legend = PixelRect{0, 0, legend_width, bar_top + bands * band_height + kGlyphHeight * s};
  }
  o.model = PixelRect{legend_width, 0, std::max(1, width - legend_width),
                      std::max(1, height - title_height)};
  return o;
}

}  // namespace styk::render
