// Where the method fails, the solver says so before solving (docs/solver.md §1 "Warnings"; SPEC
// §2.1 hourglassing of C3D8R without control, §3.1.7 volumetric locking as nu -> 0.5, §3.1.2
// distorted elements). Every warning lands in AnalysisReport::warnings; these tests assert which
// models get which warning, and that sound models get none.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "hex_model_builder.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

const test::HexCorners kCube = {
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};

// A 2 x 2 x 2 cube of `type`, bottom fixed, top pulled up; the warnings of solving it (a model
// the solver then refuses, e.g. singular, still reports what the check found).
std::vector<std::string> warnings_of(Model model, const ElementRegistry& registry) {
  for (int n = 0; n < model.node_count(); ++n)
    if (std::abs(model.coords[n][2]) < 1e-12)
      for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, {}});
  for (int n = 0; n < model.node_count(); ++n)
    if (std::abs(model.coords[n][2] - 2.0) < 1e-12)
      model.steps[0].cloads.push_back({n, 3, 1.0, {}});
  AnalysisReport report;
  try {
    run_static_analysis(model, registry, SolveOptions{}, nullptr, &report);
  } catch (const InputError&) {
    // C3D8R0 alone is singular: the warning said why beforehand.
  }
  return report.warnings;
}

Model cube_of(const ElementRegistry& registry, const std::string& type, double poisson) {
  test::HexModelBuilder builder(registry, 210000.0, poisson);
  for (int cell = 0; cell < 8; ++cell) {
    test::HexCorners corners = kCube;
    for (Vec3& c : corners)
      for (int d = 0; d < 3; ++d) c[d] += (cell >> d) & 1;
    builder.add(type, corners);
  }
  return builder.finish();
}

class ModelWarnings : public ::testing::Test {
 protected:
  std::unique_ptr<test::FullRegistry> full_ = test::registry_with_plugins();
  const ElementRegistry& registry_ = full_->registry;
};

// SPEC §2.1: only the brick without hourglass control has zero-energy modes that a mesh keeps
// (C3D20R's single-element modes do not spread through a patch).
TEST_F(ModelWarnings, OnlyTheUncontrolledReducedBrickWarnsOfHourglassModes) {
  for (const char* type :
       {"C3D8", "C3D8R", "C3D8I", "C3D20", "C3D20R", "C3D27", "C3D14", "C3D21", "C3D28"}) {
    const auto warnings = warnings_of(cube_of(registry_, type, 0.3), registry_);
    EXPECT_TRUE(warnings.empty()) << type << ": " << (warnings.empty() ? "" : warnings[0]);
  }
  const auto warnings = warnings_of(cube_of(registry_, "C3D8R0", 0.3), registry_);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("8 elements of type C3D8R0 have"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("zero-energy (hourglass) modes"), std::string::npos);
}

// SPEC §3.1.7: elements lock as nu -> 0.5, each from the Poisson's ratio where its error passes
// 10 % on the stability sweep (docs/stability.md; the brackets are asserted in
// atlas_warnings_test.cpp): C3D8 from 0.45, the quadratic hexahedra and C3D8R (its hourglass
// control) from 0.495; incompatible modes, C3D20R and TECHNIQUE=SELECTIVE do not lock.
TEST_F(ModelWarnings, NearlyIncompressibleElementsWarnOfLockingFromTheirOnset) {
  struct Case {
    const char* type;
    double nu;
    const char* printed;
  };
  const Case locking[] = {{"C3D8", 0.49, "0.49"},
                          {"C3D20", 0.499, "0.499"},
                          {"C3D21", 0.499, "0.499"},
                          {"C3D8R", 0.499, "0.499"}};
  for (const auto& [type, nu, printed] : locking) {
    const auto warnings = warnings_of(cube_of(registry_, type, nu), registry_);
    ASSERT_EQ(warnings.size(), 1u) << type;
    EXPECT_NE(warnings[0].find(std::string("8 ") + type + " elements of element set EALL lock"),
              std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[0].find(std::string("Poisson's ratio ") + printed), std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[0].find(std::string(type) == "C3D8R" ? "use C3D8I or C3D20R"
                                                            : "TECHNIQUE=SELECTIVE"),
              std::string::npos)
        << warnings[0];
  }
  EXPECT_NE(warnings_of(cube_of(registry_, "C3D20", 0.499), registry_)[0].find(
                "(C3D20 locks from 0.495)"),
            std::string::npos);
  // Below the onsets: C3D20 at 0.49 (1.1 % error on the sweep), C3D8R at 0.49 (2.2 %).
  for (const char* type : {"C3D8R", "C3D8I", "C3D20R", "C3D20", "C3D21"})
    EXPECT_TRUE(warnings_of(cube_of(registry_, type, 0.49), registry_).empty()) << type;
  for (const char* type : {"C3D8I", "C3D20R"})
    EXPECT_TRUE(warnings_of(cube_of(registry_, type, 0.49999), registry_).empty()) << type;
  Model selective = cube_of(registry_, "C3D20", 0.499);
  selective.sections[0].selective_volumetric = true;
  EXPECT_TRUE(warnings_of(selective, registry_).empty());
  EXPECT_TRUE(warnings_of(cube_of(registry_, "C3D8", 0.44), registry_).empty());
}

// SPEC §3.1.2's kind of failure: an element whose det J falls to 0.072 of its largest value inside
// (a corner pushed to the element's centre) is named; a strongly tapered but even wedge (0.31) is
// not.
TEST_F(ModelWarnings, StronglyDistortedElementsAreNamed) {
  Model model = cube_of(registry_, "C3D8", 0.3);
  // Element 1 (the cell at the origin): its top corner (1, 1, 1) moves to (0.5, 0.5, 0.5). Its
  // neighbours keep the old node, so the mesh opens there; the warning is about the shape.
  test::HexModelBuilder builder(registry_, 210000.0, 0.3);
  test::HexCorners pushed = kCube;
  pushed[6] = {0.5, 0.5, 0.5};
  builder.add("C3D8", pushed);
  test::HexCorners wedge = kCube;
  wedge[5][0] = wedge[6][0] = 0.05;  // the top face shrunk to a sliver at x = 0..0.05
  for (Vec3& c : wedge) c[0] += 3.0;
  builder.add("C3D8", wedge);
  Model two = builder.finish();
  for (int n = 0; n < two.node_count(); ++n)
    if (std::abs(two.coords[n][2]) < 1e-12)
      for (int dof = 1; dof <= 3; ++dof) two.boundaries.push_back({n, dof, 0.0, {}});
  AnalysisReport report;
  run_static_analysis(two, registry_, SolveOptions{}, nullptr, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("1 element is strongly distorted"), std::string::npos)
      << report.warnings[0];
  EXPECT_NE(report.warnings[0].find("worst: element 1 (C3D8"), std::string::npos);
  EXPECT_NE(report.warnings[0].find("min/max det J 0.0718"), std::string::npos)
      << report.warnings[0];
  EXPECT_TRUE(warnings_of(model, registry_).empty());
}

}  // namespace
}  // namespace styk
