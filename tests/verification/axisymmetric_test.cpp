// Axisymmetric elements (CAX4, CAX4R, CAX8, CAX8R) against analytic values and CalculiX:
// - SPEC §3.1.7 thick-walled cylinder (Lamé): R1 = 3, R2 = 9, E = 1000, unit internal pressure,
//   plane strain (u_z = 0 everywhere, which makes the ring exactly the plane-strain cylinder), 5
//   radial elements graded 4:1, 1 axial; u(R1) = (1+nu) p R1^2 / (E (R2^2 - R1^2)) [R2^2/R1 +
//   (1-2nu) R1];
// - the same deck in CalculiX 2.20 (which expands each ring element into a 2 degree segment of
//   3D elements and scales the loads back to the circumference);
// - SPEC §4.2 shrink fit as an axisymmetric model: the shaft (r 0..10, z 0..60) heated by 100 with
//   alpha = 2e-5 inside the sleeve (r 10..15, z 20..40), frictionless contact; the contact
//   pressure at mid-length against the Lamé hand values of SPEC (111 plane stress, 122 plane
//   strain) and against the 3D model of spec_4_2_shrink_fit_test (111.1).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "axisymmetric_decks.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/solver/analysis.hpp"
#include "support/ccx_runner.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(STYK_BINARY_DIR) / "tests" / "verification" / "axisymmetric" / name;
  std::filesystem::create_directories(dir);
  return dir;
}

// CalculiX on the deck (in its directory): the last displacement block of job.dat, by node id.
std::map<Id, Vec3> ccx_displacements(const std::filesystem::path& dir) {
  if (test::run_ccx(dir, "job").exit_code != 0)
    throw std::runtime_error("ccx failed in " + dir.string());
  std::ifstream dat(dir / "job.dat");
  const std::vector<DatDisplacements> blocks = parse_dat_displacements(dat);
  if (blocks.empty()) throw std::runtime_error("no displacements in job.dat");
  return blocks.back().u;
}

double lame_u1(double nu) {
  const double E = 1000, p = 1, R1 = 3, R2 = 9;
  return (1 + nu) * p * R1 * R1 / (E * (R2 * R2 - R1 * R1)) * (R2 * R2 / R1 + (1 - 2 * nu) * R1);
}

// The SPEC §3.1.7 ring as a deck; INNER holds the nodes at r = R1.
std::string lame_deck(const std::string& type, double nu) {
  test::AxiMesh mesh(type);
  const std::vector<int> elements = mesh.rectangle("WALL", 3.0, 9.0, 5, 0.0, 1.0, 1, 4.0);
  const std::vector<int> inner = mesh.nodes_where([](double r, double) { return r < 3 + 1e-9; });
  std::ostringstream deck;
  deck << "*HEADING\nSPEC 3.1.7 thick cylinder, " << type << ", nu = " << nu << "\n"
       << mesh.mesh_text() << "*NSET, NSET=INNER\n"
       << test::id_lines(inner) << "*MATERIAL, NAME=M\n*ELASTIC\n1000., " << nu << "\n"
       << "*SOLID SECTION, ELSET=WALL, MATERIAL=M\n"
       << "*BOUNDARY\nNALL, 2, 2\n*STEP\n*STATIC\n*DLOAD\n";
  for (const auto& [e, face] :
       mesh.faces_where(elements, [](double r, double) { return r < 3 + 1e-9; }))
    deck << e << ", P" << face << ", 1.\n";
  deck << "*NODE PRINT, NSET=INNER\nU\n*END STEP\n";
  return deck.str();
}

double mean_ur(const std::map<Id, Vec3>& u) {
  double sum = 0.0;
  for (const auto& [id, v] : u) sum += v[0];
  return sum / u.size();
}

std::map<Id, Vec3> inner_displacements(const Model& model, const Results& results) {
  std::map<Id, Vec3> out;
  for (int n : model.find_nset("INNER")->nodes)
    out[model.node_ids[n]] = results.increments.back().U[n];
  return out;
}

// SPEC §3.1.7 (thesis Tab 3.11; the thesis' CPE8 column -0.03 % / -0.26 % / -2.5 %): CAX8 and
// CAX8R against the Lamé value. Measured here (asserted to 2 % of the value, or 1e-6 absolute
// where it is below that): CAX8 -0.0086 % (nu 0.3), -0.130 % (0.49), -1.267 % (0.499), -11.36 %
// (0.4999: volumetric locking of the 3x3 rule, as CPE8, docs/elements.md); CAX8R (2x2) within
// 1e-6 of the formula at every nu: the reduced rule does not lock.
TEST(AxisymmetricLame, ThickCylinderMatchesTheFormula) {
  struct Case {
    const char* type;
    double nu;
    double error;  // measured relative error of u(R1)
  };
  const Case cases[] = {{"CAX8", 0.3, -8.6e-5},      {"CAX8", 0.49, -1.302e-3},
                        {"CAX8", 0.499, -1.2673e-2}, {"CAX8", 0.4999, -0.113593},
                        {"CAX8R", 0.3, 0.0},         {"CAX8R", 0.49, 0.0},
                        {"CAX8R", 0.499, 0.0},       {"CAX8R", 0.4999, 0.0}};
  for (const Case& c : cases) {
    const std::filesystem::path dir = scratch(std::string("lame_") + c.type);
    { std::ofstream(dir / "job.inp") << lame_deck(c.type, c.nu); }
    const Model model = read_inp((dir / "job.inp").string(), test::shared_builtin_registry());
    const Results results = run_static_analysis(model, test::shared_builtin_registry(),
                                                SolveOptions{}, nullptr, nullptr);
    const double u = mean_ur(inner_displacements(model, results));
    const double error = u / lame_u1(c.nu) - 1.0;
    std::printf("%s nu = %g: u(R1) = %.7e, Lame %.7e, error %+.4f %%\n", c.type, c.nu, u,
                lame_u1(c.nu), 100 * error);
    EXPECT_NEAR(error, c.error, std::max(0.02 * std::abs(c.error), 1e-6)) << c.type << " " << c.nu;
  }
}

