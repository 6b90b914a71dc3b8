// Every SPEC builder (docs/mesher.md), every element family it offers: positive Jacobians at all
// integration points and nodes, conforming faces (C3D28 layers, C3D21/C3D20 neighbours included),
// no free nodes, the analytic volume within the stated discretisation error, non-empty sets,
// the SPEC element counts, and a deck that reads back through read_inp.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/quality.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Case {
  std::string builder;
  std::map<std::string, std::string> args;  // element family etc.
  int elements;                             // SPEC element count
  int layer;         // elements of the family's own type (C3D21/C3D28 layers), -1 = all
  double volume;     // analytic
  double tolerance;  // relative: 1e-9 for flat geometry; curved: chord / quadratic-arc error
  double min_jacobian_ratio = 0.0;  // strict lower bound over integration points and nodes
};

std::string family_of(const Case& c) { return c.args.count("element") ? c.args.at("element") : ""; }

std::ostream& operator<<(std::ostream& os, const Case& c) {
  os << c.builder;
  for (const auto& [k, v] : c.args) os << " --" << k << " " << v;
  return os;
}

// Tolerances: linear elements facet curved boundaries (chord error of arcs of 8-15 degrees:
// about 1 - sin(a)/a <= 1.2 %); quadratic elements follow them to ~1e-5.
const double kCurvedVolume = kPi / 4 * (4.32 * 4.32 - 4.12 * 4.12) * 0.1;
const double kHemisphereVolume =
    (kPi / 2) * std::sin(72 * kPi / 180) * (std::pow(10.02, 3) - std::pow(9.98, 3)) / 3;

