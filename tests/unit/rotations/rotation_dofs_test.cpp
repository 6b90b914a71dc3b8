// The rotational-dof layer (docs/solver.md, "Degrees of freedom"): nodes carry the dofs their
// elements need, *BOUNDARY and *CLOAD act on rotations 4-6, UR and RM reach the results, the .dat
// report, the HDF5 file and VTU, *TRANSFORM turns rotations like displacements, *EQUATION ties
// rotations, and the rigid-body check sees a beam spinning about its own axis. The elements are
// EBF2 of a test plug-in (plugin/ebframe.cpp): exact Euler-Bernoulli frames, so every expected
// value is a closed form of beam theory and the tolerance is round-off (1e-9 relative).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../../support/test_scratch.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/dat_writer.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/vtu_export.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

// E = 1000, nu = 0.25 (G = 400), A = 0.12: I = A^2 / 12 = 0.0012, J = 2 I = 0.0024.
constexpr double kE = 1000.0, kG = 400.0, kI = 0.0012, kJ = 0.0024, kL = 2.0;

struct Loaded {
  PluginLibraries libraries;
  ElementRegistry registry;
};

std::unique_ptr<Loaded> registry_with_frame() {
  auto loaded = std::make_unique<Loaded>();
  const auto diagnostics =
      setup_element_registry(loaded->registry, loaded->libraries, {STYK_ROTATION_PLUGIN_DIR});
  for (const PluginDiagnostic& d : diagnostics) ADD_FAILURE() << d.message;
  return loaded;
}

std::filesystem::path scratch(const std::string& name) {
  return test::test_scratch_dir("tests/rotation_decks") / name;
}

Model parse(const Loaded& loaded, const std::string& name, const std::string& deck) {
  const std::filesystem::path path = scratch(name);
  std::ofstream(path) << deck;
  return read_inp(path.string(), loaded.registry);
}

// A cantilever of 4 EBF2 elements along x from node 1 (x = 0) to node 5 (x = L), clamped at node
// 1 in all six dofs unless `support` says otherwise; `step` holds the step's loads.
std::string cantilever(const std::string& step, const std::string& support = "1, 1, 6\n",
                       const std::string& extra = "") {
  std::ostringstream deck;
  deck << "*NODE, NSET=NALL\n";
  for (int i = 0; i <= 4; ++i) deck << i + 1 << ", " << 0.5 * i << ", 0, 0\n";
  deck << "*NSET, NSET=TIP\n5\n"
          "*ELEMENT, TYPE=EBF2, ELSET=FRAME\n1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 4, 5\n"
          "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.25\n"
          "*SOLID SECTION, ELSET=FRAME, MATERIAL=M\n0.12\n"
       << extra << "*BOUNDARY\n"
       << support << "*STEP\n*STATIC\n"
       << step << "*END STEP\n";
  return deck.str();
}

Results solve(const Loaded& loaded, const Model& model, AnalysisReport* report = nullptr) {
  return run_static_analysis(model, loaded.registry, SolveOptions{}, nullptr, report);
}

void expect_relative(double actual, double expected, const char* what) {
  EXPECT_NEAR(actual, expected, 1e-9 * std::abs(expected)) << what;
}

// Tip force P along y: w = P L^3 / (3 E I), slope rz = P L^2 / (2 E I); the clamp reacts with
// RF_y = -P and RM_z = -P L.
TEST(RotationDofs, TipForceGivesBeamDeflectionSlopeAndMomentReaction) {
  const auto loaded = registry_with_frame();
  const Model model = parse(*loaded, "tip_force.inp", cantilever("*CLOAD\n5, 2, 0.5\n"));
  const Results results = solve(*loaded, model);
  const IncrementResult& inc = results.increments.at(0);
  const int tip = model.node_index(5), root = model.node_index(1);
  ASSERT_EQ(inc.UR.size(), model.coords.size());
  ASSERT_EQ(inc.RM.size(), model.coords.size());
  expect_relative(inc.U[tip][1], 0.5 * kL * kL * kL / (3.0 * kE * kI), "tip uy");
  expect_relative(inc.UR[tip][2], 0.5 * kL * kL / (2.0 * kE * kI), "tip rz");
  expect_relative(inc.RF[root][1], -0.5, "root RF_y");
  expect_relative(inc.RM[root][2], -0.5 * kL, "root RM_z");
  EXPECT_NEAR(inc.RM[tip][2], 0.0, 1e-12);  // no rotation prescribed at the tip
}

