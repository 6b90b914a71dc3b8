// The element registry of every Styk program and test: the built-in elements, then the plug-ins
// of a list of directories (docs/plugins.md, "Where the programs look").
//
//   PluginLibraries libraries;   // declare BEFORE the registry: destroyed after it
//   ElementRegistry registry;
//   for (const PluginDiagnostic& d :
//        setup_element_registry(registry, libraries, standard_plugin_directories()))
//     warn(d.message);
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_loader.hpp"

namespace styk {

// The directory the build tree writes its plug-ins to (<build>/plugins).
std::string build_plugin_directory();

// The plug-in directory of the installation the running program belongs to,
// <prefix>/lib/styk/plugins with <prefix> the parent of the executable's directory, if it
// exists; otherwise the build tree's. So an installed program loads the installed plug-ins and a
// program in the build tree the built ones, never both.
std::string default_plugin_directory();

// The programs' search path: the entries of STYK_PLUGIN_PATH, then default_plugin_directory().
std::vector<std::string> standard_plugin_directories();

// Registers the built-in elements, then loads the plug-ins of `plugin_directories` (earlier
// directories win a clash of type names). `libraries` receives the plug-in handles and must
// outlive `registry`. Returns the plug-in problems (non-fatal: the other plug-ins still load).
// Throws std::invalid_argument if `registry` already holds a built-in name.
std::vector<PluginDiagnostic> setup_element_registry(
    ElementRegistry& registry, PluginLibraries& libraries,
    const std::vector<std::string>& plugin_directories);

}  // namespace styk
