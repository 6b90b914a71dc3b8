// Progress lines on stderr for the long phases of an analysis, with their timings.
#pragma once

#include "styk/solver/analysis.hpp"

namespace styk::cli {

class StderrProgress : public ProgressSink {
 public:
  explicit StderrProgress(bool quiet) : quiet_(quiet) {}
  void begin(const std::string& phase) override;
  void end(const std::string& phase, double seconds) override;
  void info(const std::string& message) override;
  void warning(const std::string& message) override;  // printed even with -q

 private:
  bool quiet_;
};

}  // namespace styk::cli
