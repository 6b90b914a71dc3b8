// styk::load_plugins / load_plugin / plugin_directories: the good plug-ins load from the build
// directory, and every failure mode is a named, non-fatal PluginDiagnostic (DESIGN "The element
// interface"; brief: missing directory, not a library, no entry, wrong ABI version, duplicate
// type name, throwing registration).
#include <dlfcn.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plugin_fixtures.hpp"
#include "styk/core/plugin_api.h"
#include "styk/elements/builtin.hpp"

namespace styk {
namespace {

namespace fs = std::filesystem;
using Kind = PluginDiagnostic::Kind;

std::string bad_plugin_dir(const std::string& name) {
  return std::string(STYK_BAD_PLUGIN_DIR) + "/" + name;
}

std::string canonical(const std::string& path) { return fs::canonical(path).string(); }

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A fresh empty directory under the test binary dir, removed at the end of the test.
class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& name)
      : path_(fs::path(STYK_BINARY_DIR) / "plugin_test_scratch" / name) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

TEST(PluginLoader, LoadsTheThreeContactHexahedraFromTheBuildDirectory) {
  auto plugins = test::load_build_plugins();
  EXPECT_TRUE(plugins->diagnostics.empty());
  EXPECT_EQ(plugins->libraries.size(), 3u);
  for (const std::string name : {"C3D14", "C3D21", "C3D28"}) {
    const ElementRegistry::Entry* entry = plugins->registry.entry(name);
    ASSERT_NE(entry, nullptr) << name;
    EXPECT_EQ(entry->element->name(), name);
    const std::string lib = "libstyk_" +
                            std::string(name == "C3D14"   ? "c3d14"
                                        : name == "C3D21" ? "c3d21"
                                                          : "c3d28") +
                            ".so";
    EXPECT_EQ(entry->source, canonical(std::string(STYK_PLUGIN_BUILD_DIR) + "/" + lib));
  }
  EXPECT_EQ(plugins->registry.find("c3d21"), plugins->registry.find("C3D21"));  // case-insensitive
  EXPECT_EQ(plugins->registry.searched_paths, STYK_PLUGIN_BUILD_DIR);
}

TEST(PluginLoader, SameDirectoryTwiceLoadsEachLibraryOnce) {
  auto plugins = test::load_build_plugins({STYK_PLUGIN_BUILD_DIR, STYK_PLUGIN_BUILD_DIR});
  EXPECT_TRUE(plugins->diagnostics.empty());
  EXPECT_EQ(plugins->libraries.size(), 3u);
  EXPECT_EQ(plugins->registry.names().size(), 3u);
}

TEST(PluginLoader, MissingDirectoryIsANonFatalDiagnostic) {
  const std::string missing = std::string(STYK_BINARY_DIR) + "/no/such/plugin/dir";
  auto plugins = test::load_build_plugins({missing, STYK_PLUGIN_BUILD_DIR});
  ASSERT_EQ(plugins->diagnostics.size(), 1u);
  EXPECT_EQ(plugins->diagnostics[0].kind, Kind::DirectoryMissing);
  EXPECT_EQ(plugins->diagnostics[0].path, missing);
  EXPECT_TRUE(contains(plugins->diagnostics[0].message, missing + " does not exist"))
      << plugins->diagnostics[0].message;
  EXPECT_NE(plugins->registry.find("C3D28"), nullptr);  // the others still load
  EXPECT_EQ(plugins->registry.searched_paths, missing + ":" + STYK_PLUGIN_BUILD_DIR);
}

TEST(PluginLoader, FileThatIsNotALibraryReportsTheDlerrorText) {
  ScratchDirectory dir("not_a_library");
  const std::string file = dir.str() + "/libjunk.so";
  std::ofstream(file) << "this is not an ELF file\n";
  auto plugins = test::load_build_plugins({dir.str()});
  ASSERT_EQ(plugins->diagnostics.size(), 1u);
  const PluginDiagnostic& d = plugins->diagnostics[0];
  EXPECT_EQ(d.kind, Kind::OpenFailed);
  EXPECT_EQ(d.path, canonical(file));
  EXPECT_TRUE(contains(d.message, "plug-in " + canonical(file) + ": cannot be loaded: "))
      << d.message;
  EXPECT_TRUE(contains(d.message, "libjunk.so:")) << d.message;  // dlerror names the file
  EXPECT_EQ(plugins->libraries.size(), 0u);
}

TEST(PluginLoader, LibraryWithoutEntryIsNotAPlugin) {
  auto plugins = test::load_build_plugins({bad_plugin_dir("no_entry")});
  ASSERT_EQ(plugins->diagnostics.size(), 1u);
  const PluginDiagnostic& d = plugins->diagnostics[0];
  EXPECT_EQ(d.kind, Kind::NoEntry);
  EXPECT_TRUE(contains(d.message, "libstyk_test_no_entry.so: is not a Styk plug-in")) << d.message;
  EXPECT_TRUE(contains(d.message, "styk_plugin_register")) << d.message;
  EXPECT_EQ(plugins->libraries.size(), 0u);
}

TEST(PluginLoader, WrongAbiVersionNamesBothVersions) {
  auto plugins = test::load_build_plugins({bad_plugin_dir("abi_mismatch")});
  ASSERT_EQ(plugins->diagnostics.size(), 1u);
  const PluginDiagnostic& d = plugins->diagnostics[0];
  EXPECT_EQ(d.kind, Kind::AbiMismatch);
  EXPECT_TRUE(contains(d.message, "expects version " + std::to_string(STYK_PLUGIN_ABI_VERSION)))
      << d.message;
  EXPECT_TRUE(contains(d.message, "built for version 999")) << d.message;
  EXPECT_TRUE(plugins->registry.names().empty());
  EXPECT_EQ(plugins->libraries.size(), 0u);
}

// The SDK side of the handshake: a real plug-in called by a host of another ABI version answers
// with its own version and registers nothing.
TEST(PluginLoader, SdkEntryRejectsAHostOfAnotherAbiVersion) {
  const std::string path = std::string(STYK_PLUGIN_BUILD_DIR) + "/libstyk_c3d14.so";
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  ASSERT_NE(handle, nullptr) << dlerror();
  void* symbol = dlsym(handle, STYK_PLUGIN_ENTRY_NAME);
  ASSERT_NE(symbol, nullptr);
  StykPluginRegisterFn entry = nullptr;
  std::memcpy(&entry, &symbol, sizeof entry);
  ElementRegistry registry;
  StykPluginHost host{};
  host.abi_version = STYK_PLUGIN_ABI_VERSION + 1;
  host.plugin_path = path.c_str();
  host.registry = &registry;
  StykPluginReply reply{};
  EXPECT_EQ(entry(&host, &reply), STYK_PLUGIN_ABI_MISMATCH);
  EXPECT_EQ(reply.plugin_abi_version, STYK_PLUGIN_ABI_VERSION);
  EXPECT_TRUE(registry.names().empty());
  host.abi_version = STYK_PLUGIN_ABI_VERSION;  // and with the right version it registers
  EXPECT_EQ(entry(&host, &reply), STYK_PLUGIN_OK);
  EXPECT_NE(registry.find("C3D14"), nullptr);
  // registry (declared after handle was opened) dies first; then the library may go.
  registry = ElementRegistry();
  dlclose(handle);
}

// A duplicate type name registers nothing of that plug-in (all or none) and names both sources.
TEST(PluginLoader, DuplicateTypeNameRejectsTheWholePlugin) {
  test::LoadedPlugins plugins;
  register_builtin_elements(plugins.registry);
  const auto diagnostics =
      load_plugins(plugins.registry, plugins.libraries, {bad_plugin_dir("duplicate_name")});
  ASSERT_EQ(diagnostics.size(), 1u);
  const PluginDiagnostic& d = diagnostics[0];
  EXPECT_EQ(d.kind, Kind::RegistrationFailed);
  EXPECT_TRUE(contains(d.message,
                       "registration failed: element type C3D8 is already registered by built-in"))
      << d.message;
  EXPECT_EQ(plugins.registry.find("DUPOK"), nullptr);
  EXPECT_EQ(plugins.registry.entry("C3D8")->source, "built-in");
}

// Two copies of the same plug-in (e.g. an installed and a freshly built one): the first
// directory wins, the second copy is reported with both paths.
TEST(PluginLoader, SecondCopyOfAPluginIsReportedAsDuplicate) {
  ScratchDirectory dir("copy");
  const std::string original = canonical(std::string(STYK_PLUGIN_BUILD_DIR) + "/libstyk_c3d14.so");
  fs::copy_file(original, dir.str() + "/libstyk_c3d14.so");
  auto plugins = test::load_build_plugins({STYK_PLUGIN_BUILD_DIR, dir.str()});
  ASSERT_EQ(plugins->diagnostics.size(), 1u);
  const PluginDiagnostic& d = plugins->diagnostics[0];
  EXPECT_EQ(d.kind, Kind::RegistrationFailed);
  EXPECT_TRUE(contains(d.message, canonical(dir.str() + "/libstyk_c3d14.so"))) << d.message;
  EXPECT_TRUE(contains(d.message, "C3D14 is already registered by " + original)) << d.message;
  EXPECT_EQ(plugins->registry.entry("C3D14")->source, original);
  EXPECT_EQ(plugins->libraries.size(), 3u);
}

TEST(PluginLoader, ThrowingRegistrationIsReportedWithItsMessage) {
  auto plugins = test::load_build_plugins({bad_plugin_dir("throwing_registration")});
  ASSERT_EQ(plugins->diagnostics.size(), 1u);
  EXPECT_EQ(plugins->diagnostics[0].kind, Kind::RegistrationFailed);
  EXPECT_TRUE(contains(plugins->diagnostics[0].message,
                       "registration failed: cannot read the element table tmpl.dat"))
      << plugins->diagnostics[0].message;
}

// A hand-written entry that lets an exception escape does not take the host down.
TEST(PluginLoader, ExceptionEscapingAHandWrittenEntryIsCaught) {
  auto plugins = test::load_build_plugins({bad_plugin_dir("escaping_exception")});
  ASSERT_EQ(plugins->diagnostics.size(), 1u);
  EXPECT_EQ(plugins->diagnostics[0].kind, Kind::RegistrationFailed);
  EXPECT_TRUE(contains(plugins->diagnostics[0].message, "hand-written entry gave up"))
      << plugins->diagnostics[0].message;
}

// All bad plug-ins together with the good ones: one diagnostic each, the good ones still load.
TEST(PluginLoader, BadPluginsDoNotStopTheGoodOnes) {
  std::vector<std::string> dirs;
  for (const char* bad :
       {"no_entry", "abi_mismatch", "throwing_registration", "escaping_exception"})
    dirs.push_back(bad_plugin_dir(bad));
  dirs.push_back(STYK_PLUGIN_BUILD_DIR);
  auto plugins = test::load_build_plugins(dirs);
  EXPECT_EQ(plugins->diagnostics.size(), 4u);
  EXPECT_EQ(plugins->registry.names(), (std::vector<std::string>{"C3D14", "C3D21", "C3D28"}));
}

// RTLD_NODELETE safety belt: even if the libraries are released before the registry, the
// registered elements (whose vtables live in the plug-ins) stay usable and destructible.
TEST(PluginLoader, RegistryMayOutliveTheLibraryHandles) {
  ElementRegistry registry;
  {
    PluginLibraries libraries;
    EXPECT_TRUE(load_plugins(registry, libraries, {STYK_PLUGIN_BUILD_DIR}).empty());
  }
  const TElement* e = registry.find("C3D28");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->node_count(), 28);
  Eigen::MatrixXd K;
  e->stiffness(test::reference_geometry(*e), test::unit_material(), RuleKind::Full, K);
  EXPECT_EQ(K.rows(), 84);
}