std::vector<Case> cases() {
  std::vector<Case> out;
  auto all = [&](const std::string& builder, std::map<std::string, std::string> args, int n,
                 std::map<std::string, int> layer, double volume, double linear_tol,
                 double quadratic_tol) {
    for (const std::string fam : {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"}) {
      auto a = args;
      a["element"] = fam;
      const bool linear = fam == "C3D8" || fam == "C3D14";
      out.push_back({builder, a, n, layer.count(fam) ? layer[fam] : -1, volume,
                     linear ? linear_tol : quadratic_tol});
    }
  };
  // SPEC §2.1: meshes 6x1, 12x2, 12x4, 24x8, one element across the width.
  for (const auto& [mesh, n] :
       std::map<std::string, int>{{"6x1", 6}, {"12x2", 24}, {"12x4", 48}, {"24x8", 192}})
    all("cantilever", {{"mesh", mesh}}, n,
        {{"C3D21", n / std::stoi(mesh.substr(mesh.find('x') + 1))},
         {"C3D28", n / std::stoi(mesh.substr(mesh.find('x') + 1))}},
        150 * 2.5 * 5, 1e-9, 1e-9);
  all("single-element", {}, 1, {}, 8, 1e-12, 1e-12);  // SPEC §2.4
  for (int n : {6, 12, 24})
    all("straight-beam", {{"n", std::to_string(n)}}, n, {}, 6 * 0.2 * 0.1, 1e-9, 1e-9);
  for (const char* mesh : {"regular", "distorted"})
    all("beam-10x2x2", {{"mesh", mesh}}, 5, {}, 40, 1e-9, 1e-9);  // SPEC §3.1.2: 5 elements
  all("curved-beam", {}, 6, {}, kCurvedVolume, 0.012, 1e-5);      // 15 deg arcs
  for (int n : {12, 24})                                          // SPEC §3.1.4: 12x2, 24x2
    all("twisted-beam", {{"n", std::to_string(n)}}, 2 * n, {{"C3D21", n}, {"C3D28", n}},
        12 * 1.1 * 0.32, 0.01, 1e-4);
  for (int n : {6, 10})  // SPEC §3.1.5: 6x6, 10x10
    all("thick-plate", {{"n", std::to_string(n)}}, n * n, {}, 400 * 400 * 40, 1e-9, 1e-9);
  all("hemisphere", {}, 81, {}, kHemisphereVolume, 0.012, 5e-5);  // 9x9 elements, 10/8 deg arcs
  all("thick-cylinder", {}, 45, {{"C3D21", 9}, {"C3D28", 9}}, 18 * kPi, 0.006, 1e-5);
  all("patch-test", {}, 7, {{"C3D21", 6}, {"C3D28", 6}}, 1.0, 1e-12, 1e-12);  // SPEC §3.1.8
  // The MacNeal-Harder interior nodes make one element's corner det J negative (node 5 lies
  // 0.186 from the y = 0 face); the integration points, which the solver uses, stay positive.
  for (std::size_t i = out.size() - 5; i < out.size(); ++i) out[i].min_jacobian_ratio = -1.0;
  all("cylinder-wall", {}, 200, {}, 5 * kPi, 0.005, 1e-5);  // SPEC §6.2: 200 elements
  return out;
}

class BuilderTest : public ::testing::TestWithParam<Case> {
 protected:
  test::Elements elements_;
};

TEST_P(BuilderTest, MeshIsValidAndReadsBack) {
  const Case& c = GetParam();
  const ElementRegistry& registry = elements_.registry;
  const mesher::BuildResult r = mesher::run_builder(c.builder, c.args, registry);
  const Model& model = r.model;
  SCOPED_TRACE(test::type_counts(model));

  EXPECT_EQ(model.element_count(), c.elements);
  const std::string fam = family_of(c);
  int of_family = 0;
  for (const Element& e : model.elements) of_family += e.type == fam;
  EXPECT_EQ(of_family, c.layer < 0 ? c.elements : c.layer);
  for (const Element& e : model.elements) EXPECT_TRUE(e.type == fam || e.type == "C3D20") << e.type;

  // Positive Jacobians (TElement::jacobian throws naming the element otherwise).
  const mesher::QualityReport q = mesher::assess_quality(model, registry);
  EXPECT_GT(q.min_jacobian_ratio, c.min_jacobian_ratio);
  EXPECT_NEAR(test::volume(model, registry), c.volume, c.tolerance * c.volume);
  EXPECT_NEAR(q.volume, c.volume, c.tolerance * c.volume);

  EXPECT_EQ(test::conformity_problem(model, registry), "");
  EXPECT_EQ(test::free_nodes(model), 0);
  EXPECT_FALSE(model.nsets.empty());
  for (const auto& [name, set] : model.nsets) EXPECT_FALSE(set.nodes.empty()) << name;
  for (const auto& [name, set] : model.elsets) EXPECT_FALSE(set.elements.empty()) << name;
  ASSERT_EQ(model.steps.size(), 1u);
  EXPECT_FALSE(model.steps[0].outputs.empty());
  EXPECT_TRUE(!model.boundaries.empty() || !model.steps[0].boundaries.empty());

  // The deck re-reads to the same mesh.
  const std::string path = ::testing::TempDir() + "mesher_" + c.builder + "_" + fam + ".inp";
  {
    std::ofstream out(path);
    write_inp(model, out);
  }
  const Model back = read_inp(path, registry);
  EXPECT_EQ(back.node_count(), model.node_count());
  EXPECT_EQ(back.element_count(), model.element_count());
  EXPECT_EQ(back.nsets.size(), model.nsets.size());
  std::remove(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(Spec, BuilderTest, ::testing::ValuesIn(cases()));

TEST(Builders, CatalogueIsInSpecOrderWithSections) {
  const auto all = mesher::builder_catalogue();
  // Every SPEC model with a builder, in SPEC order (issue: "a builder for every SPEC.md model").
  const std::vector<std::string> expected = {
      "cantilever",     "single-element",  "stacked-elements", "straight-beam",
      "beam-10x2x2",    "curved-beam",     "twisted-beam",     "thick-plate",
      "hemisphere",     "thick-cylinder",  "patch-test",       "punch-foundation",
      "cylinders",      "two-cantilevers", "punch-halfspace",  "shrink-fit",
      "conical-fit",    "spline-joint",    "p3g-joint",        "bolted-flange",
      "electric-plate", "cylinder-wall"};
  std::vector<std::string> names;
  for (const auto& b : all) names.push_back(b.name);
  EXPECT_EQ(names, expected);
  EXPECT_EQ(all.front().section, "§2.1");
  EXPECT_EQ(all.back().section, "§6.2");
  for (const auto& b : all) {
    EXPECT_FALSE(b.title.empty());
    EXPECT_EQ(b.params.front().name, "element") << b.name;
  }
}

TEST(Builders, BadParametersAreInputErrorsNamingThem) {
  test::Elements elements;
  auto message = [&](const std::string& builder, std::map<std::string, std::string> args) {
    try {
      mesher::run_builder(builder, args, elements.registry);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("nonsense", {}).find("unknown builder 'nonsense'"), std::string::npos);
  EXPECT_NE(message("cantilever", {{"colour", "red"}}).find("unknown parameter --colour"),
            std::string::npos);
  EXPECT_NE(message("cantilever", {{"mesh", "6by1"}}).find("--mesh"), std::string::npos);
  EXPECT_NE(message("cantilever", {{"element", "C3D99"}}).find("--element: 'C3D99' is not one of"),
            std::string::npos);
  EXPECT_NE(message("thick-plate", {{"n", "7"}}).find("--n must be even"), std::string::npos);
  EXPECT_NE(message("straight-beam", {{"n", "0"}}).find("--n: expected an integer >= 1"),
            std::string::npos);
  EXPECT_NE(message("thick-cylinder", {{"grading", "abc"}}).find("'abc' is not a number"),
            std::string::npos);
}

// SPEC §2.1: consistent traction on the end face sums to P; the twisted beam's tip load is one
// node with a mid-edge node (C3D20), two halves without (C3D8).
TEST(Builders, LoadsSumToTheirResultants) {
  test::Elements elements;
  for (const char* fam : {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"}) {
    const auto r =
        mesher::run_builder("cantilever", {{"element", fam}, {"mesh", "12x2"}}, elements.registry);
    double fz = 0.0;
    for (const auto& c : r.model.steps[0].cloads) fz += c.dof == 3 ? c.value : 0.0;
    EXPECT_NEAR(fz, 5.0, 1e-12) << fam;
  }
  const auto c20 = mesher::run_builder("twisted-beam", {{"element", "C3D20"}}, elements.registry);
  EXPECT_EQ(c20.model.steps[0].cloads.size(), 1u);
  const auto c8 = mesher::run_builder("twisted-beam", {{"element", "C3D8"}}, elements.registry);
  ASSERT_EQ(c8.model.steps[0].cloads.size(), 2u);
  EXPECT_NEAR(c8.model.steps[0].cloads[0].value, 0.5, 1e-12);
}

}  // namespace
}  // namespace styk
