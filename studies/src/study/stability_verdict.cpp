#include "styk/studies/study/stability_verdict.hpp"

#include <algorithm>

#include "styk/studies/results/convergence.hpp"

namespace styk::studies {

std::vector<FamilyVerdict> stability_verdicts(const std::vector<RunRecord>& records,
                                              const std::string& sweep) {
  std::vector<RunRecord> of_sweep;
  for (const RunRecord& r : records)
    if (r.problem == sweep) of_sweep.push_back(r);
  std::vector<FamilyVerdict> out;
  for (const std::string& family : families_of(of_sweep)) {
    FamilyVerdict v;
    v.family = family;
    std::vector<const RunRecord*> runs;
    for (const RunRecord& r : of_sweep)
      if (r.family == family) runs.push_back(&r);
    std::sort(runs.begin(), runs.end(),
              [](const RunRecord* a, const RunRecord* b) { return a->value < b->value; });
    std::vector<std::string> kinds;
    for (const RunRecord* r : runs) {
      const std::optional<double> e = r->error_of(kStabilityMeasure);
      const bool fails = !r->ok() || !e || *e > kStabilityLimit;
      // A run the solver refused (no result) told its user with an error: the loudest warning.
      const bool warned = !r->warnings.empty() || !r->ok();
      for (const std::string& k : r->warnings)
        if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
      if (fails) {
        v.failing.push_back(r->value);
        (warned ? v.failing_warned : v.missed).push_back(r->value);
      } else if (warned) {
        v.false_alarms.push_back(r->value);
      }
    }
    for (const RunRecord* r : runs)
      if (!r->ok() && std::find(kinds.begin(), kinds.end(), "refused") == kinds.end())
        kinds.push_back("refused");
    for (const std::string& k : kinds) v.kinds += (v.kinds.empty() ? "" : ", ") + k;
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace styk::studies
