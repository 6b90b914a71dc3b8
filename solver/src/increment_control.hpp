// The load increments of one step of the contact driver (docs/contact.md, "Increments and
// steps"): fixed increments with *STATIC, DIRECT; otherwise automatic, a failed increment retried
// with a quarter of its size down to the minimum, the size grown after easy increments.
#pragma once

#include "styk/core/model.hpp"

namespace styk::solver_detail {

class IncrementControl {
 public:
  explicit IncrementControl(const StaticProcedure& procedure);

  bool finished() const;
  // The increment to try next ends at step time end() = start() + size(), at the step fraction
  // tau() of the linear load ramp.
  double start() const { return t_; }
  double size() const { return dt_; }
  double end() const { return t_ + dt_; }
  double tau() const { return end() / period_; }
  bool fixed() const { return fixed_; }
  int converged_count() const { return converged_; }
  // dt_new / dt_last within the step (ActiveSetOptions::extrapolation; 0 before the first
  // converged increment of the step).
  double extrapolation() const { return last_dt_ > 0.0 ? dt_ / last_dt_ : 0.0; }

  // After a failure: whether a smaller increment may be tried (automatic, above the minimum).
  bool can_cut() const;
  double cut_size() const { return dt_ * kCut; }
  void cut();
  // After convergence in `iterations`: the step time advances and the next size is chosen.
  void accept(int iterations);

  // Within the iteration budget of docs/contact.md: "quick" increments let the size grow. A
  // tighter limit (5) kept the shrink-fit push at 1/90 of the step for 100 increments of 6
  // iterations each.
  static constexpr int kIterationBudget = 8;
  // An increment that converged in this many iterations (the predictor was nearly right) doubles
  // the size at once; otherwise two quick increments in a row grow it by kGrowth.
  static constexpr int kEasyIterations = 3;
  static constexpr double kGrowth = 1.5;
  static constexpr double kCut = 0.25;

 private:
  double period_, max_increment_, min_increment_;
  bool fixed_;
  double dt_;
  double t_ = 0.0;
  double last_dt_ = 0.0;  // the last converged increment of this step (0: none yet)
  int converged_ = 0;
  int quick_ = 0;  // converged increments in a row within the budget
};

}  // namespace styk::solver_detail
