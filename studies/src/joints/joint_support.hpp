// Pieces every joint study uses (private to the studies): build and solve one model with its wall
// time and contact iterations, stresses, nodes by position, chart series.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "styk/charts/chart_spec.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/studies/joints/joint_report.hpp"

namespace styk::studies::joints {

constexpr double kPi = 3.14159265358979323846;

struct SolvedModel {
  Model model;
  Results results;
  double seconds = 0.0;  // build and solve
  int iterations = 0;    // contact iterations over all increments
};

// Runs `builder` with `args` (the calibrating builders get a static solve), solves every step and
// adds a line "what: elements, dofs, contact iterations, seconds" to `report.models`.
SolvedModel build_and_solve(const std::string& builder,
                            const std::map<std::string, std::string>& args,
                            const ElementRegistry& registry, const JointOptions& options,
                            const std::string& what, JointReport& report);

double mises(const Tensor6& s);

// The largest integration-point Mises stress over the elements of `elset` whose centre satisfies
// `where` (all when empty).
double largest_mises(const Model& model, const IncrementResult& increment, const std::string& elset,
                     const std::function<bool(const Vec3& centre)>& where = {});

// The same with each element's Mises stress of its mean integration-point stress (the element
// mean docs/mesher.md quotes for the joints): no single point's extrapolation peak.
double largest_element_mises(const Model& model, const IncrementResult& increment,
                             const std::string& elset,
                             const std::function<bool(const Vec3& centre)>& where = {});

// Where the largest element-mean Mises stress of `elset` sits: its value, the element's centre and
// the largest integration-point Mises stress of that element.
struct StressPeak {
  double mean = 0.0;
  double point = 0.0;
  Vec3 centre{0, 0, 0};
};
StressPeak element_mises_peak(const Model& model, const IncrementResult& increment,
                              const std::string& elset,
                              const std::function<bool(const Vec3& centre)>& where = {});

// The last increment of step `step` (1-based); std::runtime_error when the step has none.
const IncrementResult& end_of_step(const Results& results, int step);

// The node at `at` (within 1e-6); std::runtime_error when the model has none there.
int node_at(const Model& model, const Vec3& at);

inline double radius(const Vec3& x) { return std::hypot(x[0], x[1]); }

// A polyline series of `colour` (palette index) through (x[i], y[i]).
charts::Series line(const std::string& name, const std::vector<double>& x,
                    const std::vector<double>& y, int colour, bool markers = true);
// A horizontal guide at `y` from x0 to x1 (dashed, grey unless `colour` >= 0).
charts::Series guide(const std::string& name, double x0, double x1, double y, int colour = -1);

std::string fixed(double value, int decimals);

}  // namespace styk::studies::joints
