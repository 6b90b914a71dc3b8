// The element registry of the desktop program: the built-in elements and the plug-ins from
// STYK_PLUGIN_PATH and the build or install directory (like the `styk` program). Plug-in
// problems are returned as messages for the log; they never stop the program.
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_loader.hpp"

namespace styk::gui {

// `libraries` receives the plug-in handles and must outlive `registry`.
std::vector<std::string> load_elements(ElementRegistry& registry, PluginLibraries& libraries,
                                       const std::string& default_plugin_dir);

}  // namespace styk::gui
