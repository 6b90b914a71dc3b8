#include "styk/studies/results/run_record.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace styk::studies {
namespace {

// Columns in file order; the error columns follow kMeasures.
const std::vector<std::string>& columns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> c = {"study", "problem",  "family", "level", "parameter", "value", "h",
                                  "dof",   "elements", "time_s", "runs",  "memory_mb"};
    for (Measure m : kMeasures) c.push_back(measure_key(m));
    c.insert(c.end(), {"warnings", "quantities", "failure"});
    return c;
  }();
  return names;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string joined(const std::vector<std::string>& items, char separator) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : std::string(1, separator)) + s;
  return out;
}

std::vector<std::string> split_fields(const std::string& row, const std::string& name, int line) {
  std::vector<std::string> fields(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < row.size(); ++i) {
    const char c = row[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < row.size() && row[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  if (in_quotes) throw StudyCsvError(name, line, "unterminated quote");
  return fields;
}

std::vector<std::string> split_list(const std::string& s, char separator) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, separator))
    if (!item.empty()) out.push_back(item);
  return out;
}

class FieldReader {
 public:
  FieldReader(const std::vector<std::string>& fields, std::string name, int line)
      : fields_(fields), name_(std::move(name)), line_(line) {}
  const std::string& text(int column) const { return fields_[column]; }
  double real(int column) const {
    const std::string& s = fields_[column];
    if (s.empty()) return kNaN;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (*end != '\0' || errno != 0) fail(column, "'" + s + "' is not a number");
    return v;
  }
  long long integer(int column) const {
    const double v = real(column);
    if (std::isnan(v)) return 0;
    if (v != std::floor(v)) fail(column, "'" + fields_[column] + "' is not an integer");
    return static_cast<long long>(v);
  }
  [[noreturn]] void fail(int column, const std::string& message) const {
    throw StudyCsvError(name_, line_, "column " + columns()[column] + ": " + message);
  }

 private:
  const std::vector<std::string>& fields_;
  std::string name_;
  int line_;
};

}  // namespace

StudyCsvError::StudyCsvError(std::string file, int line, std::string message)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + message),
      file_(std::move(file)),
      line_(line),
      message_(std::move(message)) {}

const char* measure_key(Measure m) {
  switch (m) {
    case Measure::PointDisplacement:
      return "err_u_point";
    case Measure::PointStress:
      return "err_s_point";
    case Measure::DisplacementL2:
      return "err_u_l2";
    case Measure::Energy:
      return "err_energy";
    case Measure::ContactPressure:
      return "err_contact_p";
  }
  return "";
}

const char* measure_label(Measure m) {
  switch (m) {
    case Measure::PointDisplacement:
      return "displacement error at the named point";
    case Measure::PointStress:
      return "stress error at the named point";
    case Measure::DisplacementL2:
      return "L2 displacement error";
    case Measure::Energy:
      return "energy-norm error";
    case Measure::ContactPressure:
      return "contact-pressure error (worst node)";
  }
  return "";
}

std::optional<Measure> measure_from_key(const std::string& key) {
  for (Measure m : kMeasures)
    if (key == measure_key(m)) return m;
  return std::nullopt;
}

std::string csv_header() { return joined(columns(), ','); }

std::string csv_row(const RunRecord& r) {
  std::vector<std::string> f = {r.study,
                                r.problem,
                                r.family,
                                std::to_string(r.level),
                                r.parameter,
                                number(r.value),
                                number(r.h),
                                std::to_string(r.dof),
                                std::to_string(r.elements),
                                number(r.time_s),
                                std::to_string(r.runs),
                                number(r.memory_mb)};
  for (const std::optional<double>& e : r.error) f.push_back(e ? number(*e) : "");
  f.push_back(joined(r.warnings, ';'));
  std::vector<std::string> quantities;
  for (const auto& [name, v] : r.quantities) quantities.push_back(name + "=" + number(v));
  f.push_back(joined(quantities, ';'));
  f.push_back(r.failure);
  std::string out;
  for (std::size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + quoted(f[i]);
  return out;
}

void write_csv(std::ostream& out, const std::vector<RunRecord>& records) {
  out << csv_header() << '\n';
  for (const RunRecord& r : records) out << csv_row(r) << '\n';
}

RunRecord parse_csv_row(const std::string& row, const std::string& name, int line) {
  const std::vector<std::string> fields = split_fields(row, name, line);
  const int n = static_cast<int>(columns().size());
  if (static_cast<int>(fields.size()) != n)
    throw StudyCsvError(
        name, line,
        "expected " + std::to_string(n) + " columns, found " + std::to_string(fields.size()));
  const FieldReader in(fields, name, line);
  RunRecord r;
  int c = 0;
  r.study = in.text(c++);
  r.problem = in.text(c++);
  r.family = in.text(c++);
  r.level = static_cast<int>(in.integer(c++));
  r.parameter = in.text(c++);
  r.value = in.real(c++);
  r.h = in.real(c++);
  r.dof = in.integer(c++);
  r.elements = static_cast<int>(in.integer(c++));
  r.time_s = in.real(c++);
  r.runs = static_cast<int>(in.integer(c++));
  r.memory_mb = in.real(c++);
  for (int m = 0; m < kMeasureCount; ++m, ++c) {
    const double v = in.real(c);
    if (!std::isnan(v)) r.error[m] = v;
  }
  r.warnings = split_list(in.text(c++), ';');
  for (const std::string& item : split_list(in.text(c), ';')) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) in.fail(c, "'" + item + "' is not NAME=VALUE");
    const std::string text = item.substr(eq + 1);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') in.fail(c, "'" + item + "': the value is not a number");
    r.quantities[item.substr(0, eq)] = v;
  }
  ++c;
  r.failure = in.text(c++);
  if (r.study.empty() || r.problem.empty() || r.family.empty())
    throw StudyCsvError(name, line, "study, problem and family must not be empty");
  return r;
}

std::vector<RunRecord> read_csv(std::istream& in, const std::string& name) {
  std::string line;
  if (!std::getline(in, line)) throw StudyCsvError(name, 1, "empty file");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line != csv_header())
    throw StudyCsvError(name, 1,
                        "not a study CSV (the header differs from '" + csv_header() + "')");
  std::vector<RunRecord> records;
  int number_of_line = 1;
  while (std::getline(in, line)) {
    ++number_of_line;
    if (line.empty() || line == "\r") continue;
    records.push_back(parse_csv_row(line, name, number_of_line));
  }
  return records;
}

}  // namespace styk::studies
