#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "json_progress.hpp"
#include "output_paths.hpp"
#include "registry_setup.hpp"
#include "stderr_progress.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/dat_writer.hpp"
#include "styk/io/results_file.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::cli {
namespace {

LinearSolverKind parse_solver(const std::string& name) {
  if (name == "auto") return LinearSolverKind::Automatic;
  if (name == "cholmod") return LinearSolverKind::Cholmod;
  if (name == "iterative") return LinearSolverKind::Iterative;
  throw InputError({}, "--solver must be auto, cholmod or iterative, not '" + name + "'");
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int solve_command(const SolveArgs& args) {
  const bool json = args.progress == ProgressFormat::JsonLines;
  std::unique_ptr<ProgressSink> sink;
  if (json)
    sink = std::make_unique<JsonLinesProgress>();
  else
    sink = std::make_unique<StderrProgress>(args.quiet);
  ProgressSink& progress = *sink;
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);

  auto t0 = std::chrono::steady_clock::now();
  progress.begin("read");
  const Model model = read_inp(args.deck, registry);
  progress.end("read", seconds_since(t0));
  progress.info(fmt::format("{} nodes, {} elements, {} steps", model.node_count(),
                            model.element_count(), model.steps.size()));

  SolveOptions options;
  options.threads = args.threads;
  options.force = parse_solver(args.solver);
  options.memory_limit_gb = args.memory_limit_gb;
  AnalysisReport report;
  const Results results = run_static_analysis(model, registry, options, &progress, &report);

  std::error_code ec;
  std::filesystem::create_directories(args.output_dir, ec);
  if (ec) throw InputError({}, "cannot create output directory " + args.output_dir + ": " +
                                   ec.message());
  const std::string job = job_name(args.deck);
  const std::string h5_path = join_path(args.output_dir, job + ".styk.h5");
  const std::string dat_path = join_path(args.output_dir, job + ".dat");

  t0 = std::chrono::steady_clock::now();
  progress.begin("write");
  {
    AtomicTextFile dat(dat_path);
    write_dat(dat.stream(), model, results);
    write_results_file(h5_path, model, results);
    dat.commit();  // the .dat appears only once the results file is complete too
  }
  progress.end("write", seconds_since(t0));

  if (json)
    std::cerr << json_done_line(h5_path, dat_path, report.dofs, report.linear_solver,
                                static_cast<int>(model.steps.size()))
              << std::endl;
  std::cout << "results: " << h5_path << "\n" << "report:  " << dat_path << "\n";
  std::cout << fmt::format("solved {} dofs with {} in {} step(s)\n", report.dofs,
                           report.linear_solver, model.steps.size());
  return kOk;
}

}  // namespace styk::cli
