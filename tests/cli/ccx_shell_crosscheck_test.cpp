// Shells against CalculiX 2.20 (docs/elements.md, "Shells", CalculiX paragraph). The same deck —
// read by Styk, written back by Styk's .inp writer — is solved by `styk solve` and by `ccx`.
// ccx expands every shell into one layer of bricks through the thickness (S8R -> C3D20R,
// S4 -> C3D8I) and turns rotation conditions into rigid knots, so the two agree as far as one
// brick through a thin plate behaves like a Mindlin shell. Measured on SPEC §7.3's quarter plate
// (side 1, q = 10 as *DLOAD P, E = 10.92e5, nu = 0.3, t = 0.01, hard simple supports and symmetry
// with rotation conditions, 4 x 4 elements; Mindlin series 0.40645): Styk's S8R 0.406413 and
// ccx's 0.406347 (-0.016 %); Styk's S4 (MITC4) 0.404355 and ccx's S4 (one C3D8I layer) 0.298486,
// 26.18 % stiffer. The differences are asserted within 0.05 % of the measured ones (ccx is
// deterministic). Every deck written here runs in ccx.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "support/ccx_runner.hpp"
#include "support/element_registries.hpp"

namespace styk::testing {
namespace {

// Node `id`'s displacement from the last "displacements" block of a .dat report.
std::array<double, 3> displacement(const std::string& path, long wanted) {
  std::ifstream in(path);
  std::array<double, 3> found{};
  std::string line;
  bool reading = false;
  while (std::getline(in, line)) {
    if (line.rfind(" displacements (vx,vy,vz) for set", 0) == 0) {
      reading = true;
      std::getline(in, line);
      continue;
    }
    if (!reading) continue;
    std::istringstream fields(line);
    long id = 0;
    std::array<double, 3> u{};
    if (!(fields >> id >> u[0] >> u[1] >> u[2])) {
      reading = false;
      continue;
    }
    if (id == wanted) found = u;
  }
  return found;
}

// The quarter plate [0, 1/2]^2 of n x n `type` elements on a (order n + 1)^2 grid.
std::string plate_deck(const std::string& type, int n, long& centre) {
  const int p = type[1] == '4' ? 1 : 2, side = p * n + 1;
  const auto id = [&](int i, int j) { return j * side + i + 1; };
  std::ostringstream out;
  out.precision(17);
  out << "*NODE, NSET=NALL\n";
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      if (!(p == 2 && i % 2 == 1 && j % 2 == 1))
        out << id(i, j) << ", " << 0.5 * i / (side - 1) << ", " << 0.5 * j / (side - 1) << ", 0\n";
  out << "*ELEMENT, TYPE=" << type << ", ELSET=PLATE\n";
  int e = 1;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const int I = p * a, J = p * b;
      out << e++ << ", " << id(I, J) << ", " << id(I + p, J) << ", " << id(I + p, J + p) << ", "
          << id(I, J + p);
      if (p == 2)
        out << ", " << id(I + 1, J) << ", " << id(I + 2, J + 1) << ", " << id(I + 1, J + 2) << ", "
            << id(I, J + 1);
      out << "\n";
    }
  out << "*MATERIAL, NAME=M\n*ELASTIC\n1092000., 0.3\n*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n"
      << "0.01\n*BOUNDARY\n";
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      if (p == 2 && i % 2 == 1 && j % 2 == 1) continue;
      const auto fix = [&](int dof) { out << id(i, j) << ", " << dof << ", " << dof << "\n"; };
      if (i == 0) fix(3), fix(4);
      if (j == 0) fix(3), fix(5);
      if (i == side - 1) fix(1), fix(5), fix(6);
      if (j == side - 1) fix(2), fix(4), fix(6);
    }
  out << "*STEP\n*STATIC\n*DLOAD\nPLATE, P, 10.\n*NODE PRINT, NSET=NALL\nU\n*END STEP\n";
  centre = id(side - 1, side - 1);
  return out.str();
}

