// Pieces shared by the accuracy and stability pages (private to the studies).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "styk/charts/chart_spec.hpp"
#include "styk/studies/results/run_record.hpp"

namespace styk::studies::detail {

inline std::string fmt(const char* pattern, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, v);
  return buffer;
}

// The catalogue's families, then any other family of the records: the charts' colour order.
std::vector<std::string> family_order(const std::vector<RunRecord>& records);

// Draws `figure` into `path` through a temporary file renamed at the end.
void write_chart(const charts::Figure& figure, const std::string& path);

}  // namespace styk::studies::detail
