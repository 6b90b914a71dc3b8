#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/core.h>

#include "exit_codes.hpp"
#include "registry_setup.hpp"
#include "study_args.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/studies/joints/joint_report.hpp"
#include "styk/studies/results/run_record.hpp"
#include "styk/studies/study/families.hpp"
#include "styk/studies/study/problems.hpp"
#include "styk/studies/study/report.hpp"
#include "styk/studies/study/run.hpp"

namespace styk::cli {
namespace {

SourceLoc here(const StudyArgs& args) { return {"styk study " + args.kind, 0}; }

std::string this_program() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string() : exe.string();
}

const std::vector<studies::ReferenceProblem>& problems_of(const std::string& kind) {
  if (kind == "stability") return studies::stability_sweeps();
  if (kind == "model-size") return studies::model_size_problems();
  return studies::accuracy_problems();
}

void print_list(const StudyArgs& args, const ElementRegistry& registry) {
  for (const studies::ReferenceProblem& p : problems_of(args.kind)) {
    fmt::print("{:<26} {}\n    {}\n", p.name, p.title, p.source);
    if (!p.parameter.empty()) {
      std::string values;
      for (double v : p.values) values += (values.empty() ? "" : ", ") + fmt::format("{:g}", v);
      fmt::print("    {}: {}\n", p.parameter, values);
    }
  }
  std::vector<std::string> unavailable;
  fmt::print("families:");
  for (const studies::ElementFamily& f : studies::available_families(registry, &unavailable))
    fmt::print(" {}", f.name);
  fmt::print("\n");
  for (const std::string& u : unavailable) fmt::print("  not run: {}\n", u);
}

std::vector<const studies::ReferenceProblem*> selected_problems(const StudyArgs& args) {
  std::vector<const studies::ReferenceProblem*> out;
  const auto& all = problems_of(args.kind);
  if (args.problems.empty()) {
    for (const studies::ReferenceProblem& p : all) out.push_back(&p);
    return out;
  }
  for (const std::string& name : args.problems) {
    const studies::ReferenceProblem* found = nullptr;
    for (const studies::ReferenceProblem& p : all)
      if (p.name == name) found = &p;
    if (!found) {
      std::string list;
      for (const studies::ReferenceProblem& p : all) list += (list.empty() ? "" : ", ") + p.name;
      throw InputError(here(args), "unknown problem '" + name + "'; " + args.kind + " has " + list);
    }
    out.push_back(found);
  }
  return out;
}

void check_families(const StudyArgs& args, const std::vector<std::string>& families,
                    const ElementRegistry& registry) {
  for (const std::string& f : families) {
    const studies::ElementFamily* family = studies::find_family(f);
    if (!family)
      throw InputError(here(args), "unknown element family '" + f + "' (styk study " + args.kind +
                                       " --list shows them)");
    if (!registry.find(family->type()))
      throw InputError(here(args), "element family " + f + ": type " + family->type() +
                                       " is not registered (element plug-ins not loaded?)");
  }
}

std::vector<studies::RunRecord> read_records(const StudyArgs& args) {
  std::ifstream in(args.from_csv);
  if (!in) throw InputError({args.from_csv, 0}, "cannot read the study CSV");
  try {
    return studies::read_csv(in, args.from_csv);
  } catch (const studies::StudyCsvError& e) {
    throw InputError({e.file(), e.line()}, e.message());
  }
}

std::string command_line(const StudyArgs& args) {
  std::string c = "styk study " + args.kind;
  auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ",") + x;
    return s;
  };
  if (!args.problems.empty()) c += " --problems " + list(args.problems);
  if (!args.families.empty()) c += " --families " + list(args.families);
  c += fmt::format(" --max-dof {} --max-seconds {:g} --repeats {}", args.max_dof, args.max_seconds,
                   args.repeats);
  if (args.max_levels > 0) c += fmt::format(" --max-levels {}", args.max_levels);
  if (args.in_process) c += " --in-process";
  if (!args.docs_dir.empty()) c += " --docs " + args.docs_dir;
  return c;
}

