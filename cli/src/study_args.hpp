// `styk study`: the studies (docs/cli.md, docs/accuracy.md, docs/stability.md): refinement series
// and stability sweeps against exact solutions, the shrink-fit model-size comparison, one run of
// any of them, and the SPEC §4 joint reports (docs/joints.md).
#pragma once

#include <string>
#include <vector>

namespace styk::cli {

struct StudyArgs {
  std::string kind;  // run, accuracy, stability, model-size, or a joint (shrink-fit, ...)
  // run: one model of one problem
  std::string study = "accuracy";
  std::string problem;
  std::string family;
  int level = 0;
  int repeats = 3;
  // accuracy, stability, model-size
  std::vector<std::string> problems;  // empty: all
  std::vector<std::string> families;  // empty: every available family
  long long max_dof = 500000;
  double max_seconds = 120;
  int max_levels = 0;
  bool in_process = false;  // no child process per run (no memory figures)
  bool list = false;        // list the problems and families
  std::string output_dir;   // -o DIR: the CSV, the charts and the Markdown page
  std::string docs_dir;     // --docs DIR: DIR/<study>.md, DIR/atlas/<study>.csv, DIR/images/atlas
  std::string from_csv;     // redraw the charts and the page from a CSV instead of running
  bool coarse = false;      // joint reports: the tests' coarse meshes
};

// Exit codes as every command: unknown problem, family or option values -> InputError (1).
// `styk study run` prints the record's CSV row on stdout; a run that fails is a row with its
// failure (exit 0), so a series records it and goes on.
int study_command(const StudyArgs& args);

}  // namespace styk::cli