// The same decks in CalculiX 2.20: its expansion into a 2 degree segment of 3D elements (C3D20
// for CAX8, C3D20R for CAX8R) places the sector's nodes on chords of the circles, so the ring's
// volume is short by (1 - sin(theta)/theta) ~ theta^2/6 = 5e-5 of ours (theta = 1 degree each
// side): the formulations agree to that order, not to 1e-6. Measured: the nodal displacements of
// INNER differ by 1.52e-4 (CAX8, CAX8R) and 2.49e-4 (CAX4) relative, three to five times that
// chord estimate; the rest of the difference is not traced. Asserted: those values to 2 %.
TEST(AxisymmetricLame, CalculixOnTheSameDeck) {
  const std::map<std::string, double> measured = {
      {"CAX8", 1.523e-4}, {"CAX8R", 1.523e-4}, {"CAX4", 2.487e-4}};
  for (const char* type : {"CAX8", "CAX8R", "CAX4"}) {
    const std::filesystem::path dir = scratch(std::string("lame_ccx_") + type);
    { std::ofstream(dir / "job.inp") << lame_deck(type, 0.3); }
    const Model model = read_inp((dir / "job.inp").string(), test::shared_builtin_registry());
    const Results results = run_static_analysis(model, test::shared_builtin_registry(),
                                                SolveOptions{}, nullptr, nullptr);
    const std::map<Id, Vec3> ours = inner_displacements(model, results);
    const std::map<Id, Vec3> theirs = ccx_displacements(dir);
    double worst = 0.0;
    for (const auto& [id, u] : ours) worst = std::max(worst, std::abs(u[0] / theirs.at(id)[0] - 1));
    std::printf("%s: largest relative difference of u_r at R1 against ccx %.3e\n", type, worst);
    EXPECT_NEAR(worst, measured.at(type), 0.02 * measured.at(type)) << type;
  }
}

