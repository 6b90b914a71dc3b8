// The element registry a command works with: the built-in elements, then the plug-ins found on
// STYK_PLUGIN_PATH and in the default plug-in directory (styk_element_setup).
#pragma once

#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_loader.hpp"

namespace styk::cli {

// `libraries` receives the plug-in handles and must outlive the returned registry: declare it
// first. Plug-in problems are printed to stderr as warnings; they never stop the command.
ElementRegistry make_registry(PluginLibraries& libraries);

}  // namespace styk::cli
