#include "registry_setup.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/core.h>

#include "styk/elements/builtin.hpp"

namespace styk::cli {

namespace {

// One default plug-in directory: <prefix>/lib/styk/plugins next to an installed executable if it
// exists, otherwise the build tree's (so a build tree and an installation never both load).
std::vector<std::string> default_plugin_directories() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed =
        exe.parent_path().parent_path() / STYK_PLUGIN_INSTALL_DIR;
    if (std::filesystem::is_directory(installed, error)) return {installed.string()};
  }
  return {STYK_PLUGIN_BUILD_DIR};
}

}  // namespace

ElementRegistry make_registry(PluginLibraries& libraries) {
  ElementRegistry registry;
  register_builtin_elements(registry);
  const std::vector<std::string> directories =
      plugin_directories(std::getenv("STYK_PLUGIN_PATH"), default_plugin_directories());
  for (const PluginDiagnostic& d : load_plugins(registry, libraries, directories))
    fmt::print(stderr, "styk: warning: {}\n", d.message);
  return registry;
}

}  // namespace styk::cli