// Torque T about x (dof 4): twist T L / (G J), reaction -T.
TEST(RotationDofs, TorqueOnDofFourTwistsTheFrame) {
  const auto loaded = registry_with_frame();
  const Model model = parse(*loaded, "torque.inp", cantilever("*CLOAD\nTIP, 4, 0.3\n"));
  const Results results = solve(*loaded, model);
  const IncrementResult& inc = results.increments.at(0);
  expect_relative(inc.UR[model.node_index(5)][0], 0.3 * kL / (kG * kJ), "tip rx");
  expect_relative(inc.RM[model.node_index(1)][0], -0.3, "root RM_x");
}

// A prescribed tip rotation rz = 0.01 (translations free): constant moment M = E I theta / L, tip
// deflection theta L / 2, and the tip reports the moment it takes as RM_z = +M.
TEST(RotationDofs, PrescribedRotationReportsItsMoment) {
  const auto loaded = registry_with_frame();
  const Model model = parse(*loaded, "rotation_bc.inp", cantilever("*BOUNDARY\n5, 6, 6, 0.01\n"));
  const Results results = solve(*loaded, model);
  const IncrementResult& inc = results.increments.at(0);
  const double M = kE * kI * 0.01 / kL;
  expect_relative(inc.UR[model.node_index(5)][2], 0.01, "tip rz");
  expect_relative(inc.U[model.node_index(5)][1], 0.01 * kL / 2.0, "tip uy");
  expect_relative(inc.RM[model.node_index(5)][2], M, "tip RM_z");
  expect_relative(inc.RM[model.node_index(1)][2], -M, "root RM_z");
}

// *TRANSFORM: rotations turn with the nodal system like displacements. Local x = global y,
// local y = global z, so local z = global x: a local moment on dof 6 is a global torque.
TEST(RotationDofs, TransformTurnsRotationsLikeDisplacements) {
  const auto loaded = registry_with_frame();
  const Model model =
      parse(*loaded, "transform.inp",
            cantilever("*CLOAD\nTIP, 6, 0.3\n*NODE PRINT, NSET=TIP\nUR\n", "1, 1, 6\n",
                       "*TRANSFORM, NSET=TIP, TYPE=R\n0., 1., 0., 0., 0., 1.\n"));
  const Results results = solve(*loaded, model);
  const IncrementResult& inc = results.increments.at(0);
  const double twist = 0.3 * kL / (kG * kJ);
  expect_relative(inc.UR[model.node_index(5)][0], twist, "tip rx (global)");
  EXPECT_NEAR(inc.UR[model.node_index(5)][2], 0.0, 1e-12);
  // The .dat report shows the rotation in the node's local system (local z), marked " L".
  std::ostringstream dat;
  write_dat(dat, model, results);
  EXPECT_NE(dat.str().find(" rotations (rx,ry,rz) for set TIP"), std::string::npos) << dat.str();
  EXPECT_NE(dat.str().find("         5  0.000000E+00  0.000000E+00  6.250000E-01 L"),
            std::string::npos)
      << dat.str();
}

// *EQUATION on rotations: two cantilevers with their tip rotations rz tied; a tip moment on one
// rotates both by M L / (2 E I).
TEST(RotationDofs, EquationTiesRotations) {
  const auto loaded = registry_with_frame();
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 2, 0, 0\n11, 0, 1, 0\n12, 2, 1, 0\n"
      "*ELEMENT, TYPE=EBF2, ELSET=FRAME\n1, 1, 2\n2, 11, 12\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.25\n"
      "*SOLID SECTION, ELSET=FRAME, MATERIAL=M\n0.12\n"
      "*EQUATION\n2\n2, 6, 1., 12, 6, -1.\n"
      "*BOUNDARY\n1, 1, 6\n11, 1, 6\n"
      "*STEP\n*STATIC\n*CLOAD\n2, 6, 0.2\n*END STEP\n";
  const Model model = parse(*loaded, "equation.inp", deck);
  const Results results = solve(*loaded, model);
  const IncrementResult& inc = results.increments.at(0);
  const double theta = 0.2 * kL / (2.0 * kE * kI);
  expect_relative(inc.UR[model.node_index(2)][2], theta, "rz of the loaded tip");
  expect_relative(inc.UR[model.node_index(12)][2], theta, "rz of the tied tip");
}

