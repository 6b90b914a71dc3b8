// `styk import` on the command line: a mesh deck written whole or not at all, every refusal a
// "file:line: message" with exit code 1, and the deck it writes read back by `styk solve` through
// *INCLUDE (docs/input.md, "Importing Gmsh meshes").
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace styk::testing {
namespace {

namespace fs = std::filesystem;

std::string fixture(const std::string& name) {
  return std::string(STYK_SOURCE_DIR) + "/tests/inputs/gmsh/" + name;
}

struct Refusal {
  std::string mesh;
  std::string options;
  int line;
  std::string message;
};

TEST(CliImport, RefusalsNameFileAndLineAndWriteNothing) {
  const std::string dir = scratch_dir("cli_import_refusals");
  std::ofstream(dir + "/binary.msh") << "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n";
  std::ofstream(dir + "/version3.msh") << "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n";
  std::ofstream(dir + "/missing_node.msh")
      << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"
         "$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n";
  std::ofstream(dir + "/short_nodes.msh")
      << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 0 x\n$EndNodes\n";
  const Refusal refusals[] = {
      {fixture("pyramid_v22.msh"), "", 15, "5-node pyramid"},
      {fixture("surface_v41.msh"), "", 67, "--planar"},
      {fixture("surface_v41.msh"), "--planar cax", 71, "9-node quadrangle"},
      {dir + "/binary.msh", "", 2, "binary"},
      {dir + "/version3.msh", "", 2, "version 3.0"},
      {dir + "/missing_node.msh", "", 10, "node 2"},
      {dir + "/short_nodes.msh", "", 7, "'x'"},
  };
  for (const Refusal& r : refusals) {
    const std::string out = dir + "/out.inp";
    const CommandResult result = run_command(
        styk_executable() + " import '" + r.mesh + "' " + r.options + " -o " + out, dir);
    SCOPED_TRACE(r.mesh + " " + r.options + "\nstderr: " + result.err);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find(r.mesh + ":" + std::to_string(r.line) + ": "), std::string::npos);
    EXPECT_NE(result.err.find(r.message), std::string::npos);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out + ".tmp"));
  }
}

// The hex20 fixture imported, completed by *INCLUDE with a material and a step and solved: a
// unit cube clamped on x = 0 (the physical surface "Fixed face") and pulled along x by a uniform
// pressure on x = 1 stretches by p / E there (nu = 0: the exact answer of the C3D20, 1e-9).
TEST(CliImport, ImportedDeckSolvesThroughInclude) {
  const std::string dir = scratch_dir("cli_import_solve");
  const CommandResult imported = run_command(
      styk_executable() + " import '" + fixture("hex20_v22.msh") + "' -o cube.inp", dir);
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(imported.out.find("1 elements (C3D20) from MSH 2.2"), std::string::npos)
      << imported.out;
  std::ofstream(dir + "/model.inp") << "*INCLUDE, INPUT=cube.inp\n"
                                       "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n"
                                       "*SOLID SECTION, ELSET=SOLID, MATERIAL=M\n"
                                       "*BOUNDARY\nFIXED_FACE, 1, 1\n1, 2, 3\n4, 3, 3\n2, 3, 3\n"
                                       "*STEP\n*STATIC\n*DLOAD\n2, P4, -10.\n"
                                       "*NODE PRINT, NSET=NALL\nU\n*END STEP\n";
  const CommandResult solved = run_command(styk_executable() + " solve -q model.inp", dir);
  ASSERT_EQ(solved.exit_code, 0) << solved.err;
  // Node 7 is the corner (1, 1, 1): u_x = p / E = 0.01.
  std::istringstream dat(read_file(dir + "/model.dat"));
  std::string line;
  bool found = false;
  while (std::getline(dat, line)) {
    std::istringstream fields(line);
    std::string id;
    double ux = 0.0;
    if (fields >> id >> ux && id == "7") {
      EXPECT_NEAR(ux, 0.01, 1e-9) << line;
      found = true;
    }
  }
  EXPECT_TRUE(found) << "node 7 not printed";
}

}  // namespace
}  // namespace styk::testing
