#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include <fmt/core.h>

#include <algorithm>
#include <thread>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "json_progress.hpp"
#include "mpi_launcher.hpp"
#include "output_paths.hpp"
#include "registry_setup.hpp"
#include "stderr_progress.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/dat_writer.hpp"
#include "styk/io/frd_writer.hpp"
#include "styk/io/results_file.hpp"
#include "styk/solver/analysis.hpp"
#include "styk/solver/mpi_world.hpp"

namespace styk::cli {
namespace {

LinearSolverKind parse_solver(const std::string& name) {
  if (name == "auto") return LinearSolverKind::Automatic;
  if (name == "cholmod") return LinearSolverKind::Cholmod;
  if (name == "iterative") return LinearSolverKind::Iterative;
  throw InputError({}, "--solver must be auto, cholmod or iterative, not '" + name + "'");
}

ContactSolveKind parse_contact_solver(const std::string& name) {
  if (name == "auto") return ContactSolveKind::Automatic;
  if (name == "dense") return ContactSolveKind::Dense;
  if (name == "sparse") return ContactSolveKind::Sparse;
  throw InputError({}, "--contact-solver must be auto, dense or sparse, not '" + name + "'");
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Progress of the ranks other than 0: rank 0 speaks for the run.
class SilentProgress final : public ProgressSink {
 public:
  void begin(const std::string&) override {}
  void end(const std::string&, double) override {}
  void info(const std::string&) override {}
  void warning(const std::string&) override {}
};

// Threads per rank: the machine's cores shared by the ranks the runner placed on it.
int threads_per_rank(int requested) {
  if (requested > 0) return requested;
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return std::max(1, cores / mpi_ranks_on_this_machine());
}

int solve_here(const SolveArgs& args, const MpiWorld& world) {
  const bool json = args.progress == ProgressFormat::JsonLines;
  std::unique_ptr<ProgressSink> rank0_progress;
  if (json)
    rank0_progress = std::make_unique<JsonLinesProgress>();
  else
    rank0_progress = std::make_unique<StderrProgress>(args.quiet);
  SilentProgress silent;
  ProgressSink& progress = world.rank == 0 ? *rank0_progress : static_cast<ProgressSink&>(silent);
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);

  auto t0 = std::chrono::steady_clock::now();
  progress.begin("read");
  const Model model = read_inp(args.deck, registry);
  progress.end("read", seconds_since(t0));
  progress.info(fmt::format("{} nodes, {} elements, {} steps", model.node_count(),
                            model.element_count(), model.steps.size()));

  SolveOptions options;
  options.threads = world.size > 1 ? threads_per_rank(args.threads) : args.threads;
  options.distributed = world.size > 1;
  options.force = parse_solver(args.solver);
  options.memory_limit_gb = args.memory_limit_gb;
  options.contact_solve = parse_contact_solver(args.contact_solver);
  AnalysisReport report;
  const Results results = run_static_analysis(model, registry, options, &progress, &report);
  if (world.rank != 0) return kOk;  // every rank holds the results; rank 0 writes them

  std::error_code ec;
  std::filesystem::create_directories(args.output_dir, ec);
  if (ec)
    throw InputError({}, "cannot create output directory " + args.output_dir + ": " + ec.message());
  const std::string job = job_name(args.deck);
  const std::string h5_path = join_path(args.output_dir, job + ".styk.h5");
  const std::string dat_path = join_path(args.output_dir, job + ".dat");

  // *NODE FILE / *EL FILE ask for a .frd, as in CalculiX (docs/results.md, "The .frd file").
  const FrdPlan frd_plan = frd_plan_from_requests(model, results);
  const std::string frd_path =
      frd_plan.increments.empty() ? std::string() : join_path(args.output_dir, job + ".frd");
  for (const std::string& note : frd_plan.notes) progress.warning(note);

  t0 = std::chrono::steady_clock::now();
  progress.begin("write");
  {
    AtomicTextFile dat(dat_path);
    write_dat(dat.stream(), model, results);
    write_results_file(h5_path, model, results);
    if (!frd_path.empty()) write_frd(frd_path, model, registry, frd_plan, job);
    dat.commit();  // the .dat appears only once the results file is complete too
  }
  progress.end("write", seconds_since(t0));

  if (json)
    std::cerr << json_done_line(h5_path, dat_path, report.dofs, report.linear_solver,
                                static_cast<int>(model.steps.size()))
              << std::endl;
  std::cout << "results: " << h5_path << "\n"
            << "report:  " << dat_path << "\n";
  if (!frd_path.empty()) std::cout << "frd:     " << frd_path << "\n";
  std::cout << fmt::format("solved {} dofs with {} in {} step(s)\n", report.dofs,
                           report.linear_solver, model.steps.size());
  return kOk;
}

}  // namespace

int solve_command(const SolveArgs& args) {
  const bool under_runner = started_by_mpi_runner();
  if (args.ranks > 1 && !under_runner) return launch_ranks(args);
  const MpiWorld world = under_runner ? join_mpi_world() : MpiWorld{};
  if (args.ranks > 1 && args.ranks != world.size)
    throw InputError({}, "--ranks " + std::to_string(args.ranks) +
                             " under an MPI runner that "
                             "started " +
                             std::to_string(world.size) +
                             " ranks: the runner's -n decides (drop --ranks)");
  if (world.size == 1) return solve_here(args, world);
  // Errors every rank meets together (the same deck, collective solves) are reported once, by
  // rank 0; an error of one rank alone ends the whole run, so no rank waits for it forever.
  try {
    return solve_here(args, world);
  } catch (const InputError&) {
    if (world.rank == 0) throw;
    return kBadInput;
  } catch (const NotConvergedError&) {
    if (world.rank == 0) throw;
    return kNotConverged;
  } catch (const ResourceLimitError&) {
    if (world.rank == 0) throw;
    return kResourceLimit;
  } catch (const std::exception& e) {
    std::cerr << "rank " << world.rank << " of " << world.size << ": " << e.what()
              << " (ending the distributed run)\n";
    abort_mpi_world(kInternalError);
  }
}

}  // namespace styk::cli
