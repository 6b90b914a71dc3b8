// The studies' output: the CSV of the runs, the charts (PNG, drawn with styk_charts) and a
// Markdown page that embeds them with the tables read from the runs, all generated, each file
// written under a temporary name and renamed when complete.
#pragma once

#include <string>
#include <vector>

#include "styk/studies/results/run_record.hpp"

namespace styk::studies {

struct ReportLayout {
  std::string markdown;    // the page
  std::string csv;         // the runs
  std::string image_dir;   // the charts
  std::string image_link;  // the charts' directory as the page links it
  std::string csv_link;    // the CSV as the page links it
};
// `styk study NAME --docs DIR`: DIR/NAME.md, DIR/atlas/NAME.csv, DIR/images/atlas/NAME-*.png.
ReportLayout docs_layout(const std::string& docs_dir, const std::string& study);
// `styk study NAME -o DIR`: everything in DIR.
ReportLayout output_layout(const std::string& dir, const std::string& study);

struct ReportContext {
  std::string command;  // the command that made the runs
  std::string machine;  // machine_description()
  long long max_dof = 0;
  double max_seconds = 0;
  int repeats = 0;
  bool isolated = true;            // each run in a child process of its own
  std::vector<std::string> notes;  // e.g. families not available
};

// "CPU model, N cores, M GB, OS" from /proc and /etc/os-release.
std::string machine_description();

// The pages (tested on their own) and the complete reports.
std::string accuracy_markdown(const std::vector<RunRecord>& records, const ReportContext& context,
                              const ReportLayout& layout);
std::string stability_markdown(const std::vector<RunRecord>& records, const ReportContext& context,
                               const ReportLayout& layout);
void write_accuracy_report(const std::vector<RunRecord>& records, const ReportContext& context,
                           const ReportLayout& layout);
void write_stability_report(const std::vector<RunRecord>& records, const ReportContext& context,
                            const ReportLayout& layout);
std::string model_size_markdown(const std::vector<RunRecord>& records, const ReportContext& context,
                                const ReportLayout& layout);
void write_model_size_report(const std::vector<RunRecord>& records, const ReportContext& context,
                             const ReportLayout& layout);

// The picture file of one problem (or sweep) of a study, e.g. "accuracy-lame.png".
std::string chart_file(const std::string& study, const std::string& problem);

// Writes `text` to `path` through a temporary file renamed at the end (std::runtime_error on
// failure; nothing is left half-written).
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace styk::studies
