#include "results_check_structure.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include "h5_util.hpp"
#include "results_schema.hpp"

namespace styk::io {
namespace {

// "/steps/step_<k>/increment_<n>" must hold the increment whose attributes say k and n.
void check_group_names(hid_t file, ResultsCheck& report) {
  const h5::Handle steps = h5::open_group(file, "steps");
  for (const std::string& step_name : h5::link_names(steps.get())) {
    const h5::Handle step = h5::open_group(steps.get(), step_name);
    for (const std::string& name : h5::link_names(step.get())) {
      const h5::Handle group = h5::open_group(step.get(), name);
      const std::int64_t k = h5::read_int_attribute(group.get(), "step");
      const std::int64_t n = h5::read_int_attribute(group.get(), "increment");
      if (step_name != schema::step_group(static_cast<int>(k)) ||
          name != schema::increment_group(static_cast<int>(n)))
        report.problems.push_back("group /steps/" + step_name + "/" + name + " holds step " +
                                  std::to_string(k) + ", increment " + std::to_string(n));
    }
  }
}

void check_times(const Results& results, ResultsCheck& report) {
  std::set<int> steps;
  const IncrementResult* previous = nullptr;
  for (const IncrementResult& inc : results.increments) {
    steps.insert(inc.step);
    const std::string label =
        "step " + std::to_string(inc.step) + ", increment " + std::to_string(inc.increment);
    if (inc.step_time < 0.0 || inc.step_time > inc.total_time)
      report.problems.push_back(label + ": step time " + std::to_string(inc.step_time) +
                                " is not within 0 .. total time " + std::to_string(inc.total_time));
    if (previous && inc.total_time < previous->total_time)
      report.problems.push_back(label + " ends at total time " + std::to_string(inc.total_time) +
                                ", before the increment ahead of it (" +
                                std::to_string(previous->total_time) + ")");
    if (previous && previous->step == inc.step && inc.step_time < previous->step_time)
      report.problems.push_back(label + " ends at step time " + std::to_string(inc.step_time) +
                                ", before the increment ahead of it");
    previous = &inc;
  }
  report.steps = static_cast<int>(steps.size());
  report.increments = static_cast<int>(results.increments.size());
}

template <typename Set, typename Members>
void check_sorted(const std::map<std::string, Set>& sets, Members members, const char* kind,
                  ResultsCheck& report) {
  for (const auto& [name, set] : sets) {
    const auto& v = members(set);
    if (std::adjacent_find(v.begin(), v.end(), [](int a, int b) { return a >= b; }) != v.end())
      report.problems.push_back(std::string(kind) + " set " + name +
                                " is not sorted without repeats");
  }
}

void check_contact_pairs(const Results& results, ResultsCheck& report) {
  for (const IncrementResult& inc : results.increments) {
    if (inc.contact.empty() || inc.contact_pairs.empty()) continue;
    for (const ContactNodeResult& c : inc.contact)
      if (c.pair >= static_cast<int>(inc.contact_pairs.size())) {
        report.problems.push_back("step " + std::to_string(inc.step) + ", increment " +
                                  std::to_string(inc.increment) + ": contact row of pair " +
                                  std::to_string(c.pair) + " but only " +
                                  std::to_string(inc.contact_pairs.size()) + " pairs");
        break;
      }
  }
}

}  // namespace

void check_structure(hid_t file, const ResultsFileContents& contents, ResultsCheck& report) {
  try {
    check_group_names(file, report);
  } catch (const std::runtime_error& e) {
    report.problems.push_back(std::string("the steps cannot be listed: ") + e.what());
  }
  check_times(contents.results, report);
  check_sorted(
      contents.model.nsets, [](const NodeSet& s) -> const std::vector<int>& { return s.nodes; },
      "node", report);
  check_sorted(
      contents.model.elsets,
      [](const ElementSet& s) -> const std::vector<int>& { return s.elements; }, "element", report);
  check_contact_pairs(contents.results, report);
}

}  // namespace styk::io
