// Reader of .dat reports (ours or CalculiX's): blocks start at a "... for set X and time T"
// header; every following non-empty line up to the next header is one row.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "styk/io/dat_reader.hpp"

namespace styk {

namespace {

std::string trim(const std::string& s) {
  const std::size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// Accepts Fortran's three-digit exponents without the letter ("1.000000-100") as well as C's.
bool parse_number(const std::string& token, double& value) {
  const char* begin = token.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  if (end == begin) return false;
  if (*end == '\0') return true;
  if ((*end == '+' || *end == '-') && end > begin && end[-1] >= '0' && end[-1] <= '9') {
    char* exponent_end = nullptr;
    const long exponent = std::strtol(end, &exponent_end, 10);
    if (*exponent_end != '\0' || exponent_end == end + 1) return false;
    value *= std::pow(10.0, static_cast<double>(exponent));
    return true;
  }
  return false;
}

bool parse_integer(const std::string& token, long long& value) {
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return !token.empty() && *end == '\0';
}

// How many leading integer columns a block's rows have, read off its header.
int id_columns(const std::string& what) {
  if (what.rfind("total", 0) == 0) return 0;
  if (what.find("(elem, integ.pnt.") != std::string::npos) return 2;
  return 1;
}

[[noreturn]] void bad_line(int line_number, const std::string& why, const std::string& line) {
  throw std::runtime_error(".dat line " + std::to_string(line_number) + ": " + why + ": \"" +
                           trim(line) + "\"");
}

}  // namespace

std::vector<DatBlock> parse_dat_blocks(std::istream& in) {
  std::vector<DatBlock> blocks;
  bool in_block = false;
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    const std::string text = trim(line);
    if (text.empty()) continue;
    const bool statistics = text.rfind("statistics for surface set ", 0) == 0;
    const std::size_t for_set =
        statistics ? text.find(" for surface set ") : text.find(" for set ");
    const std::size_t set_at = for_set + (statistics ? 17 : 9);
    const std::size_t and_time = text.rfind(" and time ");
    if (for_set != std::string::npos && and_time != std::string::npos && and_time > for_set) {
      DatBlock block;
      block.what = trim(text.substr(0, for_set));
      block.set = trim(text.substr(set_at, and_time - set_at));
      if (!parse_number(trim(text.substr(and_time + 10)), block.time))
        bad_line(line_number, "cannot read the time", line);
      blocks.push_back(std::move(block));
      in_block = true;
      continue;
    }
    if (!in_block) continue;
    DatBlock& block = blocks.back();
    std::istringstream tokens(text);
    std::string token;
    DatRow row;
    if (block.what == "statistics") {
      double first = 0.0;
      if (!parse_number(text.substr(0, text.find(' ')), first)) continue;  // a title line
    }
    const int ids = block.what == "statistics" ? 0 : id_columns(block.what);
    for (int column = 0; tokens >> token; ++column) {
      if (column < ids) {
        long long integer = 0;
        if (!parse_integer(token, integer)) bad_line(line_number, "expected an integer id", line);
        if (column == 0)
          row.id = integer;
        else
          row.integration_point = static_cast<int>(integer);
      } else if (token == "L" && !row.values.empty() && !(tokens >> std::ws).good()) {
        row.local = true;  // the last token: ccx marks a row in a node's local system
      } else {
        double value = 0.0;
        if (!parse_number(token, value)) {
          // The last token may name the *ORIENTATION the element results are printed in.
          if (row.values.empty() || (tokens >> std::ws).good())
            bad_line(line_number, "expected a number", line);
          row.label = token;
          continue;
        }
        row.values.push_back(value);
      }
    }
    if (row.values.empty()) bad_line(line_number, "row without values", line);
    block.rows.push_back(std::move(row));
  }
  return blocks;
}

std::vector<DatDisplacements> parse_dat_displacements(std::istream& in) {
  std::vector<DatDisplacements> out;
  for (const DatBlock& block : parse_dat_blocks(in)) {
    if (block.what.rfind("displacements", 0) != 0) continue;
    DatDisplacements* entry = nullptr;
    for (DatDisplacements& d : out)
      if (d.time == block.time) entry = &d;
    if (entry == nullptr) {
      out.push_back(DatDisplacements{block.time, {}});
      entry = &out.back();
    }
    for (const DatRow& row : block.rows) {
      if (row.values.size() != 3)
        throw std::runtime_error(".dat displacement row of node " + std::to_string(row.id) +
                                 " has " + std::to_string(row.values.size()) +
                                 " values (expected 3)");
      entry->u[row.id] = {row.values[0], row.values[1], row.values[2]};
    }
  }
  return out;
}

}  // namespace styk