// A frame held at both ends in translation only can spin about its own axis: the rigid-body check
// names the rotation and the remedy; holding one rotation about the axis cures it.
TEST(RotationDofs, SpinAboutTheAxisIsAMechanism) {
  const auto loaded = registry_with_frame();
  const Model loose =
      parse(*loaded, "spin.inp", cantilever("*CLOAD\n3, 2, 1.\n", "1, 1, 3\n5, 2, 3\n"));
  try {
    solve(*loaded, loose);
    FAIL() << "a free spin about the frame axis was not detected";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("rotate freely"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("along (1, 0, 0)"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("or a rotation (dofs 4-6) about it"), std::string::npos)
        << e.message();
  }
  const Model held =
      parse(*loaded, "spin_held.inp", cantilever("*CLOAD\n3, 2, 1.\n", "1, 1, 4\n5, 2, 3\n"));
  const Results results = solve(*loaded, held);
  const IncrementResult& inc = results.increments.at(0);
  // Simply supported span 2, central load 1: w = P L^3 / (48 E I).
  expect_relative(inc.U[held.node_index(3)][1], kL * kL * kL / (48.0 * kE * kI), "mid-span uy");
}

// A frame standing on a C3D8 cube: the shared corner carries 6 dofs, the other cube nodes 3. A
// frame attached to a solid at one node is a hinge there (the solid resists no rotation): the
// factorisation names the free rotation; holding the corner's rotations cures it. Free dofs then:
// 4 free cube nodes x 3 + 6 at the frame's far node = 18 (the corner's rotations are held).
TEST(RotationDofs, NodesCarryOnlyTheDofsTheirElementsNeed) {
  const auto loaded = registry_with_frame();
  const std::string mesh =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
      "5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n8, 0, 1, 1\n9, 0, 0, 3\n"
      "*NSET, NSET=BASE\n1, 2, 3, 4\n"
      "*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
      "*ELEMENT, TYPE=EBF2, ELSET=FRAME\n2, 5, 9\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.25\n"
      "*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n"
      "*SOLID SECTION, ELSET=FRAME, MATERIAL=M\n0.12\n"
      "*BOUNDARY\nBASE, 1, 3\n";
  const std::string step = "*STEP\n*STATIC\n*CLOAD\n9, 1, 0.01\n9, 5, 0.001\n*END STEP\n";
  try {
    solve(*loaded, parse(*loaded, "hinge.inp", mesh + step));
    FAIL() << "a frame hinged on a solid node was solved";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("singular at node 5 (r"), std::string::npos) << e.message();
  }
  const Model model = parse(*loaded, "mixed.inp", mesh + "5, 4, 6\n" + step);
  AnalysisReport report;
  const Results results = solve(*loaded, model, &report);
  const IncrementResult& inc = results.increments.at(0);
  EXPECT_EQ(report.dofs, 18);
  EXPECT_NE(inc.UR[model.node_index(9)][1], 0.0);  // the frame's free end turns
  for (int id : {5, 6, 7, 8}) EXPECT_EQ(inc.UR[model.node_index(id)], (Vec3{0.0, 0.0, 0.0}));
  EXPECT_GT(inc.U[model.node_index(5)][0], 0.0);  // the cube corner moves with the frame's load
}

