#include "increment_control.hpp"

#include <algorithm>

namespace styk::solver_detail {

IncrementControl::IncrementControl(const StaticProcedure& procedure)
    : period_(procedure.total_time),
      max_increment_(procedure.max_increment.value_or(procedure.total_time)),
      min_increment_(procedure.min_increment.value_or(1e-5 * procedure.total_time)),
      fixed_(procedure.fixed_increments),
      dt_(std::min(procedure.initial_increment, max_increment_)) {
  dt_ = std::min(dt_, period_ - t_);
}

bool IncrementControl::finished() const { return !(t_ < period_ * (1.0 - 1e-12)); }

bool IncrementControl::can_cut() const { return !fixed_ && !(dt_ * kCut < min_increment_); }

void IncrementControl::cut() {
  dt_ *= kCut;
  quick_ = 0;
}

void IncrementControl::accept(int iterations) {
  t_ += dt_;
  last_dt_ = dt_;
  ++converged_;
  quick_ = iterations <= kIterationBudget ? quick_ + 1 : 0;
  if (!fixed_ && iterations <= kEasyIterations)
    dt_ = std::min(dt_ * 2.0, max_increment_);
  else if (!fixed_ && quick_ >= 2)
    dt_ = std::min(dt_ * kGrowth, max_increment_);
  dt_ = std::min(dt_, period_ - t_);
}

}  // namespace styk::solver_detail
