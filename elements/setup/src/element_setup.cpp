#include "styk/elements/element_setup.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "styk/elements/builtin.hpp"

namespace styk {

std::string build_plugin_directory() { return STYK_PLUGIN_BUILD_DIR; }

std::string default_plugin_directory() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed =
        exe.parent_path().parent_path() / STYK_PLUGIN_INSTALL_DIR;
    if (std::filesystem::is_directory(installed, error)) return installed.string();
  }
  return build_plugin_directory();
}

std::vector<std::string> standard_plugin_directories() {
  return plugin_directories(std::getenv("STYK_PLUGIN_PATH"), {default_plugin_directory()});
}

std::vector<PluginDiagnostic> setup_element_registry(
    ElementRegistry& registry, PluginLibraries& libraries,
    const std::vector<std::string>& plugin_directories) {
  register_builtin_elements(registry);
  return load_plugins(registry, libraries, plugin_directories);
}

}  // namespace styk