// SPEC §4.2 shrink fit, axisymmetric. Shaft: r 0..10 in 5 elements, z 0..20 / 20..40 / 40..60 in
// 4 / 8 / 4 (graded towards the sleeve); sleeve: r 10..15 in 3, z 20..40 in 8, its nodes on the
// bore coinciding with the shaft's. Steel E = 2e5, nu = 0.3; the shaft heated by 100 with
// alpha = 2e-5 (free diametral growth 0.04, the interference); frictionless node-to-surface
// contact, sleeve bore slave; u_z = 0 at z = 0, u_r = 0 on the axis, one sleeve node held axially
// (determinate). The contact pressure at mid-length (mean over 25 <= z <= 35) lies between the
// Lamé hand values of SPEC (111 MPa plane stress, 122 plane strain) and, the 3D quarter model of
// spec_4_2_shrink_fit_test being the same physics, within 1 % of its 111.1; measured 110.82.
// Both edges carry more (the peaks of SPEC §4.2). The 2D model has 378 nodes (756 unknowns): the
// cheapest model of the scene (docs/verification.md, "Axisymmetric elements").
TEST(AxisymmetricShrinkFit, ContactPressureOfTheHeatedShaft) {
  test::AxiMesh mesh("CAX8");
  mesh.rectangle("SHAFT", 0.0, 10.0, 5, 0.0, 20.0, 4, 1.0, 1.0 / 3.0);
  const std::vector<int> fit = mesh.rectangle("SHAFT", 0.0, 10.0, 5, 20.0, 40.0, 8);
  mesh.rectangle("SHAFT", 0.0, 10.0, 5, 40.0, 60.0, 4, 1.0, 3.0);
  const std::vector<int> sleeve =
      mesh.rectangle("SLEEVE", 10.0, 15.0, 3, 20.0, 40.0, 8, 1.0, 1.0, /*body=*/1);
  const auto on_bore = [](double r, double z) {
    return std::abs(r - 10) < 1e-9 && z > 20 - 1e-9 && z < 40 + 1e-9;
  };
  const auto nodes = [&](auto inside, int body) {
    return test::id_lines(mesh.nodes_where(inside, body));
  };
  std::ostringstream deck;
  deck << "*HEADING\nSPEC 4.2 shrink fit, axisymmetric CAX8, shaft heated by 100\n"
       << mesh.mesh_text() << "*NSET, NSET=SHAFTN\n"
       << nodes([](double, double) { return true; }, 0) << "*NSET, NSET=AXIS\n"
       << nodes([](double r, double) { return r < 1e-9; }, 0) << "*NSET, NSET=BOTTOM\n"
       << nodes([](double, double z) { return z < 1e-9; }, 0) << "*NSET, NSET=HOLD\n"
       << nodes(
              [](double r, double z) { return std::abs(r - 15) < 1e-9 && std::abs(z - 30) < 1e-9; },
              1)
       << "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.e5, 0.3\n*EXPANSION\n2.e-5\n"
       << "*SOLID SECTION, ELSET=SHAFT, MATERIAL=STEEL\n*SOLID SECTION, ELSET=SLEEVE, "
          "MATERIAL=STEEL\n"
       << "*SURFACE, NAME=BORE, TYPE=ELEMENT\n";
  for (const auto& [e, face] : mesh.faces_where(sleeve, on_bore))
    deck << e << ", S" << face << "\n";
  deck << "*SURFACE, NAME=FIT, TYPE=ELEMENT\n";
  for (const auto& [e, face] : mesh.faces_where(fit, on_bore)) deck << e << ", S" << face << "\n";
  deck << "*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n"
       << "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE\nBORE, FIT\n"
       << "*BOUNDARY\nAXIS, 1, 1\nBOTTOM, 2, 2\nHOLD, 2, 2\n"
       << "*STEP\n*STATIC\n*TEMPERATURE\nSHAFTN, 100.\n*END STEP\n";
  const std::filesystem::path dir = scratch("shrink_fit");
  { std::ofstream(dir / "job.inp") << deck.str(); }
  const Model model = read_inp((dir / "job.inp").string(), test::shared_builtin_registry());
  EXPECT_EQ(model.node_count(), 378);
  const Results results =
      run_static_analysis(model, test::shared_builtin_registry(), SolveOptions{}, nullptr, nullptr);
  const IncrementResult& r = results.increments.back();
  ASSERT_FALSE(r.contact.empty());
  std::map<double, double> by_height;
  for (const ContactNodeResult& c : r.contact) {
    EXPECT_NE(c.status, ContactStatus::Open) << "node " << model.node_ids[c.node];
    by_height[std::round(model.coords[c.node][1] * 1e6) / 1e6] = c.pressure;
  }
  double mid = 0.0;
  int count = 0;
  for (const auto& [z, p] : by_height)
    if (z >= 25 - 1e-9 && z <= 35 + 1e-9) mid += p, ++count;
  mid /= count;
  for (const auto& [z, p] : by_height) std::printf("z = %6.3f  p = %8.3f\n", z, p);
  std::printf("axisymmetric mid pressure %.3f\n", mid);
  EXPECT_GT(mid, 111.0 * 0.99);
  EXPECT_LT(mid, 122.0);
  EXPECT_NEAR(mid, 111.1, 0.01 * 111.1);
  // Both edges of the fit carry the SPEC 4.2 peaks: measured 184.04 at z = 20 and z = 40.
  EXPECT_NEAR(by_height.begin()->second, 184.04, 0.005 * 184.04);   // z = 20
  EXPECT_NEAR(by_height.rbegin()->second, 184.04, 0.005 * 184.04);  // z = 40
  // Measured 2.8e-7 (the 3D contact tests reach 1e-8; not traced).
  EXPECT_LT(r.contact_equilibrium.relative_residual, 1e-6);
}

// The writer's deck of an axisymmetric model reads back to the same model and solution (the
// element type, the face loads on edges, the section without a data line): u(R1) the same to
// 1e-10 relative (the writer rounds numbers below 5e-13 relative, docs/input.md).
TEST(AxisymmetricLame, WrittenDeckReadsBackToTheSameSolution) {
  const std::filesystem::path dir = scratch("lame_round_trip");
  { std::ofstream(dir / "job.inp") << lame_deck("CAX8R", 0.3); }
  const Model model = read_inp((dir / "job.inp").string(), test::shared_builtin_registry());
  {
    std::ofstream out(dir / "written.inp");
    write_inp(model, out);
  }
  const Model again = read_inp((dir / "written.inp").string(), test::shared_builtin_registry());
  ASSERT_EQ(again.element_count(), model.element_count());
  EXPECT_EQ(again.elements[0].type, "CAX8R");
  const Results a =
      run_static_analysis(model, test::shared_builtin_registry(), SolveOptions{}, nullptr, nullptr);
  const Results b =
      run_static_analysis(again, test::shared_builtin_registry(), SolveOptions{}, nullptr, nullptr);
  const std::map<Id, Vec3> ua = inner_displacements(model, a), ub = inner_displacements(again, b);
  for (const auto& [id, u] : ua) EXPECT_NEAR(u[0], ub.at(id)[0], 1e-10 * std::abs(u[0])) << id;
}

}  // namespace
}  // namespace styk
