#include "json_progress.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "styk/core/progress_protocol.hpp"

namespace styk::cli {
namespace {

nlohmann::json event(const char* name) {
  nlohmann::json line;
  line[progress_protocol::kVersionKey] = progress_protocol::kVersion;
  line["event"] = name;
  return line;
}

// One line, flushed at once, so a reader sees each event as it happens.
void emit(const nlohmann::json& line) {
  const std::string text = line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::fprintf(stderr, "%s\n", text.c_str());
  std::fflush(stderr);
}

}  // namespace

void JsonLinesProgress::begin(const std::string& phase) {
  nlohmann::json line = event("begin");
  line["phase"] = phase;
  emit(line);
}

void JsonLinesProgress::end(const std::string& phase, double seconds) {
  nlohmann::json line = event("end");
  line["phase"] = phase;
  line["seconds"] = seconds;
  emit(line);
}

void JsonLinesProgress::info(const std::string& message) {
  nlohmann::json line = event("info");
  line["message"] = message;
  emit(line);
}

void JsonLinesProgress::warning(const std::string& message) {
  nlohmann::json line = event("warning");
  line["message"] = message;
  emit(line);
}

std::string json_error_line(int exit_code, const std::string& kind, const std::string& file,
                            int line_number, const std::string& message) {
  nlohmann::json line = event("error");
  line["exit_code"] = exit_code;
  line["kind"] = kind;
  if (!file.empty()) {
    line["file"] = file;
    line["line"] = line_number;
  }
  line["message"] = message;
  return line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string json_done_line(const std::string& results, const std::string& report, long long dofs,
                           const std::string& linear_solver, int steps) {
  nlohmann::json line = event("done");
  line["results"] = results;
  line["report"] = report;
  line["dofs"] = dofs;
  line["linear_solver"] = linear_solver;
  line["steps"] = steps;
  return line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace styk::cli
