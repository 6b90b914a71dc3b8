#include "registry_setup.hpp"

#include <cstdio>

#include <fmt/core.h>

#include "styk/elements/element_setup.hpp"

namespace styk::cli {

ElementRegistry make_registry(PluginLibraries& libraries) {
  ElementRegistry registry;
  for (const PluginDiagnostic& d :
       setup_element_registry(registry, libraries, standard_plugin_directories()))
    fmt::print(stderr, "styk: warning: {}\n", d.message);
  return registry;
}

}  // namespace styk::cli
