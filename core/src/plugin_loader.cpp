// The plug-in loader: dlopen, entry lookup, ABI handshake, registration, and a named non-fatal
// diagnostic for each way this can fail.
#include "styk/core/plugin_loader.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>

#include "styk/core/plugin_api.h"

namespace styk {

namespace fs = std::filesystem;

namespace {

struct DlCloser {
  void operator()(void* handle) const {
    if (handle) dlclose(handle);
  }
};
using LibraryHandle = std::unique_ptr<void, DlCloser>;

std::string last_dl_error() {
  const char* text = dlerror();
  return text ? text : "unknown dynamic-loader error";
}

// The canonical form of an existing path (symlinks resolved), or the path as given.
std::string canonical_or_same(const std::string& path) {
  std::error_code error;
  const fs::path canonical = fs::canonical(path, error);
  return error ? path : canonical.string();
}

PluginDiagnostic diagnostic(PluginDiagnostic::Kind kind, const std::string& path,
                            const std::string& what) {
  return PluginDiagnostic{kind, path, "plug-in " + path + ": " + what};
}

}  // namespace

struct PluginLibraries::Impl {
  struct Library {
    std::string path;
    LibraryHandle handle;
  };
  std::vector<Library> libraries;
};

PluginLibraries::PluginLibraries() : impl_(std::make_unique<Impl>()) {}
PluginLibraries::PluginLibraries(PluginLibraries&&) noexcept = default;
PluginLibraries& PluginLibraries::operator=(PluginLibraries&&) noexcept = default;

PluginLibraries::~PluginLibraries() {
  if (!impl_) return;  // moved from
  // Close in reverse load order, as a library loaded later may depend on an earlier one.
  while (!impl_->libraries.empty()) impl_->libraries.pop_back();
}

std::vector<std::string> PluginLibraries::paths() const {
  std::vector<std::string> out;
  if (impl_)
    for (const auto& library : impl_->libraries) out.push_back(library.path);
  return out;
}

std::size_t PluginLibraries::size() const { return impl_ ? impl_->libraries.size() : 0; }

bool PluginLibraries::contains(const std::string& canonical_path) const {
  if (!impl_) return false;
  return std::any_of(impl_->libraries.begin(), impl_->libraries.end(),
                     [&](const Impl::Library& l) { return l.path == canonical_path; });
}

std::vector<PluginDiagnostic> load_plugin(ElementRegistry& registry, PluginLibraries& libraries,
                                          const std::string& given_path) {
  using Kind = PluginDiagnostic::Kind;
  if (!libraries.impl_) libraries.impl_ = std::make_unique<PluginLibraries::Impl>();
  const std::string path = canonical_or_same(given_path);
  if (libraries.contains(path)) return {};

  // RTLD_LOCAL: a plug-in's symbols never serve another plug-in. RTLD_NODELETE: see
  // PluginLibraries. RTLD_NOW: a missing symbol is reported here, not as a crash mid-analysis.
  dlerror();
  LibraryHandle handle(dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE));
  if (!handle) return {diagnostic(Kind::OpenFailed, path, "cannot be loaded: " + last_dl_error())};

  dlerror();
  void* symbol = dlsym(handle.get(), STYK_PLUGIN_ENTRY_NAME);
  if (!symbol)
    return {diagnostic(Kind::NoEntry, path,
                       "is not a Styk plug-in: it does not export " STYK_PLUGIN_ENTRY_NAME " (" +
                           last_dl_error() + ")")};
  StykPluginRegisterFn entry = nullptr;
  static_assert(sizeof entry == sizeof symbol, "function and data pointers differ in size");
  std::memcpy(&entry, &symbol, sizeof entry);  // POSIX: dlsym results may be function pointers

  StykPluginHost host{};
  host.abi_version = STYK_PLUGIN_ABI_VERSION;
  host.plugin_path = path.c_str();
  host.registry = &registry;
  StykPluginReply reply{};
  const std::size_t types_before = registry.names().size();

  std::vector<PluginDiagnostic> out;
  int result = STYK_PLUGIN_FAILED;
  try {
    // The SDK entry never throws, but a hand-written one might (C++ exceptions do propagate
    // through an extern "C" function compiled as C++).
    result = entry(&host, &reply);
  } catch (const std::exception& error) {
    std::snprintf(reply.message, sizeof reply.message, "%s", error.what());
  } catch (...) {
    std::snprintf(reply.message, sizeof reply.message, "%s", "an unknown exception");
  }
  reply.message[sizeof reply.message - 1] = '\0';

  switch (result) {
    case STYK_PLUGIN_OK:
      break;
    case STYK_PLUGIN_ABI_MISMATCH:
      out.push_back(diagnostic(
          Kind::AbiMismatch, path,
          "plug-in ABI version mismatch: this Styk expects version " +
              std::to_string(STYK_PLUGIN_ABI_VERSION) + ", the plug-in was built for version " +
              std::to_string(reply.plugin_abi_version) + "; rebuild it against this Styk"));
      break;
    case STYK_PLUGIN_FAILED:
      out.push_back(diagnostic(Kind::RegistrationFailed, path,
                               std::string("registration failed: ") +
                                   (reply.message[0] ? reply.message : "no reason given")));
      break;
    default:
      out.push_back(diagnostic(Kind::RegistrationFailed, path,
                               "registration returned the unknown code " + std::to_string(result)));
  }
  // Keep the library whenever it put something into the registry (even after a partial
  // failure of a hand-written entry): the registry now holds its code.
  if (result == STYK_PLUGIN_OK || registry.names().size() != types_before)
    libraries.impl_->libraries.push_back(PluginLibraries::Impl::Library{path, std::move(handle)});
  return out;
}

std::vector<PluginDiagnostic> load_plugins(ElementRegistry& registry, PluginLibraries& libraries,
                                           const std::vector<std::string>& directories) {
  std::vector<PluginDiagnostic> out;
  std::string searched;
  for (const std::string& directory : directories) {
    searched += (searched.empty() ? "" : ":") + directory;
    std::error_code error;
    if (!fs::is_directory(directory, error)) {
      out.push_back(PluginDiagnostic{
          PluginDiagnostic::Kind::DirectoryMissing, directory,
          "plug-in directory " + directory + " does not exist or is not a directory"});
      continue;
    }
    std::vector<std::string> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
      std::error_code status_error;
      if (entry.path().extension() == ".so" && entry.is_regular_file(status_error))
        files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    for (const std::string& file : files) {
      std::vector<PluginDiagnostic> found = load_plugin(registry, libraries, file);
      out.insert(out.end(), found.begin(), found.end());
    }
  }
  registry.searched_paths = searched;
  return out;
}

std::vector<std::string> plugin_directories(const char* path_list,
                                            const std::vector<std::string>& defaults) {
  std::vector<std::string> out;
  std::vector<std::string> seen;  // canonical forms: a directory listed twice is searched once
  auto add = [&](const std::string& directory) {
    const std::string canonical = canonical_or_same(directory);
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) return;
    seen.push_back(canonical);
    out.push_back(directory);
  };
  if (path_list) {
    const std::string list = path_list;
    std::size_t start = 0;
    while (start <= list.size()) {
      const std::size_t end = std::min(list.find(':', start), list.size());
      if (end > start) add(list.substr(start, end - start));
      start = end + 1;
    }
  }
  for (const std::string& directory : defaults) {
    std::error_code error;
    if (!directory.empty() && fs::is_directory(directory, error)) add(directory);
  }
  return out;
}

}  // namespace styk
