// SPEC §2.1: the Getting-Started-with-Abaqus cantilever, l = 150, b = 2.5, h = 5, E = 70 000,
// nu = 0, P = 5 along h at the free end, clamped root; meshes (length x height) 6x1, 12x2, 12x4,
// 24x8 with one element across the width. Beam theory Pl^3/(3EI) = 3.0857.
//
// The load is a uniform shear traction on the end face (consistent nodal loads), the set-up under
// which SPEC's CalculiX 2.20 table was measured; those values are the checkable truth. The
// thesis' own columns are printed beside ours: its load/support details are not recoverable
// (SPEC §2.1), so they are reported, not asserted, where they differ.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

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

double tip_deflection(const std::string& type, Mesh mesh) {
  mesher::CantileverSpec spec;
  spec.box.type = type;
  spec.box.size = {150.0, 2.5, 5.0};
  spec.box.divisions = {mesh.along, 1, mesh.through};
  spec.young = 70000.0;
  spec.poisson = 0.0;
  spec.load = mesher::CantileverSpec::Load::EndTraction;
  spec.force = {0.0, 0.0, 5.0};
  const Model model = mesher::make_cantilever(spec);
  return mean_displacement(model, solve(model), "TIP", 2);
}

TEST(Spec2_1, BeamTheoryValue) {
  // SPEC §2.1: u = Pl^3/(3EI) = 3.0857.
  EXPECT_NEAR(kBeamTheory, 3.0857, 5e-5);
}

TEST(Spec2_1, C3D8FullIntegrationLocks) {
  // Expected (SPEC §2.1, CalculiX 2.20, consistent traction): 0.2287 / 0.7485 / 0.7485 / 1.7334 mm,
  // tolerance 0.1 % (four digits). Thesis (own code, Tab 2.3): 0.2303 / 0.7501 / 0.7502 / 1.735.
  const double expected[4] = {0.2287, 0.7485, 0.7485, 1.7334};
  const double thesis[4] = {0.2303, 0.7501, 0.7502, 1.735};
  std::printf("SPEC 2.1 C3D8 full  | mesh | styk     | CalculiX | thesis  | styk/thesis\n");
  for (int m = 0; m < 4; ++m) {
    const double u = tip_deflection("C3D8", kMeshes[m]);
    std::printf("                    | %2dx%d | %.5f  | %.4f   | %.4f  | %+.2f %%\n",
                kMeshes[m].along, kMeshes[m].through, u, expected[m], thesis[m],
                100.0 * (u / thesis[m] - 1.0));
    EXPECT_NEAR(u, expected[m], 1e-3 * expected[m])
        << "mesh " << kMeshes[m].along << "x" << kMeshes[m].through;
    // The thesis' values sit 0.1-0.7 % above (SPEC §2.1); they must stay within 1 %.
    EXPECT_NEAR(u, thesis[m], 1e-2 * thesis[m]);
  }
}

TEST(Spec2_1, C3D20Converges) {
  // Expected normalised deflection (SPEC §2.1, CalculiX 2.20, consistent traction):
  // 0.996 / 1.000 / 1.000 / 1.001, tolerance 1 %. Thesis' Abaqus C3D20 (Tab 2.2): 0.944 / 1.000 /
  // 1.000 / 1.000 -- its 6x1 value is 5 % below the consistent-traction answer (different,
  // unrecoverable load details; SPEC §2.1) and is printed, not asserted.
  const double expected[4] = {0.996, 1.000, 1.000, 1.001};
  const double thesis[4] = {0.944, 1.000, 1.000, 1.000};
  std::printf("SPEC 2.1 C3D20 normalised | mesh | styk   | CalculiX | thesis Abaqus\n");
  for (int m = 0; m < 4; ++m) {
    const double normalised = tip_deflection("C3D20", kMeshes[m]) / kBeamTheory;
    std::printf("                          | %2dx%d | %.4f | %.3f    | %.3f\n", kMeshes[m].along,
                kMeshes[m].through, normalised, expected[m], thesis[m]);
    EXPECT_NEAR(normalised, expected[m], 1e-2 * expected[m]);
  }
}

}  // namespace
}  // namespace styk::verification
