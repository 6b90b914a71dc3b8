#include "cli_runner.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

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
  const std::filesystem::path dir = std::filesystem::path(STYK_BINARY_DIR) / "test-scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace styk::testing
