#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "registry_setup.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/studies/verify/report.hpp"
#include "verify_args.hpp"

namespace styk::cli {
namespace {

const SourceLoc kHere{"styk verify", 0};

void print_cases(const std::vector<verify::BenchmarkCase>& cases) {
  for (const verify::BenchmarkCase& c : cases) {
    std::string params;
    for (const auto& [name, value] : c.params) params += " --" + name + " " + value;
    fmt::print("{:<18} {:<7} {:<10} {}\n", c.name, c.section,
               c.grade_row.empty() ? "" : c.grade_row, c.title);
    fmt::print("    styk mesh {}{} --element FAMILY; {}; theory {:.5g}{}\n", c.builder, params,
               c.measure.label, c.theory,
               c.support == verify::Support::PlateSimplySupported
                   ? "; supports replaced: w = 0 on the bottom edges"
                   : "");
  }
}

// Prints every cell that could not be computed; returns how many.
int report_failures(const std::vector<verify::CaseOutcome>& outcomes) {
  int failures = 0;
  for (const verify::CaseOutcome& o : outcomes)
    for (int f = 0; f < verify::kFamilyCount; ++f)
      if (!o.ours[f].value) {
        fmt::print(stderr, "styk verify: {} {}: {}\n", o.bench.name, verify::kElementFamilies[f],
                   o.ours[f].failure);
        ++failures;
      }
  return failures;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(kHere, "cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_section(const std::string& path, const std::string& body) {
  const std::string text = read_file(path);
  std::string updated;
  try {
    updated =
        verify::replace_marked_section(text, verify::kTable313Begin, verify::kTable313End, body);
  } catch (const std::runtime_error& e) {
    throw InputError({path, 0}, e.what());
  }
  AtomicTextFile file(path);
  file.stream() << updated;
  file.commit();
}

}  // namespace

int verify_command(const VerifyArgs& args) {
  const std::vector<verify::BenchmarkCase> all = verify::benchmark_cases();
  if (args.list) {
    print_cases(all);
    return kOk;
  }
  if (!args.write_path.empty() && args.table.empty())
    throw InputError(kHere, "--write needs --table 3.13");
  if (args.case_name.empty() && args.table.empty())
    throw InputError(kHere, "give --list, --case NAME or --table 3.13");
  if (!args.table.empty() && args.table != "3.13")
    throw InputError(kHere, "--table: only 3.13 (SPEC §3.1.9) exists, not '" + args.table + "'");

  std::vector<verify::BenchmarkCase> selected = all;
  if (!args.case_name.empty()) {
    const verify::BenchmarkCase* c = verify::find_case(all, args.case_name);
    if (!c) throw InputError(kHere, "unknown case '" + args.case_name + "' (styk verify --list)");
    selected = {*c};
  }

  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  const std::vector<verify::CaseOutcome> outcomes = verify::run_cases(selected, registry);

  if (!args.table.empty()) {
    fmt::print("{}", verify::table_313_section(outcomes));
  } else {
    fmt::print("{}", verify::value_tables_markdown(outcomes));
  }
  const int failures = report_failures(outcomes);
  if (!args.write_path.empty()) {
    if (failures > 0)
      throw InputError(kHere, std::to_string(failures) +
                                  " cells could not be computed (see above); " + args.write_path +
                                  " left unchanged");
    write_section(args.write_path, verify::table_313_section(outcomes));
    fmt::print("updated {}\n", args.write_path);
  }
  return kOk;
}

}  // namespace styk::cli
