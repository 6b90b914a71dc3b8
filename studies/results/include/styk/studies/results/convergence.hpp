// What the atlas reads from a set of runs: fitted convergence slopes (error against element size
// or DOF on log-log axes), the Pareto front of error against cost, and the cheapest run that
// reaches an error target.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "styk/studies/results/run_record.hpp"

namespace styk::studies {

// Least-squares line through (log10 x, log10 y); nullopt with fewer than two usable points
// (x, y > 0 and finite) or no spread in x.
struct LogLogFit {
  double slope = 0.0;
  double intercept = 0.0;  // log10 y at log10 x = 0
  int points = 0;
};
std::optional<LogLogFit> fit_log_log(const std::vector<double>& x, const std::vector<double>& y);

// The runs of one problem and family that succeeded and have measure `m`, by level.
std::vector<const RunRecord*> series_of(const std::vector<RunRecord>& records,
                                        const std::string& problem, const std::string& family,
                                        Measure m);

enum class Cost { Dof, Time, Size };
double cost_of(const RunRecord& r, Cost c);

// Relative errors below this are at the round-off of the solves (double precision, condition
// numbers up to ~1e10): the fits leave them out.
inline constexpr double kRoundOffFloor = 1e-6;

// The slope of log(error) against log(cost) over the last `last` levels of the series whose
// error lies above kRoundOffFloor (the asymptotic range; all levels when `last` <= 0). Against the
// element size (Cost::Size) the slope is the convergence order p of error ~ h^p; against DOF it is
// -p/d for a mesh refined in d directions.
std::optional<LogLogFit> convergence_fit(const std::vector<const RunRecord*>& series, Measure m,
                                         Cost c, int last = 3);

// The runs (of any family) not beaten on both cost and error by another run: sorted by cost,
// each with a smaller error than every cheaper run.
std::vector<const RunRecord*> pareto_front(const std::vector<const RunRecord*>& runs, Measure m,
                                           Cost c);

// The cheapest run (by cost `c`) whose error is at most `target`; nullptr if none is.
const RunRecord* cheapest_reaching(const std::vector<const RunRecord*>& runs, Measure m, Cost c,
                                   double target);

// The problems and families of `records` in order of first appearance.
std::vector<std::string> problems_of(const std::vector<RunRecord>& records);
std::vector<std::string> families_of(const std::vector<RunRecord>& records);

}  // namespace styk::studies
