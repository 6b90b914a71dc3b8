// SPEC §2.1 through the solver for the rest of the solid family: the cantilever l = 150, b = 2.5,
// h = 5, E = 70 000, nu = 0, P = 5 as a uniform shear traction on the end face (consistent nodal
// loads), clamped root; meshes 6x1, 12x2, 12x4, 24x8 (one element across the width); deflection
// normalised by beam theory Pl^3/(3EI) = 3.0857. Expected values: SPEC's CalculiX 2.20 table.
// Meshes are built as C3D8/C3D20 by mesher::make_cantilever and the element type is renamed.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "styk/core/diagnostics.hpp"
#include "styk/mesher/cantilever.hpp"
#include "verification_support.hpp"

namespace styk::verification {
namespace {

constexpr double kBeamTheory = 5.0 * 150.0 * 150.0 * 150.0 / (3.0 * 70000.0 * 2.5 * 125.0 / 12.0);

struct Mesh {
  int along;
  int through;
};
constexpr Mesh kMeshes[4] = {{6, 1}, {12, 2}, {12, 4}, {24, 8}};

// Normalised tip deflection of the cantilever meshed with `type` (built as `base`).
double normalised_deflection(const std::string& base, const std::string& type, Mesh mesh) {
  mesher::CantileverSpec spec;
  spec.box.type = base;
  spec.box.size = {150.0, 2.5, 5.0};
  spec.box.divisions = {mesh.along, 1, mesh.through};
  spec.young = 70000.0;
  spec.poisson = 0.0;
  spec.load = mesher::CantileverSpec::Load::EndTraction;
  spec.force = {0.0, 0.0, 5.0};
  Model model = mesher::make_cantilever(spec);
  for (Element& element : model.elements) element.type = type;
  return mean_displacement(model, solve(model), "TIP", 2) / kBeamTheory;
}

TEST(Spec2_1_Family, C3D8IHasNoShearLocking) {
  // SPEC §2.1 (CalculiX 2.20): C3D8I 0.994 / 0.999 / 0.999 / 1.000, tolerance 1 %.
  const double expected[4] = {0.994, 0.999, 0.999, 1.000};
  std::printf("SPEC 2.1 C3D8I normalised | mesh | styk   | CalculiX\n");
  for (int m = 0; m < 4; ++m) {
    const double u = normalised_deflection("C3D8", "C3D8I", kMeshes[m]);
    std::printf("                          | %2dx%d | %.4f | %.3f\n", kMeshes[m].along,
                kMeshes[m].through, u, expected[m]);
    EXPECT_NEAR(u, expected[m], 1e-2 * expected[m])
        << kMeshes[m].along << "x" << kMeshes[m].through;
  }
}

// The solve of a mesh that is a mechanism: the solver's InputError message ("" if it solved).
std::string mechanism_message(const std::string& base, const std::string& type, Mesh mesh) {
  try {
    normalised_deflection(base, type, mesh);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Spec2_1_Family, C3D20R) {
  // SPEC §2.1 (CalculiX 2.20): C3D20R 1.279 / 1.001 / 1.001 / 1.001. The 12x2, 12x4 and 24x8
  // meshes are asserted to 1 %. The 6x1 mesh (one element through the height AND across the
  // width) is a mechanism: the 2x2x2 rule's spurious modes connect from element to element, and
  // the clamped stiffness has zero eigenvalues (relative 1e-16). CalculiX returns a number for it
  // (1.279, 28 % off); Styk's solver reports the mechanism instead, which is asserted. Thesis'
  // Abaqus C3D20R (Tab 2.4): 1.00 / 1.000 / 1.000 / 1.000, printed.
  const double expected[4] = {1.279, 1.001, 1.001, 1.001};
  const double thesis[4] = {1.00, 1.000, 1.000, 1.000};
  const std::string message = mechanism_message("C3D20", "C3D20R", kMeshes[0]);
  std::printf("SPEC 2.1 C3D20R 6x1: %s (CalculiX 1.279)\n", message.c_str());
  EXPECT_NE(message.find("singular"), std::string::npos) << message;
  EXPECT_NE(message.find("mechanism"), std::string::npos) << message;
  std::printf("SPEC 2.1 C3D20R normalised | mesh | styk   | CalculiX | thesis Abaqus\n");
  for (int m = 1; m < 4; ++m) {
    const double u = normalised_deflection("C3D20", "C3D20R", kMeshes[m]);
    std::printf("                           | %2dx%d | %.4f | %.3f    | %.3f\n", kMeshes[m].along,
                kMeshes[m].through, u, expected[m], thesis[m]);
    EXPECT_NEAR(u, expected[m], 1e-2 * expected[m])
        << kMeshes[m].along << "x" << kMeshes[m].through;
  }
}

TEST(Spec2_1_Family, C3D8RWithHourglassControl) {
  // SPEC §2.1 (CalculiX 2.20, its own hourglass control): C3D8R 0.657 / 1.106 / 0.968 / 0.996.
  // Hourglass-control formulations and their stiffness scalings differ (ours: Flanagan-Belytschko
  // with kappa = 0.005, docs/elements.md), and at 6x1 the bending stiffness comes from the
  // control alone, so only this is asserted: every mesh within 25 % of CalculiX and the 24x8
  // mesh within 2 % of beam theory. Thesis' Abaqus C3D8R (Tab 2.4): 70.1 (hourglassing) / 1.323 /
  // 1.063 / 1.015, printed.
  const double expected[4] = {0.657, 1.106, 0.968, 0.996};
  const double thesis[4] = {70.1, 1.323, 1.063, 1.015};
  std::printf("SPEC 2.1 C3D8R normalised | mesh | styk   | CalculiX | thesis Abaqus\n");
  for (int m = 0; m < 4; ++m) {
    const double u = normalised_deflection("C3D8", "C3D8R", kMeshes[m]);
    std::printf("                          | %2dx%d | %.4f | %.3f    | %.3f\n", kMeshes[m].along,
                kMeshes[m].through, u, expected[m], thesis[m]);
    EXPECT_NEAR(u, expected[m], 0.25 * expected[m])
        << kMeshes[m].along << "x" << kMeshes[m].through;
  }
  EXPECT_NEAR(normalised_deflection("C3D8", "C3D8R", kMeshes[3]), 1.0, 0.02);
}

TEST(Spec2_1_Family, C3D8RWithoutHourglassControlFails) {
  // SPEC §2.1 "method fails": Abaqus' C3D8R gives 70.1 at 6x1, hourglassing. Without any control
  // (C3D8R0) the clamped 6x1 beam has exactly zero-energy hourglass modes (the stiffness has zero
  // eigenvalues, relative 1e-16): no finite deflection exists, and the solver says so, naming the
  // mechanism, instead of returning a number made of round-off. With the control (C3D8R, test
  // above) the same mesh gives a finite, if too stiff, answer.
  const std::string message = mechanism_message("C3D8", "C3D8R0", kMeshes[0]);
  std::printf("SPEC 2.1 C3D8R0 (no hourglass control) 6x1: %s (Abaqus 70.1)\n", message.c_str());
  EXPECT_NE(message.find("singular"), std::string::npos) << message;
  EXPECT_NE(message.find("mechanism"), std::string::npos) << message;
  EXPECT_EQ(mechanism_message("C3D8", "C3D8R", kMeshes[0]), "");
}

}  // namespace
}  // namespace styk::verification
