// Shared set-up of the plug-in tests: the three contact hexahedra loaded through the loader from
// the build-tree plug-in directory, reference/distorted geometries, the unit material, and the
// element-independent numeric helpers. Deterministic: random geometry comes from a seed.
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "../elements/element_fixtures.hpp"  // reference/distorted geometry, unit material, zero eigenvalues
#include "styk/core/element.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_loader.hpp"

namespace styk::test {

// The libraries and the registry they filled, in the order that destroys the registry first.
struct LoadedPlugins {
  PluginLibraries libraries;
  ElementRegistry registry;
  std::vector<PluginDiagnostic> diagnostics;
};

inline std::unique_ptr<LoadedPlugins> load_build_plugins(
    const std::vector<std::string>& directories = {STYK_PLUGIN_BUILD_DIR}) {
  auto loaded = std::make_unique<LoadedPlugins>();
  loaded->diagnostics = load_plugins(loaded->registry, loaded->libraries, directories);
  return loaded;
}

// A test fixture holding the loaded plug-ins and looking an element up by name.
class PluginElementTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    plugins_ = load_build_plugins();
    for (const PluginDiagnostic& d : plugins_->diagnostics) ADD_FAILURE() << d.message;
    element_ = plugins_->registry.find(GetParam());
    ASSERT_NE(element_, nullptr) << GetParam() << " not registered by the build plug-ins";
  }
  const TElement& element() const { return *element_; }

 private:
  std::unique_ptr<LoadedPlugins> plugins_;
  const TElement* element_ = nullptr;
};

inline Material material(double young, double poisson) {
  Material m;
  m.name = "TEST";
  m.young = young;
  m.poisson = poisson;
  m.where = SourceLoc{"test.inp", 3};
  return m;
}

inline std::vector<Vec3> random_points(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(Vec3{u(rng), u(rng), u(rng)});
  return points;
}

inline const std::vector<std::string>& contact_hexahedra() {
  static const std::vector<std::string> names = {"C3D14", "C3D21", "C3D28"};
  return names;
}

// Test-name suffix of a parameterised element test: the element name.
inline std::string element_name(const ::testing::TestParamInfo<std::string>& param) {
  return param.param;
}

}  // namespace styk::test
