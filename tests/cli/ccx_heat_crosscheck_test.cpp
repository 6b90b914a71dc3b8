// Cross-check of steady heat conduction against CalculiX (docs/solver.md, "Steady heat and
// electric potential"; SPEC §6.2 geometry): the same deck, written by Styk's .inp writer, solved
// by `styk solve` and by `ccx`; every nodal temperature (*NODE PRINT, NT) must agree to 1e-6
// relative to the largest temperature, and the heat flows (RFL) drawn at the prescribed nodes to
// 1e-6 relative to the largest one. Two decks from the `cylinder-wall` builder: C3D20 with
// T = 100 / 25 on the two walls, and C3D8 with orthotropic conductivity (k = 1, 2, 0.5), a
// uniform *DFLUX into the inner wall, a *CFLUX at one node and T = 25 outside.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "support/ccx_runner.hpp"
#include "support/element_registries.hpp"

namespace styk::testing {
namespace {

// The last block of the .dat whose header starts with `what` ("temperatures", "heat generation"):
// node id -> value.
std::map<long, double> last_block(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  std::map<long, double> block;
  std::string line;
  bool reading = false;
  while (std::getline(in, line)) {
    if (line.rfind(" " + what + " for set", 0) == 0) {
      block.clear();
      reading = true;
      std::getline(in, line);  // the blank line after the header
      continue;
    }
    if (!reading) continue;
    std::istringstream fields(line);
    long id = 0;
    double value = 0.0;
    if (!(fields >> id >> value)) {
      reading = false;
      continue;
    }
    block[id] = value;
  }
  return block;
}

double worst_difference(const std::map<long, double>& a, const std::map<long, double>& b,
                        double* largest_out) {
  double largest = 0.0;
  for (const auto& entry : b) largest = std::max(largest, std::abs(entry.second));
  double worst = 0.0;
  for (const auto& [id, value] : a) {
    const auto it = b.find(id);
    EXPECT_NE(it, b.end()) << "node " << id << " missing in ccx output";
    if (it != b.end()) worst = std::max(worst, std::abs(value - it->second) / largest);
  }
  *largest_out = largest;
  return worst;
}

void cross_check(const Model& model, const std::string& job) {
  const std::string dir = scratch_dir("ccx_heat_" + job);
  {
    std::ofstream deck(dir + "/" + job + ".inp");
    write_inp(model, deck);
  }
  const CommandResult ours =
      run_command(styk_executable() + " solve -q " + job + ".inp -o styk", dir);
  ASSERT_EQ(ours.exit_code, 0) << ours.err;
  const test::CcxRun peer = test::run_ccx(dir, job);
  ASSERT_EQ(peer.exit_code, 0) << "ccx failed (is calculix-ccx installed?)\n" << peer.log;
  const auto t_ours = last_block(dir + "/styk/" + job + ".dat", "temperatures");
  const auto t_peer = last_block(dir + "/" + job + ".dat", "temperatures");
  ASSERT_EQ(t_ours.size(), static_cast<std::size_t>(model.node_count()));
  ASSERT_EQ(t_ours.size(), t_peer.size());
  double largest_t = 0.0, largest_q = 0.0;
  const double worst_t = worst_difference(t_ours, t_peer, &largest_t);
  const auto q_ours = last_block(dir + "/styk/" + job + ".dat", "heat generation");
  const auto q_peer = last_block(dir + "/" + job + ".dat", "heat generation");
  ASSERT_FALSE(q_ours.empty());
  ASSERT_EQ(q_ours.size(), q_peer.size());
  const double worst_q = worst_difference(q_ours, q_peer, &largest_q);
  std::printf(
      "ccx heat cross-check %-16s nodes %5d  max |T| %.6g  dT/max %.2e  max |RFL| %.6g  "
      "dRFL/max %.2e\n",
      job.c_str(), model.node_count(), largest_t, worst_t, largest_q, worst_q);
  EXPECT_LT(worst_t, 1e-6);
  EXPECT_LT(worst_q, 1e-6);
}

TEST(CcxHeatCrossCheck, CylinderWallC3D20) {
  ElementRegistry registry = test::builtin_registry();
  const mesher::BuildResult r =
      mesher::run_builder("cylinder-wall", {{"element", "C3D20"}, {"ntheta", "24"}}, registry);
  cross_check(r.model, "wall_c3d20");
}

TEST(CcxHeatCrossCheck, OrthotropicC3D8WithFluxes) {
  ElementRegistry registry = test::builtin_registry();
  mesher::BuildResult r = mesher::run_builder(
      "cylinder-wall", {{"element", "C3D8"}, {"nr", "3"}, {"ntheta", "24"}, {"nz", "2"}}, registry);
  Model& model = r.model;
  model.materials.front().conductivity = std::array<double, 3>{1.0, 2.0, 0.5};
  Step& step = model.steps.front();
  // Keep T = 25 outside; heat enters through the inner wall (*DFLUX) and at one node (*CFLUX).
  std::vector<Boundary> outside;
  for (const Boundary& b : step.boundaries)
    if (b.value == 25.0) outside.push_back(b);
  step.boundaries = outside;
  for (const mesher::FaceRef& f : r.mesh.surfaces.at("INNERFACE"))
    step.dfluxes.push_back({f.element, f.face + 1, 3.0, {}});
  step.cfluxes.push_back({model.nsets.at("INNER").nodes.front(), 11, 5.0, {}});
  cross_check(model, "wall_c3d8_flux");
}

}  // namespace
}  // namespace styk::testing
