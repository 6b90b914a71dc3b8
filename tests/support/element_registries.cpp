#include "element_registries.hpp"

#include <stdexcept>

#include "styk/elements/builtin.hpp"
#include "styk/elements/element_setup.hpp"

namespace styk::test {

ElementRegistry builtin_registry() {
  ElementRegistry registry;
  register_builtin_elements(registry);
  return registry;
}

const ElementRegistry& shared_builtin_registry() {
  static const ElementRegistry registry = builtin_registry();
  return registry;
}

std::vector<std::string> build_plugin_directories() {
  return {build_plugin_directory(), build_plugin_directory() + "/examples"};
}

FullRegistry::FullRegistry(const std::vector<std::string>& plugin_directories)
    : diagnostics(setup_element_registry(registry, libraries, plugin_directories)) {}

void FullRegistry::require(std::initializer_list<const char*> types) const {
  for (const char* type : types)
    if (!registry.find(type))
      throw std::runtime_error(std::string("plug-in element ") + type + " not found in " +
                               build_plugin_directory() +
                               (diagnostics.empty() ? "" : ": " + diagnostics.front().message));
}

std::unique_ptr<FullRegistry> registry_with_plugins() { return std::make_unique<FullRegistry>(); }

const ElementRegistry& shared_registry() {
  static const std::unique_ptr<FullRegistry> full = registry_with_plugins();
  return full->registry;
}

}  // namespace styk::test
