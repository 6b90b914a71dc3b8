// styk_element_setup, the one element-registry set-up of styk, styk-gui and the tests
// (docs/plugins.md "Where plug-ins are found", "Host side"): built-ins first, then the plug-ins
// of the given directories; the programs' search path is STYK_PLUGIN_PATH, then the default
// directory, which for a program in the build tree is the build's plug-in directory. The
// installed case (<prefix>/lib/styk/plugins) is asserted by ctest sdk_out_of_tree_plugin.
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "styk/elements/element_setup.hpp"

namespace styk {
namespace {

namespace fs = std::filesystem;

TEST(ElementSetup, RegistersTheBuiltinsThenThePluginsOfTheDirectories) {
  PluginLibraries libraries;
  ElementRegistry registry;
  const std::vector<PluginDiagnostic> problems =
      setup_element_registry(registry, libraries, {build_plugin_directory()});
  EXPECT_TRUE(problems.empty()) << problems.front().message;
  ASSERT_NE(registry.entry("C3D8"), nullptr);
  EXPECT_EQ(registry.entry("C3D8")->source, "built-in");
  for (const char* type : {"C3D14", "C3D21", "C3D28"}) {
    const ElementRegistry::Entry* entry = registry.entry(type);
    ASSERT_NE(entry, nullptr) << type;
    EXPECT_EQ(fs::path(entry->source).parent_path(), fs::canonical(build_plugin_directory()))
        << type;
  }
  EXPECT_EQ(libraries.size(), 3u);
  EXPECT_EQ(registry.searched_paths, build_plugin_directory());
}

TEST(ElementSetup, ABuildTreeProgramDefaultsToTheBuildPluginDirectory) {
  // This test runs from the build tree, where <exe>/../lib/styk/plugins does not exist.
  EXPECT_EQ(default_plugin_directory(), build_plugin_directory());
}

TEST(ElementSetup, TheStandardSearchPathIsStykPluginPathThenTheDefault) {
  // Runs in its own process (one ctest case per test), so the variable touches nothing else.
  ASSERT_EQ(setenv("STYK_PLUGIN_PATH", "/no/such/styk/dir:", 1), 0);
  EXPECT_EQ(standard_plugin_directories(),
            (std::vector<std::string>{"/no/such/styk/dir", build_plugin_directory()}));
  ASSERT_EQ(unsetenv("STYK_PLUGIN_PATH"), 0);
  EXPECT_EQ(standard_plugin_directories(), std::vector<std::string>{build_plugin_directory()});
}

TEST(ElementSetup, ARegistryIsSetUpOnce) {
  PluginLibraries libraries;
  ElementRegistry registry;
  setup_element_registry(registry, libraries, {});
  EXPECT_THROW(setup_element_registry(registry, libraries, {}), std::invalid_argument);
}

}  // namespace
}  // namespace styk
