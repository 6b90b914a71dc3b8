// The SPEC §4 joint studies (`styk study shrink-fit | conical-fit | spline | p3g | bolted-flange`):
// each builds its models with the mesher's builders, solves them and gathers a report: headline
// figures beside the thesis' published values and the hand formulas, data tables (CSV) and
// charts (drawn with styk_charts). The report is plain data, so tests assert its figures on a
// coarse mesh through the same code that writes the documentation at the default density.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "styk/charts/chart_spec.hpp"
#include "styk/core/element_registry.hpp"

namespace styk::studies {

// One number the report's summary quotes.
struct Headline {
  std::string key;    // stable name, e.g. "leak_15kN" (tests look figures up by it)
  std::string label;  // what it is, for the table
  double value = 0.0;
  std::string unit;       // "MPa", "N m", ...
  std::string published;  // the thesis' value (SPEC.md), "" when it gives none
  std::string hand;       // the hand formula's value, "" when SPEC gives none
};

// A data table: one CSV file next to the report.
struct DataTable {
  std::string name;  // file stem suffix: <joint>-<name>.csv
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

struct JointChart {
  std::string name;     // file stem suffix: <joint>-<name>.png
  std::string caption;  // the sentence under the picture
  charts::Figure figure;
};

struct JointReport {
  std::string joint;                // "shrink-fit", ...
  std::string title;                // page title
  std::string summary;              // the model(s) and what was done, Markdown
  std::vector<std::string> models;  // one line per solved model: mesh, sizes, wall time
  std::vector<Headline> headlines;
  std::vector<DataTable> tables;
  std::vector<JointChart> charts;
  std::vector<std::string> findings;  // the differences from the thesis and their measured causes
  double seconds = 0.0;               // wall time of all builds and solves
  // The headline `key`'s value; std::out_of_range naming it when missing.
  double figure(const std::string& key) const;
};

struct JointOptions {
  // Coarse meshes (those the tests use): the same models and measurements, a few seconds each.
  bool coarse = false;
  std::function<void(const std::string&)> progress;  // one line per model solved; may be empty
};

// The joints `styk study` knows, in SPEC order.
const std::vector<std::string>& joint_studies();
bool is_joint_study(const std::string& name);

// Builds, solves and measures; throws what the builders and the solver throw.
JointReport run_joint_study(const std::string& joint, const ElementRegistry& registry,
                            const JointOptions& options);

// Where a joint report goes: DIR/joints/<joint>.md with its CSV files beside it, the charts in
// DIR/images/joints (--docs DIR), or everything in one directory (-o DIR).
struct JointLayout {
  std::string markdown;
  std::string data_dir;    // CSV files
  std::string data_link;   // the CSV directory as the page links it
  std::string image_dir;   // PNG files
  std::string image_link;  // the PNG directory as the page links it
};
JointLayout joint_docs_layout(const std::string& docs_dir, const std::string& joint);
JointLayout joint_output_layout(const std::string& dir, const std::string& joint);

std::string joint_markdown(const JointReport& report, const std::string& command,
                           const std::string& machine, const JointLayout& layout);
// Writes the CSV files, the charts and the page, each complete or not at all.
void write_joint_report(const JointReport& report, const std::string& command,
                        const std::string& machine, const JointLayout& layout);

}  // namespace styk::studies
