// The atlas' charts built from study runs: error against DOF, wall time or element size on
// log-log axes, one series per element family with its fitted slope in the legend and the Pareto
// front marked; and error against a swept parameter (stability). The `styk study` pictures and
// the desktop program's chart window both come from here.
#pragma once

#include <string>
#include <vector>

#include "styk/charts/chart_spec.hpp"
#include "styk/studies/results/convergence.hpp"
#include "styk/studies/results/run_record.hpp"

namespace styk::studies {

// Error of measure `m` for every family of `problem` against `x` (Cost::Dof, Cost::Time or
// Cost::Size), log-log. Families are coloured by their index in `family_order` (so a family has
// one colour in every chart); the legend gives each family's slope over its last three levels,
// and (pareto) the Pareto front of all families is drawn behind them.
charts::Chart convergence_chart(const std::vector<RunRecord>& records, const std::string& problem,
                                Measure m, Cost x, const std::vector<std::string>& family_order,
                                bool pareto = true);

// The atlas picture of one problem: error against DOF and against wall time, side by side.
charts::Figure accuracy_figure(const std::vector<RunRecord>& records, const std::string& problem,
                               Measure m, const std::vector<std::string>& family_order);

// Error of measure `m` against the swept parameter of `sweep` (RunRecord::value), one series per
// family, with the 10 % line; log_x for parameters spanning decades.
charts::Chart sweep_chart(const std::vector<RunRecord>& records, const std::string& sweep,
                          Measure m, const std::vector<std::string>& family_order, bool log_x);

// "12 345" style thousands separation for DOF counts in tips and tables.
std::string group_thousands(long long n);

}  // namespace styk::studies
