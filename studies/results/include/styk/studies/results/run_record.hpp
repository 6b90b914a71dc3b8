// One run of a study (a model built, solved and measured) as plain data, and the studies' CSV
// files: one row per run. Free of the solver and of Qt, so the desktop program reads the same
// files the studies write (docs/studies.md describes the columns).
#pragma once

#include <array>
#include <iosfwd>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace styk::studies {

// The errors a run records, each relative to the exact solution (dimensionless, 0.01 = 1 %).
enum class Measure {
  PointDisplacement,  // a displacement (temperature) component at the problem's named point
  PointStress,        // a stress (heat-flux) component at its named point, nodal average (I)
  DisplacementL2,     // || u_h - u ||_L2 / || u ||_L2 over the body
  Energy,             // energy norm of the error over the energy norm of u (stresses)
  ContactPressure,    // largest contact-pressure error over the slave nodes, over the exact one
};
inline constexpr int kMeasureCount = 5;
inline constexpr std::array<Measure, kMeasureCount> kMeasures = {
    Measure::PointDisplacement, Measure::PointStress, Measure::DisplacementL2, Measure::Energy,
    Measure::ContactPressure};
const char* measure_key(Measure m);    // CSV column, e.g. "err_energy"
const char* measure_label(Measure m);  // for charts and tables, e.g. "energy-norm error"
std::optional<Measure> measure_from_key(const std::string& key);

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct RunRecord {
  std::string study;      // accuracy, stability, model-size
  std::string problem;    // e.g. lame, cantilever
  std::string family;     // element family, e.g. C3D20
  int level = 0;          // refinement level (0 = coarsest)
  std::string parameter;  // the swept parameter (stability), empty otherwise
  double value = kNaN;    // its value
  double h = kNaN;        // characteristic element size
  long long dof = 0;      // unknowns of the linear system
  int elements = 0;
  double time_s = kNaN;     // median wall time of the solves (build and error evaluation excluded)
  int runs = 0;             // number of timed solves
  double memory_mb = kNaN;  // peak resident memory of the run's own process; NaN if not isolated
  std::array<std::optional<double>, kMeasureCount> error{};  // kMeasures order
  std::vector<std::string> warnings;  // solver warnings that fired: locking, hourglass, distortion
  std::map<std::string, double> quantities;  // absolute results (model-size study), by name
  std::string failure;                       // why the run gave no result; empty = it did

  std::optional<double> error_of(Measure m) const { return error[static_cast<int>(m)]; }
  bool ok() const { return failure.empty(); }
};

// The CSV header line (no newline) and one row per record.
std::string csv_header();
std::string csv_row(const RunRecord& record);
void write_csv(std::ostream& out, const std::vector<RunRecord>& records);
// A malformed study CSV: what() is "FILE:LINE: message".
class StudyCsvError : public std::runtime_error {
 public:
  StudyCsvError(std::string file, int line, std::string message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string message_;
};

// Reads a file written by write_csv. Throws StudyCsvError for a malformed file (a foreign header,
// missing columns, bad numbers), naming the line and the column.
std::vector<RunRecord> read_csv(std::istream& in, const std::string& name);
// One row (no header) as written by csv_row.
RunRecord parse_csv_row(const std::string& row, const std::string& name, int line);

}  // namespace styk::studies
