#include "cli_runner.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "support/test_scratch.hpp"

namespace styk::testing {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

CommandResult run_command(const std::string& command, const std::string& workdir) {
  const std::string out_path = workdir + "/.stdout";
  const std::string err_path = workdir + "/.stderr";
  const std::string full =
      "cd '" + workdir + "' && " + command + " >'" + out_path + "' 2>'" + err_path + "' </dev/null";
  const int status = std::system(full.c_str());
  CommandResult r;
  r.exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  r.out = read_file(out_path);
  r.err = read_file(err_path);
  std::filesystem::remove(out_path);
  std::filesystem::remove(err_path);
  return r;
}

std::string styk_executable() { return std::string(STYK_BINARY_DIR) + "/cli/styk"; }

std::string scratch_dir(const std::string& name) {
  return test::fresh_scratch_dir(std::filesystem::path("test-scratch") / name).string();
}

}  // namespace styk::testing
