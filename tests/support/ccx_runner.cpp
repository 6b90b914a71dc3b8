#include "ccx_runner.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace styk::test {

namespace {

// The shell's exit status of std::system's result.
int shell_status(int raw) { return raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1; }

// Single quotes for the shell (job names and directories are test-chosen, never user input).
std::string quoted(const std::string& text) { return "'" + text + "'"; }

}  // namespace

bool ccx_on_path() { return shell_status(std::system("command -v ccx > /dev/null 2>&1")) == 0; }

CcxRun run_ccx(const std::filesystem::path& dir, const std::string& job, int timeout_seconds) {
  const std::string log = job + ".log";
  std::string command =
      "cd " + quoted(dir.string()) + " && rm -f " + quoted(job + ".dat") + " && OMP_NUM_THREADS=1 ";
  if (timeout_seconds > 0) command += "timeout " + std::to_string(timeout_seconds) + " ";
  command += "ccx -i " + quoted(job) + " > " + quoted(log) + " 2>&1";
  CcxRun run;
  run.exit_code = shell_status(std::system(command.c_str()));
  std::ifstream in(dir / log);
  std::ostringstream text;
  text << in.rdbuf();
  run.log = text.str();
  return run;
}

}  // namespace styk::test
