// Loading element plug-ins (DESIGN "The element interface"; ABI in plugin_api.h).
//
//   PluginLibraries libraries;   // declare BEFORE the registry: destroyed after it
//   ElementRegistry registry;
//   register_builtin_elements(registry);
//   for (const PluginDiagnostic& d :
//        load_plugins(registry, libraries,
//                     plugin_directories(std::getenv("STYK_PLUGIN_PATH"), {default_dir})))
//     warn(d.message);
//
// Every failure is a non-fatal PluginDiagnostic naming the file: the other plug-ins still load.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"

namespace styk {

class PluginLibraries;

struct PluginDiagnostic {
  enum class Kind {
    DirectoryMissing,    // a search directory does not exist or is not a directory
    OpenFailed,          // dlopen failed (not a shared library, missing dependency, ...)
    NoEntry,             // the library does not export styk_plugin_register
    AbiMismatch,         // built for another STYK_PLUGIN_ABI_VERSION
    RegistrationFailed,  // the entry reported a failure or threw (e.g. a duplicate type name)
  };
  Kind kind;
  std::string path;     // the directory or library concerned
  std::string message;  // a full sentence for the user, starting with the path
};

// Owns the handles of the loaded plug-in libraries (move-only RAII). The registry entries the
// plug-ins created contain code and vtables of these libraries, so this object must outlive the
// registry. As a safety belt the libraries are also opened with RTLD_NODELETE: closing a handle
// never unmaps code, so a wrong destruction order cannot leave dangling vtables.
class PluginLibraries {
 public:
  PluginLibraries();
  ~PluginLibraries();
  PluginLibraries(PluginLibraries&&) noexcept;
  PluginLibraries& operator=(PluginLibraries&&) noexcept;
  PluginLibraries(const PluginLibraries&) = delete;
  PluginLibraries& operator=(const PluginLibraries&) = delete;

  // Canonical paths of the libraries loaded so far, in load order.
  std::vector<std::string> paths() const;
  std::size_t size() const;
  bool contains(const std::string& canonical_path) const;

 private:
  friend std::vector<PluginDiagnostic> load_plugin(ElementRegistry& registry,
                                                   PluginLibraries& libraries,
                                                   const std::string& path);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Loads one plug-in library: dlopen, look up the entry, ABI handshake, registration. Returns the
// diagnostic of a failure (none on success). A library already held by `libraries` (same
// canonical path) is skipped silently.
std::vector<PluginDiagnostic> load_plugin(ElementRegistry& registry, PluginLibraries& libraries,
                                          const std::string& path);

// Loads every `*.so` file of every directory (non-recursive; files in name order, directories in
// the given order, so earlier directories win a clash of type names), and sets
// registry.searched_paths to the directories joined with ':'.
std::vector<PluginDiagnostic> load_plugins(ElementRegistry& registry, PluginLibraries& libraries,
                                           const std::vector<std::string>& directories);

// The search path: the entries of a colon-separated list (the value of STYK_PLUGIN_PATH; may be
// null; empty entries ignored), then those of `defaults` that exist (the build-tree or install
// plug-in directory: a default that is absent is not worth a warning, a user's entry is).
std::vector<std::string> plugin_directories(const char* path_list,
                                            const std::vector<std::string>& defaults);

}  // namespace styk
