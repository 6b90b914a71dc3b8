// Cross-check against CalculiX (issue: foundation, "Verification"): the same deck, written by
// Styk's .inp writer, solved by `styk solve` and by `ccx`; every nodal displacement must agree to
// 1e-6 relative to the largest displacement of the model. Three decks: a distorted C3D8 block, a
// C3D20 cantilever under *DLOAD pressure, and a two-material C3D20 model.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/mesher/box_mesh.hpp"
#include "styk/mesher/cantilever.hpp"
#include "support/ccx_runner.hpp"

namespace styk::testing {
namespace {

// Writes `model` as `<dir>/<job>.inp`, solves it with both programs, compares the displacements.
void cross_check(const Model& model, const std::string& job) {
  const std::string dir = scratch_dir("ccx_" + job);
  {
    std::ofstream deck(dir + "/" + job + ".inp");
    write_inp(model, deck);
  }
  const CommandResult ours =
      run_command(styk_executable() + " solve -q " + job + ".inp -o styk", dir);
  ASSERT_EQ(ours.exit_code, 0) << ours.err;
  const test::CcxRun peer = test::run_ccx(dir, job);
  ASSERT_EQ(peer.exit_code, 0) << "ccx failed (is calculix-ccx installed? scripts/install-deps.sh "
                                  "--test installs it)\n"
                               << peer.log;

  std::ifstream ours_dat(dir + "/styk/" + job + ".dat");
  std::ifstream peer_dat(dir + "/" + job + ".dat");
  const std::vector<DatDisplacements> a = parse_dat_displacements(ours_dat);
  const std::vector<DatDisplacements> b = parse_dat_displacements(peer_dat);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  const auto& ua = a.back().u;
  const auto& ub = b.back().u;
  ASSERT_EQ(ua.size(), static_cast<std::size_t>(model.node_count()));
  ASSERT_EQ(ua.size(), ub.size());

  double largest = 0.0;
  for (const auto& [id, u] : ub)
    for (double c : u) largest = std::max(largest, std::abs(c));
  ASSERT_GT(largest, 0.0);
  double worst = 0.0;
  for (const auto& [id, u] : ua) {
    const auto it = ub.find(id);
    ASSERT_NE(it, ub.end()) << "node " << id << " missing in ccx output";
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(u[c] - it->second[c]) / largest);
  }
  std::printf("ccx cross-check %-22s nodes %6d  max |u| %.6e  max difference / max |u| %.2e\n",
              job.c_str(), model.node_count(), largest, worst);
  EXPECT_LT(worst, 1e-6);
}

// docs/results.md: a node in a *TRANSFORM prints U and RF in its local system with a trailing " L",
// as ccx does. One C3D8, node 7 in a system turned 90 degrees about z, loaded along local x and
// moved along local z. The U blocks of both programs agree row by row (to 1e-6 of the largest
// value) and mark the same rows local.
TEST(CcxCrossCheck, TransformedNodePrintsLocalComponentsMarkedL) {
  const std::string dir = scratch_dir("ccx_transform");
  {
    std::ofstream deck(dir + "/tr.inp");
    deck << "*NODE, NSET=ALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n"
            "6, 1, 0, 1\n7, 1, 1, 1\n8, 0, 1, 1\n"
            "*ELEMENT, TYPE=C3D8, ELSET=E\n1, 1, 2, 3, 4, 5, 6, 7, 8\n*NSET, NSET=N7\n7\n"
            "*MATERIAL, NAME=M\n*ELASTIC\n210000, 0.3\n*SOLID SECTION, ELSET=E, MATERIAL=M\n"
            "*TRANSFORM, NSET=N7, TYPE=R\n0, 1, 0, -1, 0, 0\n"
            "*BOUNDARY\n1, 1, 3\n2, 2, 3\n4, 1\n4, 3\n5, 1, 2\n"
            "*STEP\n*STATIC\n*CLOAD\n7, 1, 1000.\n*BOUNDARY\n7, 3, 3, 0.001\n"
            "*NODE PRINT, NSET=ALL\nU\n*END STEP\n";
  }
  const CommandResult ours = run_command(styk_executable() + " solve -q tr.inp -o styk", dir);
  ASSERT_EQ(ours.exit_code, 0) << ours.err;
  const test::CcxRun peer = test::run_ccx(dir, "tr");
  ASSERT_EQ(peer.exit_code, 0) << peer.log;
  std::ifstream ours_dat(dir + "/styk/tr.dat"), peer_dat(dir + "/tr.dat");
  const std::vector<DatBlock> a = parse_dat_blocks(ours_dat), b = parse_dat_blocks(peer_dat);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  ASSERT_EQ(a[0].rows.size(), 8u);
  ASSERT_EQ(b[0].rows.size(), 8u);
  double largest = 0.0;
  for (const DatRow& row : b[0].rows)
    for (double v : row.values) largest = std::max(largest, std::abs(v));
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(a[0].rows[i].id, b[0].rows[i].id);
    EXPECT_EQ(a[0].rows[i].local, b[0].rows[i].local) << "node " << a[0].rows[i].id;
    EXPECT_EQ(a[0].rows[i].local, a[0].rows[i].id == 7);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(a[0].rows[i].values[k], b[0].rows[i].values[k], 1e-6 * largest)
          << "node " << a[0].rows[i].id << " component " << k;
  }
  // Node 7's third local component is the prescribed 0.001 along local z.
  EXPECT_NEAR(a[0].rows[6].values[2], 0.001, 1e-12);
}

