#include "styk/studies/results/convergence.hpp"

#include <algorithm>
#include <cmath>

namespace styk::studies {

std::optional<LogLogFit> fit_log_log(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0) || !std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
    const double lx = std::log10(x[i]), ly = std::log10(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
    ++n;
  }
  if (n < 2) return std::nullopt;
  const double det = n * sxx - sx * sx;
  if (!(std::abs(det) > 1e-12 * std::max(1.0, n * sxx))) return std::nullopt;
  LogLogFit fit;
  fit.slope = (n * sxy - sx * sy) / det;
  fit.intercept = (sy - fit.slope * sx) / n;
  fit.points = n;
  return fit;
}

std::vector<const RunRecord*> series_of(const std::vector<RunRecord>& records,
                                        const std::string& problem, const std::string& family,
                                        Measure m) {
  std::vector<const RunRecord*> out;
  for (const RunRecord& r : records)
    if (r.ok() && r.problem == problem && r.family == family && r.error_of(m)) out.push_back(&r);
  std::stable_sort(out.begin(), out.end(),
                   [](const RunRecord* a, const RunRecord* b) { return a->level < b->level; });
  return out;
}

double cost_of(const RunRecord& r, Cost c) {
  switch (c) {
    case Cost::Dof:
      return static_cast<double>(r.dof);
    case Cost::Time:
      return r.time_s;
    case Cost::Size:
      return r.h;
  }
  return kNaN;
}

std::optional<LogLogFit> convergence_fit(const std::vector<const RunRecord*>& series, Measure m,
                                         Cost c, int last) {
  std::vector<const RunRecord*> above;
  for (const RunRecord* r : series)
    if (*r->error_of(m) > kRoundOffFloor) above.push_back(r);
  const std::size_t first =
      last > 0 && above.size() > static_cast<std::size_t>(last) ? above.size() - last : 0;
  std::vector<double> x, y;
  for (std::size_t i = first; i < above.size(); ++i) {
    x.push_back(cost_of(*above[i], c));
    y.push_back(*above[i]->error_of(m));
  }
  return fit_log_log(x, y);
}

std::vector<const RunRecord*> pareto_front(const std::vector<const RunRecord*>& runs, Measure m,
                                           Cost c) {
  std::vector<const RunRecord*> usable;
  for (const RunRecord* r : runs)
    if (r->ok() && r->error_of(m) && std::isfinite(cost_of(*r, c))) usable.push_back(r);
  std::sort(usable.begin(), usable.end(), [&](const RunRecord* a, const RunRecord* b) {
    const double ca = cost_of(*a, c), cb = cost_of(*b, c);
    return ca != cb ? ca < cb : *a->error_of(m) < *b->error_of(m);
  });
  std::vector<const RunRecord*> front;
  double best = INFINITY;
  for (const RunRecord* r : usable)
    if (*r->error_of(m) < best) {
      best = *r->error_of(m);
      front.push_back(r);
    }
  return front;
}

const RunRecord* cheapest_reaching(const std::vector<const RunRecord*>& runs, Measure m, Cost c,
                                   double target) {
  const RunRecord* best = nullptr;
  for (const RunRecord* r : runs) {
    if (!r->ok() || !r->error_of(m) || *r->error_of(m) > target) continue;
    if (!std::isfinite(cost_of(*r, c))) continue;
    if (!best || cost_of(*r, c) < cost_of(*best, c)) best = r;
  }
  return best;
}

namespace {
template <typename Key>
std::vector<std::string> first_appearance(const std::vector<RunRecord>& records, Key key) {
  std::vector<std::string> out;
  for (const RunRecord& r : records)
    if (std::find(out.begin(), out.end(), key(r)) == out.end()) out.push_back(key(r));
  return out;
}
}  // namespace

std::vector<std::string> problems_of(const std::vector<RunRecord>& records) {
  return first_appearance(records, [](const RunRecord& r) { return r.problem; });
}

std::vector<std::string> families_of(const std::vector<RunRecord>& records) {
  return first_appearance(records, [](const RunRecord& r) { return r.family; });
}

}  // namespace styk::studies