// The Scordelis-Lo roof's quarter (R = 25, length 50, 80 degree arc, t = 0.25, E = 4.32e8,
// nu = 0, weight 90 per unit area as GRAV with density 360) of n x n S8R: x = 25 s from mid-span,
// the angle 40 r degrees from the crown. With `normals`, a *NORMAL line per node gives the radius
// there. `edge` receives the free edge's mid-span node (reference deflection 0.3024 down).
std::string roof_deck(int n, bool normals, long& edge) {
  const int side = 2 * n + 1;
  const double pi = 3.14159265358979323846;
  const auto id = [&](int i, int j) { return j * side + i + 1; };
  const auto kept = [](int i, int j) { return !(i % 2 == 1 && j % 2 == 1); };
  std::ostringstream out;
  out.precision(17);
  out << "*NODE, NSET=NALL\n";
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const double phi = 40.0 * pi / 180.0 * j / (side - 1);
      if (kept(i, j))
        out << id(i, j) << ", " << 25.0 * i / (side - 1) << ", " << 25.0 * std::sin(phi) << ", "
            << 25.0 * std::cos(phi) << "\n";
    }
  out << "*ELEMENT, TYPE=S8R, ELSET=ROOF\n";
  int e = 1;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const int I = 2 * a, J = 2 * b;
      out << e++ << ", " << id(I, J) << ", " << id(I + 2, J) << ", " << id(I + 2, J + 2) << ", "
          << id(I, J + 2) << ", " << id(I + 1, J) << ", " << id(I + 2, J + 1) << ", "
          << id(I + 1, J + 2) << ", " << id(I, J + 1) << "\n";
    }
  out << "*MATERIAL, NAME=M\n*ELASTIC\n4.32e8, 0.\n*DENSITY\n360.\n"
      << "*SHELL SECTION, ELSET=ROOF, MATERIAL=M\n0.25\n";
  if (normals) {
    out << "*NORMAL\n";
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const double phi = 40.0 * pi / 180.0 * j / (side - 1);
        if (kept(i, j))
          out << "ROOF, " << id(i, j) << ", 0., " << std::sin(phi) << ", " << std::cos(phi) << "\n";
      }
  }
  out << "*BOUNDARY\n";
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      if (!kept(i, j)) continue;
      const auto fix = [&](int dof) { out << id(i, j) << ", " << dof << ", " << dof << "\n"; };
      if (i == 0) fix(1), fix(5), fix(6);  // mid-span symmetry
      if (j == 0) fix(2), fix(4), fix(6);  // crown symmetry
      if (i == side - 1) fix(2), fix(3);   // diaphragm
    }
  out << "*STEP\n*STATIC\n*DLOAD\nROOF, GRAV, 1., 0., 0., -1.\n*NODE PRINT, NSET=NALL\nU\n"
      << "*END STEP\n";
  edge = id(0, side - 1);
  return out.str();
}

// Node `node`'s displacement by Styk and by ccx, the deck being written by Styk's writer.
std::pair<std::array<double, 3>, std::array<double, 3>> solve_deck_both(const std::string& job,
                                                                        const std::string& deck,
                                                                        long node) {
  const std::string dir = scratch_dir("ccx_shell_" + job);
  {
    std::ofstream(dir + "/given.inp") << deck;
    ElementRegistry registry = test::builtin_registry();
    const Model model = read_inp(dir + "/given.inp", registry);
    std::ofstream written(dir + "/" + job + ".inp");
    write_inp(model, written);
  }
  const CommandResult ours =
      run_command(styk_executable() + " solve -q " + job + ".inp -o styk", dir);
  EXPECT_EQ(ours.exit_code, 0) << ours.err;
  const test::CcxRun peer = test::run_ccx(dir, job);
  EXPECT_EQ(peer.exit_code, 0) << "ccx failed on the deck Styk wrote\n" << peer.log;
  return {displacement(dir + "/styk/" + job + ".dat", node),
          displacement(dir + "/" + job + ".dat", node)};
}