// Rotations at a node whose elements have none: an error at the boundary line, naming the node.
TEST(RotationDofs, RotationOnASolidNodeIsRefusedAtItsLine) {
  const auto loaded = registry_with_frame();
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
      "5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n8, 0, 1, 1\n"
      "*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.25\n"
      "*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n"
      "*BOUNDARY\n1, 1, 3\n2, 2, 3\n4, 3, 3\n"
      "*STEP\n*STATIC\n*BOUNDARY\n7, 5, 5, 0.1\n*END STEP\n";
  const Model model = parse(*loaded, "solid_rotation.inp", deck);
  try {
    solve(*loaded, model);
    FAIL() << "a rotation on a solid node was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 23);
    EXPECT_NE(e.message().find("degree of freedom 5 of node 7, which carries no rotations"),
              std::string::npos)
        << e.message();
  }
}

// UR and RM in the HDF5 file (read back exactly), the .dat report (ccx layout, TOTALS for the
// moments) and the VTU point data.
TEST(RotationDofs, RotationsAndMomentsReachEveryOutput) {
  const auto loaded = registry_with_frame();
  const Model model =
      parse(*loaded, "outputs.inp",
            cantilever("*CLOAD\n5, 2, 0.5\n*NODE PRINT, NSET=NALL, TOTALS=YES\nU, UR, RF, RM\n"));
  const Results results = solve(*loaded, model);
  const std::filesystem::path h5 = scratch("outputs.styk.h5");
  write_results_file(h5.string(), model, results);
  const ResultsFileContents back = read_results_file(h5.string());
  ASSERT_EQ(back.results.increments.size(), 1u);
  EXPECT_EQ(back.results.increments[0].UR, results.increments[0].UR);
  EXPECT_EQ(back.results.increments[0].RM, results.increments[0].RM);

  std::ostringstream dat;
  write_dat(dat, model, results);
  const std::string text = dat.str();
  EXPECT_NE(text.find(" rotations (rx,ry,rz) for set NALL"), std::string::npos);
  EXPECT_NE(text.find(" moments (mx,my,mz) for set NALL"), std::string::npos);
  EXPECT_NE(text.find(" total moment (mx,my,mz) for set NALL"), std::string::npos);
  // Tip slope P L^2 / (2 E I) = 0.8333..., root moment -P L = -1.
  EXPECT_NE(text.find("         5  0.000000E+00  0.000000E+00  8.333333E-01"), std::string::npos)
      << text;
  EXPECT_NE(text.find("         1  0.000000E+00  0.000000E+00 -1.000000E+00"), std::string::npos)
      << text;

  const std::filesystem::path vtu = scratch("outputs.vtu");
  write_vtu(vtu.string(), model, loaded->registry, &results.increments[0]);
  std::ifstream in(vtu);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(xml.find("Name=\"UR\""), std::string::npos);
  EXPECT_NE(xml.find("Name=\"RM\""), std::string::npos);
}

// Asking for UR of a model without rotations: an error at the output request, before solving.
TEST(RotationDofs, RotationOutputOfASolidModelIsRefused) {
  const auto loaded = registry_with_frame();
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
      "5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n8, 0, 1, 1\n"
      "*ELEMENT, TYPE=C3D8, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.25\n"
      "*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n"
      "*BOUNDARY\n1, 1, 3\n2, 2, 3\n4, 3, 3\n"
      "*STEP\n*STATIC\n*CLOAD\n7, 3, 1.\n*NODE PRINT\nU, UR\n*END STEP\n";
  const Model model = parse(*loaded, "solid_ur.inp", deck);
  try {
    solve(*loaded, model);
    FAIL() << "UR of a solid model was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 24);
    EXPECT_NE(e.message().find("output variable UR needs nodes with rotations"), std::string::npos)
        << e.message();
  }
}

// The iterative solver's multigrid assumes 3 displacements per node: refused by name.
TEST(RotationDofs, IterativeSolverRefusesRotations) {
  const auto loaded = registry_with_frame();
  const Model model = parse(*loaded, "iterative.inp", cantilever("*CLOAD\n5, 2, 0.5\n"));
  SolveOptions options;
  options.force = LinearSolverKind::Iterative;
  try {
    run_static_analysis(model, loaded->registry, options, nullptr, nullptr);
    FAIL() << "the iterative solver accepted rotational dofs";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("does not support rotational dofs"), std::string::npos)
        << e.message();
  }
}

}  // namespace
}  // namespace styk
