#include "session/solve_protocol.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <regex>
#include <sstream>

namespace styk::gui {

std::vector<std::string> solve_arguments(const std::string& deck, const std::string& output_dir) {
  return {"solve", deck, "-o", output_dir};
}

SolveLine parse_solve_line(const std::string& raw) {
  SolveLine out;
  std::string line = raw;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  out.text = line;
  static const std::regex begin(R"(^styk: (\w+) \.\.\.$)");
  static const std::regex end(R"(^styk: (\w+) done in ([0-9.eE+-]+) s$)");
  static const std::regex located(R"(^(.+\.inp):(\d+): (.*)$)");
  std::smatch m;
  if (std::regex_match(line, m, begin)) {
    out.kind = SolveLine::Kind::PhaseBegin;
    out.phase = m[1];
  } else if (std::regex_match(line, m, end)) {
    out.kind = SolveLine::Kind::PhaseEnd;
    out.phase = m[1];
    out.seconds = std::strtod(m[2].str().c_str(), nullptr);
  } else if (line.rfind("styk:", 0) == 0) {
    out.kind = SolveLine::Kind::Info;
    const std::size_t first = line.find_first_not_of(' ', 5);
    out.text = first == std::string::npos ? std::string() : line.substr(first);
    static const std::string warning = "warning: ";
    if (out.text.rfind(warning, 0) == 0) {
      out.kind = SolveLine::Kind::Warning;
      out.text = out.text.substr(warning.size());
    }
  } else if (std::regex_match(line, m, located)) {
    out.kind = SolveLine::Kind::Error;
    out.where = SourceLoc{m[1], std::atoi(m[2].str().c_str())};
    out.text = m[3];
  } else if (line.rfind("not converged:", 0) == 0 || line.rfind("internal error:", 0) == 0) {
    out.kind = SolveLine::Kind::Error;
  } else if (const std::size_t at = line.find(".inp: "); at != std::string::npos) {
    out.kind = SolveLine::Kind::Error;  // a message about the deck as a whole ("no *STEP")
    out.where.file = line.substr(0, at + 4);
    out.text = line.substr(at + 6);
  }
  return out;
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

std::string results_path_from_summary(const std::string& stdout_text) {
  std::istringstream in(stdout_text);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("results: ", 0) == 0) return line.substr(9);
  return {};
}

}  // namespace styk::gui
