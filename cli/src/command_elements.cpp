#include <fmt/core.h>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "registry_setup.hpp"

namespace styk::cli {

int elements_command() {
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  fmt::print("{:<8} {:>5}  {:<13} {:<14} {:<14} {:<10} {}\n", "type", "nodes", "form", "full rule",
             "reduced rule", "source", "description");
  for (const std::string& name : registry.names()) {
    const ElementRegistry::Entry* entry = registry.entry(name);
    const TElement& e = *entry->element;
    fmt::print("{:<8} {:>5}  {:<13} {:<14} {:<14} {:<10} {}\n", name, e.node_count(),
               form_name(e.form()), e.rule(RuleKind::Full).label, e.rule(RuleKind::Reduced).label,
               entry->source, e.description());
  }
  return kOk;
}

}  // namespace styk::cli
