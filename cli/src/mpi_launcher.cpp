#include "mpi_launcher.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "json_progress.hpp"
#include "output_paths.hpp"

namespace styk::cli {
namespace {

// The runner as given (a path, or a name looked up on PATH); empty when not found.
std::string find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? name : "";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

std::string this_program() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find this program's path (/proc/self/exe)");
  return self.string();
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::vector<std::string> runner_command(const SolveArgs& args, const std::string& runner) {
  std::vector<std::string> command{runner};
  // Open MPI refuses to start as root without this (containers, CI machines).
  if (geteuid() == 0) command.push_back("--allow-run-as-root");
  command.insert(command.end(), {"-n", std::to_string(args.ranks), this_program(), "solve",
                                 args.deck, "-o", args.output_dir, "--solver", args.solver,
                                 "--threads", std::to_string(args.threads)});
  if (args.memory_limit_gb > 0.0)
    command.insert(command.end(), {"--memory-limit", format_number(args.memory_limit_gb)});
  if (args.quiet) command.push_back("-q");
  if (args.progress == ProgressFormat::JsonLines)
    command.insert(command.end(), {"--progress", "json"});
  return command;
}

// The runner's exit status: the code it returned, or 128 + the signal that ended it (the shell's
// convention, which Open MPI's runner also follows for a rank a signal killed).
int run_and_wait(const std::vector<std::string>& command) {
  std::vector<char*> argv;
  for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = fork();
  if (child < 0)
    throw std::runtime_error(std::string("cannot start the MPI runner: ") + std::strerror(errno));
  if (child == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("lost the MPI runner's process");
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// A failure of the launch itself, as the run's last line: prose for people, or with `--progress
// json` the protocol's error event (kind "run_environment"), so a driving program sees why the run
// ended instead of an unparsed line.
int report_launch_failure(const SolveArgs& args, const std::string& message) {
  if (args.progress == ProgressFormat::JsonLines)
    std::cerr << json_error_line(kRunEnvironment, "run_environment", "", 0, message) << "\n";
  else
    std::cerr << "styk: " << message << "\n";
  return kRunEnvironment;
}

void remove_partial_results(const SolveArgs& args) {
  const std::string job = job_name(args.deck);
  for (const std::string& name : {job + ".styk.h5.tmp", job + ".dat.tmp"})
    std::remove(join_path(args.output_dir, name).c_str());
}

}  // namespace

int launch_ranks(const SolveArgs& args) {
  const char* configured = std::getenv("STYK_MPIRUN");
  const std::string name = configured != nullptr && *configured != '\0' ? configured : "mpirun";
  const std::string runner = find_program(name);
  if (runner.empty())
    return report_launch_failure(
        args, "--ranks " + std::to_string(args.ranks) + " needs an MPI runner, and '" + name +
                  "' was not found" + (name.find('/') == std::string::npos ? " on PATH" : "") +
                  " (Debian: the openmpi-bin package, which scripts/install-deps.sh installs; "
                  "STYK_MPIRUN names another runner); nothing was solved");
  const int status = run_and_wait(runner_command(args, runner));
  // Rank 0 has already reported these in the usual way.
  if (status == kOk || status == kBadInput || status == kNotConverged || status == kResourceLimit)
    return status;
  remove_partial_results(args);
  // Open MPI's runner passes on 128 + the signal that killed a rank as its own exit status.
  return report_launch_failure(
      args, "the distributed run failed: " + runner + " ended with status " +
                std::to_string(status) +
                (status > 128 ? " (signal " + std::to_string(status - 128) + ")" : "") +
                " (a rank died, or MPI could not start its " + std::to_string(args.ranks) +
                " ranks); no results were written");
}

}  // namespace styk::cli
