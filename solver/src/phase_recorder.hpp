// Times the phases of an analysis and forwards them to the (optional) ProgressSink and
// AnalysisReport, so the solver code only says "this is the assemble phase".
#pragma once

#include <chrono>
#include <string>

#include "styk/solver/analysis.hpp"

namespace styk::solver_detail {

class PhaseRecorder {
 public:
  PhaseRecorder(ProgressSink* sink, AnalysisReport* report) : sink_(sink), report_(report) {}

  void info(const std::string& message) const {
    if (sink_ != nullptr) sink_->info(message);
  }
  void warning(const std::string& message) const {
    if (report_ != nullptr) report_->warnings.push_back(message);
    if (sink_ != nullptr) sink_->warning(message);
  }

  // begin() on construction, end() with the elapsed seconds on destruction (also when unwinding,
  // so a GUI closes its progress bar when the phase throws).
  class Scope {
   public:
    Scope(const PhaseRecorder& owner, std::string phase)
        : owner_(owner), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {
      if (owner_.sink_ != nullptr) owner_.sink_->begin(phase_);
    }
    ~Scope() {
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      if (owner_.report_ != nullptr) owner_.report_->timings.push_back({phase_, seconds});
      if (owner_.sink_ != nullptr) owner_.sink_->end(phase_, seconds);
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    const PhaseRecorder& owner_;
    std::string phase_;
    std::chrono::steady_clock::time_point start_;
  };

  AnalysisReport* report() const { return report_; }

 private:
  ProgressSink* sink_;
  AnalysisReport* report_;
};

}  // namespace styk::solver_detail
