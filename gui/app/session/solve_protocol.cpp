#include "session/solve_protocol.hpp"

#include <array>

#include <nlohmann/json.hpp>

#include "styk/core/progress_protocol.hpp"

namespace styk::gui {
namespace {

std::string string_of(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

double number_of(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : 0.0;
}

// The event of a protocol line as a SolveLine; Other for an unknown event.
SolveLine from_event(const nlohmann::json& object, SolveLine out) {
  const std::string event = string_of(object, "event");
  if (event == "begin" || event == "end") {
    out.kind = event == "begin" ? SolveLine::Kind::PhaseBegin : SolveLine::Kind::PhaseEnd;
    out.phase = string_of(object, "phase");
    out.seconds = number_of(object, "seconds");
  } else if (event == "info" || event == "warning") {
    out.kind = event == "info" ? SolveLine::Kind::Info : SolveLine::Kind::Warning;
    out.text = string_of(object, "message");
  } else if (event == "error") {
    out.kind = SolveLine::Kind::Error;
    out.text = string_of(object, "message");
    out.where = SourceLoc{string_of(object, "file"), static_cast<int>(number_of(object, "line"))};
    out.exit_code = static_cast<int>(number_of(object, "exit_code"));
  } else if (event == "done") {
    out.kind = SolveLine::Kind::Done;
    out.results = string_of(object, "results");
  }
  return out;
}

}  // namespace

std::vector<std::string> solve_arguments(const std::string& deck, const std::string& output_dir) {
  return {"solve", deck, "-o", output_dir, "--progress", "json"};
}

SolveLine parse_solve_line(const std::string& raw) {
  SolveLine out;
  std::string line = raw;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  out.text = line;
  if (line.empty() || line.front() != '{') return out;  // not an event: text from elsewhere
  const nlohmann::json object = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
  if (!object.is_object()) return out;
  const auto version = object.find(progress_protocol::kVersionKey);
  if (version == object.end() || !version->is_number_integer() ||
      version->get<int>() != progress_protocol::kVersion)
    return out;  // another version of the protocol: shown as text, not misread
  return from_event(object, out);
}

int phase_progress(const std::string& phase) {
  static const std::array<std::pair<const char*, int>, 9> kPhases{{{"read", 2},
                                                                   {"check", 8},
                                                                   {"pattern", 10},
                                                                   {"assemble", 20},
                                                                   {"order", 45},
                                                                   {"factorise", 50},
                                                                   {"solve", 80},
                                                                   {"recover", 85},
                                                                   {"write", 95}}};
  for (const auto& [name, percent] : kPhases)
    if (phase == name) return percent;
  return -1;
}

}  // namespace styk::gui