// The centre deflection by Styk and by ccx.
std::pair<double, double> solve_both(const std::string& type, int n) {
  long centre = 0;
  const std::string deck = plate_deck(type, n, centre);
  const auto [styk, ccx] = solve_deck_both("plate_" + type, deck, centre);
  return {styk[2], ccx[2]};
}

TEST(CcxShellCrossCheck, PlateUnderPressure) {
  const struct {
    const char* type;
    double difference;  // ccx / Styk - 1, measured
  } cases[] = {{"S8R", -0.000161}, {"S4", -0.261823}};
  for (const auto& c : cases) {
    const auto [styk, ccx] = solve_both(c.type, 4);
    std::printf("%s: Styk %.6g, ccx %.6g, ccx / Styk - 1 = %.4f %%\n", c.type, styk, ccx,
                100.0 * (ccx / styk - 1.0));
    EXPECT_GT(styk, 0.0) << "P pushes along the normal (+z) in both";
    EXPECT_NEAR(ccx / styk - 1.0, c.difference, 0.0005) << c.type;
  }
}

// *NORMAL in a deck Styk writes runs in ccx: the roof with the radius given at every node and
// without. Styk: 0.303314 / 0.303313 (the S8R's own normals on the exact cylinder already average
// to the radius), +0.3 % of 0.3024. ccx's value is not compared: its shell expansion turns the
// rotation conditions of the symmetry edges into rigid knots, measured 0.0468 with them and
// 0.409 without them (symmetry then lost), so this roof is no peer check for ccx's shells.
TEST(CcxShellCrossCheck, ScordelisLoRoofWithNormalsRunsInCcx) {
  double with_normals = 0.0;
  for (const bool normals : {true, false}) {
    long edge = 0;
    const std::string deck = roof_deck(4, normals, edge);
    const auto [styk, ccx] = solve_deck_both(normals ? "roof_normals" : "roof", deck, edge);
    std::printf("roof %s: Styk %.6g, ccx %.6g\n", normals ? "given normals" : "averaged normals",
                -styk[2], -ccx[2]);
    EXPECT_LE(std::abs(-styk[2] / 0.3024 - 1.0), 0.004);
    if (normals) {
      with_normals = styk[2];
    } else {
      EXPECT_NEAR(styk[2], with_normals, 1e-5 * std::abs(with_normals));
    }
  }
}

// `styk render` draws shells (docs/render.md "Shells"): the mesh of a deck of shells only, and
// the results on a chosen fibre; an unknown fibre is refused by name, nothing written.
TEST(ShellCli, RenderDrawsAModelOfShellsOnly) {
  const std::string dir = scratch_dir("shell_render");
  long centre = 0;
  std::ofstream(dir + "/plate.inp") << plate_deck("S8R", 2, centre);
  const CommandResult mesh = run_command(styk_executable() + " render plate.inp -o mesh.png", dir);
  EXPECT_EQ(mesh.exit_code, 0) << mesh.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/mesh.png"));
  const CommandResult solve = run_command(styk_executable() + " solve plate.inp", dir);
  ASSERT_EQ(solve.exit_code, 0) << solve.err;
  const CommandResult bottom = run_command(
      styk_executable() + " render plate.styk.h5 --field S.mises --fibre bottom -o bottom.png",
      dir);
  EXPECT_EQ(bottom.exit_code, 0) << bottom.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/bottom.png"));
  const CommandResult bad = run_command(
      styk_executable() + " render plate.styk.h5 --field S.mises --fibre side -o side.png", dir);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("unknown shell fibre 'side'; use bottom, middle or top"),
            std::string::npos)
      << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/side.png"));
}

}  // namespace
}  // namespace styk::testing