TEST(CcxCrossCheck, DistortedC3D8Block) {
  mesher::CantileverSpec spec;
  spec.box.type = "C3D8";
  spec.box.size = {4.0, 2.0, 2.0};
  spec.box.divisions = {4, 2, 2};
  spec.young = 1000.0;
  spec.poisson = 0.3;
  spec.force = {0.2, -0.3, 1.0};
  spec.print_all_displacements = true;
  Model model = mesher::make_cantilever(spec);
  // Move interior nodes by a deterministic, smooth-but-irregular pattern (up to 0.3 of a cell).
  for (int n = 0; n < model.node_count(); ++n) {
    Vec3& x = model.coords[n];
    const bool interior_x = x[0] > 1e-9 && x[0] < 4.0 - 1e-9;
    const bool interior_y = x[1] > 1e-9 && x[1] < 2.0 - 1e-9;
    const bool interior_z = x[2] > 1e-9 && x[2] < 2.0 - 1e-9;
    const double s = std::sin(3.1 * x[0] + 1.7 * x[1] + 0.9 * x[2] + 0.5);
    if (interior_x) x[0] += 0.3 * s;
    if (interior_y) x[1] += 0.25 * std::cos(2.3 * x[0] - x[2]);
    if (interior_z) x[2] += 0.2 * s;
  }
  cross_check(model, "distorted_c3d8");
}

TEST(CcxCrossCheck, C3D20CantileverWithPressure) {
  mesher::CantileverSpec spec;
  spec.box.type = "C3D20";
  spec.box.size = {10.0, 1.0, 2.0};
  spec.box.divisions = {8, 1, 2};
  spec.young = 210000.0;
  spec.poisson = 0.3;
  spec.force = {0.0, 0.0, 0.0};
  spec.print_all_displacements = true;
  Model model = mesher::make_cantilever(spec);
  Step& step = model.steps.front();
  step.cloads.clear();
  // Pressure 5 on every top face (S2 of the top-layer elements), pushing down.
  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    if (std::abs(model.coords[nodes[4]][2] - 2.0) < 1e-9) step.dloads.push_back({e, 2, 5.0, {}});
  }
  ASSERT_EQ(step.dloads.size(), 8u);
  cross_check(model, "c3d20_pressure");
}

TEST(CcxCrossCheck, TwoMaterialC3D20) {
  mesher::CantileverSpec spec;
  spec.box.type = "C3D20";
  spec.box.size = {6.0, 1.5, 1.0};
  spec.box.divisions = {6, 2, 2};
  spec.young = 70000.0;
  spec.poisson = 0.33;
  spec.force = {50.0, 20.0, -100.0};
  spec.print_all_displacements = true;
  Model model = mesher::make_cantilever(spec);
  // The outer half (x > 3) becomes steel: a second material and section.
  Material steel;
  steel.name = "STEEL";
  steel.young = 210000.0;
  steel.poisson = 0.28;
  model.materials.push_back(steel);
  ElementSet outer{"OUTER", {}, {}};
  ElementSet& all = model.elsets.at("EALL");
  std::vector<int> inner;
  for (int e : all.elements) {
    double cx = 0.0;
    for (int k = 0; k < 8; ++k) cx += model.coords[model.element_nodes(e)[k]][0] / 8.0;
    (cx > 3.0 ? outer.elements : inner).push_back(e);
  }
  all.elements = inner;
  model.elsets["OUTER"] = outer;
  Section section;
  section.elset = "OUTER";
  section.material = "STEEL";
  section.material_index = 1;
  model.sections.push_back(section);
  for (int e : outer.elements) model.elements[e].section = 1;
  cross_check(model, "two_material_c3d20");
}

}  // namespace
}  // namespace styk::testing
