#include "joint_support.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"
#include "styk/studies/static_solve.hpp"

namespace styk::studies::joints {
namespace {

// Counts the solver's contact iterations from its progress lines.
class IterationCount : public ProgressSink {
 public:
  void begin(const std::string&) override {}
  void end(const std::string&, double) override {}
  void info(const std::string& line) override {
    if (line.find(" iteration ") != std::string::npos) ++iterations;
  }
  int iterations = 0;
};

}  // namespace

SolvedModel build_and_solve(const std::string& builder,
                            const std::map<std::string, std::string>& args,
                            const ElementRegistry& registry, const JointOptions& options,
                            const std::string& what, JointReport& report) {
  const auto start = std::chrono::steady_clock::now();
  SolvedModel solved;
  solved.model = mesher::run_builder(builder, args, registry, static_solve(registry)).model;
  IterationCount count;
  solved.results = run_static_analysis(solved.model, registry, SolveOptions{}, &count, nullptr);
  solved.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  solved.iterations = count.iterations;
  report.seconds += solved.seconds;
  std::string command = "styk mesh " + builder;
  for (const auto& [name, value] : args) command += " --" + name + " " + value;
  char line[512];
  std::snprintf(line, sizeof line,
                "%s (`%s`): %d elements, %d nodes, %d contact iterations, %.1f s", what.c_str(),
                command.c_str(), solved.model.element_count(), solved.model.node_count(),
                solved.iterations, solved.seconds);
  report.models.push_back(line);
  if (options.progress) options.progress(line);
  return solved;
}

double mises(const Tensor6& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

namespace {

Vec3 centre_of(const Model& model, int e) {
  const int* nodes = model.element_nodes(e);
  const int count = model.elements[e].node_count;
  Vec3 centre{0, 0, 0};
  for (int k = 0; k < count; ++k)
    for (int d = 0; d < 3; ++d) centre[d] += model.coords[nodes[k]][d] / count;
  return centre;
}

}  // namespace

double largest_mises(const Model& model, const IncrementResult& increment, const std::string& elset,
                     const std::function<bool(const Vec3& centre)>& where) {
  double largest = 0;
  for (int e : model.elsets.at(elset).elements) {
    if (where && !where(centre_of(model, e))) continue;
    for (int i = increment.ip_offset[e]; i < increment.ip_offset[e + 1]; ++i)
      largest = std::max(largest, mises(increment.S[i]));
  }
  return largest;
}

StressPeak element_mises_peak(const Model& model, const IncrementResult& increment,
                              const std::string& elset,
                              const std::function<bool(const Vec3& centre)>& where) {
  StressPeak peak;
  for (int e : model.elsets.at(elset).elements) {
    const Vec3 centre = centre_of(model, e);
    if (where && !where(centre)) continue;
    Tensor6 mean{};
    double point = 0;
    const int first = increment.ip_offset[e], end = increment.ip_offset[e + 1];
    for (int i = first; i < end; ++i) {
      for (int c = 0; c < 6; ++c) mean[c] += increment.S[i][c] / (end - first);
      point = std::max(point, mises(increment.S[i]));
    }
    if (end > first && mises(mean) > peak.mean) peak = {mises(mean), point, centre};
  }
  return peak;
}

double largest_element_mises(const Model& model, const IncrementResult& increment,
                             const std::string& elset,
                             const std::function<bool(const Vec3& centre)>& where) {
  return element_mises_peak(model, increment, elset, where).mean;
}

const IncrementResult& end_of_step(const Results& results, int step) {
  const IncrementResult* last = nullptr;
  for (const IncrementResult& inc : results.increments)
    if (inc.step == step) last = &inc;
  if (!last) throw std::runtime_error("no converged increment in step " + std::to_string(step));
  return *last;
}

int node_at(const Model& model, const Vec3& at) {
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    if (std::hypot(x[0] - at[0], x[1] - at[1], x[2] - at[2]) < 1e-6) return n;
  }
  throw std::runtime_error("the model has no node at (" + fixed(at[0], 3) + ", " + fixed(at[1], 3) +
                           ", " + fixed(at[2], 3) + ")");
}

charts::Series line(const std::string& name, const std::vector<double>& x,
                    const std::vector<double>& y, int colour, bool markers) {
  charts::Series s;
  s.name = name;
  s.colour = colour;
  s.style = markers ? charts::SeriesStyle::LineAndMarkers : charts::SeriesStyle::Line;
  s.marker = 5.0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) s.points.push_back({x[i], y[i], ""});
  return s;
}

charts::Series guide(const std::string& name, double x0, double x1, double y, int colour) {
  charts::Series s = line(name, {x0, x1}, {y, y}, colour, false);
  s.dashed = true;
  s.width = 1.5;
  return s;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

}  // namespace styk::studies::joints
