// A GoogleTest fixture base whose suite shares one element registry with the build tree's plug-ins
// (registry_with_plugins(), element_registries.hpp):
//
//   class Contact : public test::PluginRegistrySuite<> {};
//   TEST_F(Contact, Patch) { run_static_analysis(model, registry(), ...); }
//   class Sector : public test::PluginRegistrySuite<::testing::TestWithParam<Symmetry>> {};
//
// Loading the plug-ins (dlopen and registration) is the slow part of building the registry, so
// the suite loads them once before its first test instead of once per test, and releases the
// registry together with its library handles after its last test: the registry lives exactly as
// long as the suite that uses it.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "support/element_registries.hpp"

namespace styk::test {

// `Base` is the GoogleTest fixture the suite would otherwise derive from (::testing::Test or
// ::testing::TestWithParam<T>). A suite that needs more set-up defines its own SetUpTestSuite and
// calls this one first.
//
// The registry is a static member, so there is one per instantiation of the template, and every
// suite of a test program deriving from the same instantiation shares it. That is correct because
// GoogleTest runs the tests of one suite together (also when shuffling) and calls SetUpTestSuite
// before the first and TearDownTestSuite after the last of them, one suite after another: the
// tear-down of one suite empties the slot and the set-up of the next loads a fresh registry
// (were a set-up ever to find the slot filled, the assignment would free the old registry first).
template <class Base = ::testing::Test>
class PluginRegistrySuite : public Base {
 protected:
  static void SetUpTestSuite() { full_ = registry_with_plugins(); }
  static void TearDownTestSuite() { full_.reset(); }

  // The suite's registry; only between its SetUpTestSuite and TearDownTestSuite (a test
  // parameter generator, for one, runs before any suite is set up).
  static const ElementRegistry& registry() { return loaded().registry; }
  // What went wrong while loading the plug-ins (empty when every plug-in loaded).
  static const std::vector<PluginDiagnostic>& plugin_diagnostics() { return loaded().diagnostics; }

 private:
  static const FullRegistry& loaded() {
    if (!full_) throw std::logic_error("the plug-in registry is used outside its test suite");
    return *full_;
  }

  static inline std::unique_ptr<FullRegistry> full_;
};

}  // namespace styk::test
