#include "styk/studies/results/atlas_charts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace styk::studies {
namespace {

std::string format(const char* pattern, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, v);
  return buffer;
}

int colour_of(const std::vector<std::string>& order, const std::string& family) {
  const auto it = std::find(order.begin(), order.end(), family);
  return it == order.end() ? -1 : static_cast<int>(it - order.begin());
}

const char* axis_title(Cost c) {
  switch (c) {
    case Cost::Dof:
      return "degrees of freedom";
    case Cost::Time:
      return "wall time of the solve, s (median)";
    case Cost::Size:
      return "element size h";
  }
  return "";
}

std::string tip(const RunRecord& r, Measure m) {
  std::string t = r.family + ", level " + std::to_string(r.level);
  if (!r.parameter.empty()) t += ", " + r.parameter + " = " + format("%g", r.value);
  t += ": " + group_thousands(r.dof) + " DOF, " + format("%.3g s", r.time_s);
  if (std::isfinite(r.memory_mb)) t += ", " + format("%.0f MB", r.memory_mb);
  t += ", error " + format("%.3g", *r.error_of(m));
  if (!r.warnings.empty()) {
    t += ", warned:";
    for (const std::string& w : r.warnings) t += " " + w;
  }
  return t;
}

std::vector<std::string> families_in(const std::vector<RunRecord>& records,
                                     const std::vector<std::string>& order) {
  std::vector<std::string> out = order;
  for (const std::string& f : families_of(records))
    if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
  return out;
}

}  // namespace

std::string group_thousands(long long n) {
  std::string digits = std::to_string(n < 0 ? -n : n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return n < 0 ? "-" + out : out;
}

charts::Chart convergence_chart(const std::vector<RunRecord>& records, const std::string& problem,
                                Measure m, Cost x, const std::vector<std::string>& family_order,
                                bool pareto) {
  charts::Chart chart;
  chart.title = problem + ": " + measure_label(m) + " vs " +
                (x == Cost::Dof    ? "DOF"
                 : x == Cost::Time ? "wall time"
                                   : "element size");
  chart.x = {axis_title(x), true, {}, {}};
  chart.y = {std::string(measure_label(m)) + " (relative)", true, {}, {}};
  std::vector<const RunRecord*> all;
  for (const std::string& family : families_in(records, family_order)) {
    const std::vector<const RunRecord*> series = series_of(records, problem, family, m);
    if (series.empty()) continue;
    all.insert(all.end(), series.begin(), series.end());
    charts::Series s;
    s.name = family;
    if (const auto fit = convergence_fit(series, m, x))
      s.name += (x == Cost::Size ? "  order " : "  slope ") + format("%.2f", fit->slope);
    s.colour = colour_of(family_order, family);
    for (const RunRecord* r : series)
      s.points.push_back({cost_of(*r, x), *r->error_of(m), tip(*r, m)});
    chart.series.push_back(std::move(s));
  }
  if (pareto && x != Cost::Size) {
    charts::Series front;
    front.name = "Pareto front";
    front.style = charts::SeriesStyle::Line;
    front.highlight = true;
    front.colour = -1;
    for (const RunRecord* r : pareto_front(all, m, x))
      front.points.push_back({cost_of(*r, x), *r->error_of(m), "Pareto: " + tip(*r, m)});
    if (front.points.size() > 1) chart.series.insert(chart.series.begin(), std::move(front));
  }
  return chart;
}

charts::Figure accuracy_figure(const std::vector<RunRecord>& records, const std::string& problem,
                               Measure m, const std::vector<std::string>& family_order) {
  charts::Figure figure;
  figure.columns = 2;
  figure.width = 2000;
  figure.height = 760;
  figure.charts = {convergence_chart(records, problem, m, Cost::Dof, family_order),
                   convergence_chart(records, problem, m, Cost::Time, family_order)};
  return figure;
}

charts::Chart sweep_chart(const std::vector<RunRecord>& records, const std::string& sweep,
                          Measure m, const std::vector<std::string>& family_order, bool log_x) {
  charts::Chart chart;
  std::string parameter;
  for (const RunRecord& r : records)
    if (r.problem == sweep && !r.parameter.empty()) parameter = r.parameter;
  chart.title = sweep + ": " + measure_label(m) + " vs " + parameter;
  chart.x = {parameter, log_x, {}, {}};
  chart.y = {std::string(measure_label(m)) + " (relative)", true, {}, {}};
  double lo = INFINITY, hi = -INFINITY;
  for (const std::string& family : families_in(records, family_order)) {
    std::vector<const RunRecord*> runs;
    for (const RunRecord& r : records)
      if (r.ok() && r.problem == sweep && r.family == family && r.error_of(m)) runs.push_back(&r);
    if (runs.empty()) continue;
    std::sort(runs.begin(), runs.end(),
              [](const RunRecord* a, const RunRecord* b) { return a->value < b->value; });
    charts::Series s;
    s.name = family;
    s.colour = colour_of(family_order, family);
    for (const RunRecord* r : runs) {
      s.points.push_back({r->value, *r->error_of(m), tip(*r, m)});
      if (!log_x || r->value > 0) lo = std::min(lo, r->value), hi = std::max(hi, r->value);
    }
    chart.series.push_back(std::move(s));
  }
  if (lo < hi) {
    charts::Series limit;
    limit.name = "10 % error";
    limit.style = charts::SeriesStyle::Line;
    limit.dashed = true;
    limit.points = {{lo, 0.1, "10 %"}, {hi, 0.1, "10 %"}};
    chart.series.push_back(std::move(limit));
  }
  return chart;
}

}  // namespace styk::studies
