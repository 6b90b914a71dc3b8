// The element registries the test suites build, as the programs build theirs
// (styk/elements/element_setup.hpp): the built-in elements alone, or with the build tree's
// plug-ins (C3D14, C3D21, C3D28 and the template plug-in of docs/plugins.md).
#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_loader.hpp"

namespace styk::test {

// A fresh registry of the built-in elements.
ElementRegistry builtin_registry();

// One registry of the built-in elements for the whole test program (built on first use).
const ElementRegistry& shared_builtin_registry();

// The build tree's plug-in directory and the template plug-in of docs/plugins.md (built into its
// examples/ directory).
std::vector<std::string> build_plugin_directories();

// Built-in elements and the plug-ins of `plugin_directories`; the libraries outlive the registry
// (declared first, destroyed last).
struct FullRegistry {
  explicit FullRegistry(
      const std::vector<std::string>& plugin_directories = build_plugin_directories());
  // Throws std::runtime_error naming the first of `types` the registry lacks (with the first
  // plug-in problem), so a suite whose plug-ins did not build fails at once and says why.
  void require(std::initializer_list<const char*> types) const;

  PluginLibraries libraries;
  ElementRegistry registry;
  std::vector<PluginDiagnostic> diagnostics;  // empty when every plug-in loaded
};

// A fresh registry with build_plugin_directories().
std::unique_ptr<FullRegistry> registry_with_plugins();

// One registry with the plug-ins for the whole test program, for the model builders that
// convert meshes (mesher::convert_elements reads the target types' descriptions from it).
const ElementRegistry& shared_registry();

}  // namespace styk::test
