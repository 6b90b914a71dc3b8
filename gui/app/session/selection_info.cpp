#include "session/selection_info.hpp"

#include <algorithm>
#include <cstdio>

#include "session/results_navigation.hpp"
#include "styk/render/color_scale.hpp"

namespace styk::gui {
namespace {

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

std::string point(const Vec3& x) {
  return "(" + number(x[0]) + ", " + number(x[1]) + ", " + number(x[2]) + ")";
}

std::string field_text(const Scene& scene, const std::optional<double>& value) {
  if (!scene.field() || !value) return std::string();
  const render::ScalarField& f = *scene.field();
  if (!f.categories.empty() && *value >= 0 && *value < double(f.categories.size()))
    return "  " + f.name + " = " + f.categories[std::size_t(*value)];
  return "  " + f.name + " = " + render::format_legend_value(*value);
}

std::string element_text(const Model& model, int e) {
  return "element " + std::to_string(model.elements[e].id) + " " + model.elements[e].type;
}

}  // namespace

std::vector<std::string> describe_selection(const Scene& scene, const Selection& selection,
                                            std::size_t limit) {
  std::vector<std::string> lines;
  const Model* model = scene.model();
  if (!model) return lines;
  std::size_t total = 0;
  const auto add = [&](std::string line) {
    if (++total <= limit) lines.push_back(std::move(line));
  };
  for (int n : selection.nodes())
    if (n >= 0 && n < model->node_count())
      add("node " + std::to_string(model->node_ids[n]) + " " + point(model->coords[n]) +
          field_text(scene, scene.value_at_node(n)));
  for (int e : selection.elements()) {
    if (e < 0 || e >= model->element_count()) continue;
    Vec3 centroid{0, 0, 0};
    const Element& el = model->elements[e];
    for (int k = 0; k < el.node_count; ++k)
      for (int i = 0; i < 3; ++i)
        centroid[i] += model->coords[model->element_nodes(e)[k]][i] / el.node_count;
    std::optional<double> value;
    if (scene.field()) value = field_at_element(*model, *scene.field(), e);
    add(element_text(*model, e) + ", centroid " + point(centroid) + field_text(scene, value));
  }
  for (const SurfaceFace& f : selection.faces())
    if (f.element >= 0 && f.element < model->element_count())
      add(element_text(*model, f.element) + " face S" + std::to_string(f.face));
  if (total > limit) lines.push_back("... and " + std::to_string(total - limit) + " more");
  return lines;
}

std::string selection_summary(const Scene& scene, const Selection& selection) {
  if (selection.empty()) return std::string();
  if (selection.size() == 1) {
    const std::vector<std::string> lines = describe_selection(scene, selection, 1);
    return lines.empty() ? std::string() : lines.front();
  }
  return std::to_string(selection.size()) + " " + pick_kind_name(selection.kind()) + "s selected";
}

std::string element_probe_summary(const ElementProbe& probe) {
  std::string text = "element " + std::to_string(probe.element_id) + " " + probe.type + ": " +
                     probe.field + " at " + std::to_string(probe.points.size()) +
                     " integration points";
  if (probe.points.empty()) return text;
  double lo = probe.points.front().value, hi = lo;
  for (const render::PointValue& p : probe.points)
    lo = std::min(lo, p.value), hi = std::max(hi, p.value);
  return text + ", " + render::format_legend_value(lo) + " .. " + render::format_legend_value(hi);
}

std::vector<std::string> describe_element_probe(const ElementProbe& probe) {
  std::vector<std::string> lines;
  for (const render::PointValue& p : probe.points)
    lines.push_back("point " + std::to_string(p.number) + " " + point(p.natural) + " at " +
                    point(p.position) + ": " + render::format_legend_value(p.value));
  return lines;
}

}  // namespace styk::gui
