// The solver's model warnings (docs/solver.md §1 "Warnings") for the tetrahedra, wedges and
// axisymmetric rings: no hourglass warning for their standard rules except C3D6 (its check's patch
// keeps 2 zero-energy modes; CAX4R's section rotation does not survive a patch), linear tetrahedra
// warned of bending stiffness where the part is thin for their size and of volumetric locking even
// with TECHNIQUE=SELECTIVE, and the distortion check on a flattened tetrahedron.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "hex_model_builder.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/split.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

class SolidFamilyWarnings : public ::testing::Test {
 protected:
  std::vector<std::string> warnings_of(const Model& model) const {
    AnalysisReport report;
    run_static_analysis(model, full_->registry, SolveOptions{}, nullptr, &report);
    return report.warnings;
  }
  Model built(const std::string& builder, std::map<std::string, std::string> args) const {
    return mesher::run_builder(builder, args, full_->registry).model;
  }
  static bool any_with(const std::vector<std::string>& warnings, const std::string& text) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
  }
  std::unique_ptr<test::FullRegistry> full_ = test::registry_with_plugins();
};

// SPEC §3.1.1 1b cantilever (L = 6, 0.1 x 0.2, 6 bricks) split into tetrahedra and wedges: only
// C3D4 is warned of bending (the part is 0.1 thick, its 36 tetrahedra of 0.02/6 have the size
// (6 sqrt2 V)^(1/3) = 0.305 of a regular one: 0.33 sizes across); only C3D6 has hourglass modes in
// a patch.
TEST_F(SolidFamilyWarnings, ThinPartsOfLinearTetrahedraAreWarnedOfBending) {
  for (const char* family : {"C3D4", "C3D10", "C3D6", "C3D15"}) {
    const auto warnings =
        warnings_of(built("straight-beam", {{"element", family}, {"load", "bending"}}));
    // Measured: the hourglass check finds 2 zero-energy modes of C3D6 (CalculiX's 2-point rule)
    // in its patch and warns; the other types have none.
    EXPECT_EQ(any_with(warnings, "zero-energy"), std::string(family) == "C3D6") << family;
    EXPECT_EQ(any_with(warnings, "linear tetrahedra"), std::string(family) == "C3D4") << family;
  }
  const auto warnings =
      warnings_of(built("straight-beam", {{"element", "C3D4"}, {"load", "bending"}}));
  ASSERT_TRUE(any_with(warnings, "36 linear tetrahedra (C3D4) of element set EALL have only 0.33"))
      << (warnings.empty() ? "" : warnings[0]);
}

// A compact part meshed finely enough is not warned: the unit cube of 6 x 6 x 6 bricks split into
// 1296 C3D4 (size 0.187: 5.3 sizes across), bottom held, top pulled.
TEST_F(SolidFamilyWarnings, FinelyMeshedPartsAreNotWarned) {
  mesher::Mesh mesh;
  mesher::mesh_block(mesh,
                     [](const Vec3& xi) {
                       return Vec3{0.5 * (xi[0] + 1), 0.5 * (xi[1] + 1), 0.5 * (xi[2] + 1)};
                     },
                     {"C3D8", {6, 6, 6}, {1, 1, 1}, "EALL"});
  mesher::split_to_tetrahedra(mesh, full_->registry, "C3D4");
  Model model = mesher::to_model(mesh);
  Material steel;
  steel.name = "STEEL";
  steel.young = 2e5;
  steel.poisson = 0.3;
  model.materials.push_back(steel);
  Section section;
  section.elset = "EALL";
  section.material = "STEEL";
  section.material_index = 0;
  model.sections.push_back(section);
  for (Element& e : model.elements) e.section = 0;
  Step step;
  step.has_procedure = true;
  for (int n = 0; n < model.node_count(); ++n) {
    if (model.coords[n][2] < 1e-12)
      for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, {}});
    if (model.coords[n][2] > 1 - 1e-12) step.cloads.push_back({n, 3, 1.0, {}});
  }
  model.steps.push_back(step);
  const auto warnings = warnings_of(model);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

// SPEC §3.1.7: linear tetrahedra lock as nu -> 0.5 and TECHNIQUE=SELECTIVE cannot help one point;
// the warning says so and points to C3D10.
TEST_F(SolidFamilyWarnings, LinearTetrahedraLockEvenWithSelective) {
  Model model = built("thick-cylinder", {{"element", "C3D4"}, {"poisson", "0.49"}});
  model.sections[0].selective_volumetric = true;
  const auto warnings = warnings_of(model);
  EXPECT_TRUE(any_with(warnings, "C3D4 elements of element set EALL lock volumetrically"));
  EXPECT_TRUE(any_with(warnings, "use quadratic tetrahedra (C3D10)"));
  model.sections[0].selective_volumetric = false;
  Model c3d10 = built("thick-cylinder", {{"element", "C3D10"}, {"poisson", "0.49"}});
  EXPECT_TRUE(any_with(warnings_of(c3d10), "C3D10 elements of element set EALL lock"));
  c3d10.sections[0].selective_volumetric = true;
  EXPECT_FALSE(any_with(warnings_of(c3d10), "lock volumetrically"));
}

}  // namespace
}  // namespace styk
