#include "session/element_setup.hpp"

#include <cstdlib>

#include "styk/elements/builtin.hpp"

namespace styk::gui {

std::vector<std::string> load_elements(ElementRegistry& registry, PluginLibraries& libraries,
                                       const std::string& default_plugin_dir) {
  register_builtin_elements(registry);
  std::vector<std::string> messages;
  for (const PluginDiagnostic& d :
       load_plugins(registry, libraries,
                    plugin_directories(std::getenv("STYK_PLUGIN_PATH"), {default_plugin_dir})))
    messages.push_back(d.message);
  return messages;
}

}  // namespace styk::gui
