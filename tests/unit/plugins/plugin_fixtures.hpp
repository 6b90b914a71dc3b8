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

inline ElementGeometry reference_geometry(const TElement& element, Id id = 1) {
  ElementGeometry g;
  const auto& nodes = element.natural_nodes();
  g.X.resize(element.node_count(), 3);
  for (int i = 0; i < element.node_count(); ++i)
    for (int j = 0; j < 3; ++j) g.X(i, j) = nodes[i][j];
  g.id = id;
  g.where = SourceLoc{"test.inp", 7};
  return g;
}

// Every node moved by a uniform random amount in [-amplitude, amplitude] (elements-ref section 7
// uses up to 0.15).
inline ElementGeometry distorted_geometry(const TElement& element, unsigned seed,
                                          double amplitude = 0.15) {
  ElementGeometry g = reference_geometry(element);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-amplitude, amplitude);
  for (int i = 0; i < g.X.rows(); ++i)
    for (int j = 0; j < 3; ++j) g.X(i, j) += shift(rng);
  return g;
}

inline Material material(double young, double poisson) {
  Material m;
  m.name = "TEST";
  m.young = young;
  m.poisson = poisson;
  m.where = SourceLoc{"test.inp", 3};
  return m;
}

// E = 1, nu = 0.3: the material of elements-ref section 7.
inline Material unit_material() { return material(1.0, 0.3); }

inline std::vector<Vec3> random_points(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int k = 0; k < count; ++k) points.push_back(Vec3{u(rng), u(rng), u(rng)});
  return points;
}

// Zero eigenvalues of a symmetric K, relative tolerance 1e-9 of the largest (elements-ref
// section 7, where the gap to the first non-zero eigenvalue is > 1e13).
inline int zero_eigenvalue_count(const Eigen::MatrixXd& K) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd lambda = solver.eigenvalues();
  const double largest = lambda.cwiseAbs().maxCoeff();
  int zeros = 0;
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    if (std::abs(lambda(i)) < 1e-9 * largest) ++zeros;
  return zeros;
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