TEST(PluginLoader, MovedLibrariesKeepTheirHandles) {
  PluginLibraries first;
  ElementRegistry registry;
  load_plugins(registry, first, {STYK_PLUGIN_BUILD_DIR});
  PluginLibraries second = std::move(first);
  EXPECT_EQ(second.size(), 3u);
  EXPECT_EQ(second.paths().size(), 3u);
  EXPECT_TRUE(second.contains(canonical(std::string(STYK_PLUGIN_BUILD_DIR) + "/libstyk_c3d21.so")));
}

TEST(PluginDirectories, EnvironmentEntriesThenExistingDefaults) {
  const std::string build = STYK_PLUGIN_BUILD_DIR;
  const std::string missing_default = build + "/missing_default";
  EXPECT_EQ(plugin_directories("/a::/b:", {build, missing_default}),
            (std::vector<std::string>{"/a", "/b", build}));
  EXPECT_EQ(plugin_directories(nullptr, {missing_default}), std::vector<std::string>{});
  EXPECT_EQ(plugin_directories("", {build}), std::vector<std::string>{build});
  // A directory named twice (e.g. STYK_PLUGIN_PATH includes the default) is searched once.
  EXPECT_EQ(plugin_directories((build + ":" + build + "/.").c_str(), {build}),
            std::vector<std::string>{build});
}

}  // namespace
}  // namespace styk