int run_one(const StudyArgs& args, const ElementRegistry& registry) {
  if (!studies::find_problem(args.problem))
    throw InputError(here(args), "unknown problem '" + args.problem +
                                     "' (styk study accuracy --list, styk study stability --list)");
  check_families(args, {args.family}, registry);
  const studies::RunRecord r = studies::run_in_process(
      {args.study, args.problem, args.family, args.level, args.repeats}, registry);
  fmt::print("{}\n", studies::csv_row(r));
  return kOk;
}

int run_study(const StudyArgs& args, const ElementRegistry& registry) {
  if (!args.docs_dir.empty() && !args.output_dir.empty())
    throw InputError(here(args), "give either -o DIR or --docs DIR, not both");
  const studies::ReportLayout layout =
      !args.docs_dir.empty()
          ? studies::docs_layout(args.docs_dir, args.kind)
          : studies::output_layout(args.output_dir.empty() ? "study-" + args.kind : args.output_dir,
                                   args.kind);
  studies::ReportContext context;
  context.machine = studies::machine_description();
  context.max_dof = args.max_dof;
  context.max_seconds = args.max_seconds;
  context.repeats = args.repeats;
  context.isolated = !args.in_process;
  context.command = command_line(args);
  std::vector<std::string> unavailable;
  studies::available_families(registry, &unavailable);
  context.notes = unavailable;

  std::vector<studies::RunRecord> records;
  if (!args.from_csv.empty()) {
    records = read_records(args);
  } else {
    check_families(args, args.families, registry);
    studies::SeriesOptions options;
    options.families = args.families;
    if (args.kind == "model-size" && options.families.empty())
      options.families = studies::model_size_families();
    options.max_dof = args.max_dof;
    options.max_seconds = args.max_seconds;
    options.repeats = args.repeats;
    options.max_levels = args.max_levels;
    if (!args.in_process) options.program = this_program();
    options.progress = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
    for (const studies::ReferenceProblem* p : selected_problems(args)) {
      const std::vector<studies::RunRecord> some =
          studies::run_problem(*p, args.kind, registry, options);
      records.insert(records.end(), some.begin(), some.end());
    }
  }
  std::filesystem::create_directories(std::filesystem::path(layout.markdown).parent_path());
  std::filesystem::create_directories(std::filesystem::path(layout.csv).parent_path());
  std::filesystem::create_directories(layout.image_dir);
  if (args.kind == "stability")
    studies::write_stability_report(records, context, layout);
  else if (args.kind == "model-size")
    studies::write_model_size_report(records, context, layout);
  else
    studies::write_accuracy_report(records, context, layout);
  int failed = 0;
  for (const studies::RunRecord& r : records) failed += !r.ok();
  fmt::print("{} runs ({} without a result): {}, {}, charts in {}\n", records.size(), failed,
             layout.csv, layout.markdown, layout.image_dir);
  return kOk;
}

// A SPEC §4 joint report: build, solve, write the page, its CSV files and charts.
int run_joint(const StudyArgs& args, const ElementRegistry& registry) {
  if (!args.docs_dir.empty() && !args.output_dir.empty())
    throw InputError(here(args), "give either -o DIR or --docs DIR, not both");
  const studies::JointLayout layout =
      !args.docs_dir.empty()
          ? studies::joint_docs_layout(args.docs_dir, args.kind)
          : studies::joint_output_layout(
                args.output_dir.empty() ? "study-" + args.kind : args.output_dir, args.kind);
  std::string command = "styk study " + args.kind;
  if (args.coarse) command += " --coarse";
  if (!args.docs_dir.empty()) command += " --docs " + args.docs_dir;
  studies::JointOptions options;
  options.coarse = args.coarse;
  options.progress = [](const std::string& line) { fmt::print(stderr, "{}\n", line); };
  const studies::JointReport report = studies::run_joint_study(args.kind, registry, options);
  studies::write_joint_report(report, command, studies::machine_description(), layout);
  fmt::print("{}: {} figures, {} charts, {} tables, {:.1f} s\n", layout.markdown,
             report.headlines.size(), report.charts.size(), report.tables.size(), report.seconds);
  return kOk;
}

}  // namespace

int study_command(const StudyArgs& args) {
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  if (args.kind == "run") return run_one(args, registry);
  if (studies::is_joint_study(args.kind)) return run_joint(args, registry);
  if (args.list) {
    print_list(args, registry);
    return kOk;
  }
  return run_study(args, registry);
}

}  // namespace styk::cli
