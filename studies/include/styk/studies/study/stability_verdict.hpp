// The verdict of a stability sweep per family: where the error passes 10 %, and whether the
// solver's pre-solve warnings fired there (docs/stability.md; the warnings are tuned against it).
#pragma once

#include <string>
#include <vector>

#include "styk/studies/results/run_record.hpp"

namespace styk::studies {

// The error that decides pass or fail in a sweep, and the limit.
inline constexpr Measure kStabilityMeasure = Measure::PointDisplacement;
inline constexpr double kStabilityLimit = 0.10;

struct FamilyVerdict {
  std::string family;
  std::vector<double> failing;         // swept values with error > 10 % (or no result)
  std::vector<double> failing_warned;  // ... where a warning fired or the solver refused the run
  std::vector<double> missed;          // ... where none fired
  std::vector<double> false_alarms;    // values with error <= 10 % where a warning fired
  std::string kinds;  // the warning kinds that fired anywhere, e.g. "locking"; "refused": runs
                      // the solver refused
};

// One verdict per family of the sweep's runs, in order of appearance.
std::vector<FamilyVerdict> stability_verdicts(const std::vector<RunRecord>& records,
                                              const std::string& sweep);

}  // namespace styk::studies
