// The joint decks of spline-joint (SPEC §4.4) and p3g-joint (SPEC §4.5) solve: coarse meshes
// (spline: C3D21, C3D28, C3D14; P3G: C3D21) written, read back through the solver's reader and run
// by run_static_analysis. Checked:
// the moment balance (rim torque = shaft-end reactions = contact moment on the hub), the flanks
// that carry the spline's torque, the receding P3G contact and the rim displacement of §4.5.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTorque = 1e6;  // 1000 N m in N mm

struct Solved {
  Model model;
  Results results;
};

Solved build_and_solve(const std::string& builder, const std::string& family,
                       std::map<std::string, std::string> args, const ElementRegistry& registry) {
  args["element"] = family;
  const mesher::BuildResult built = mesher::run_builder(builder, args, registry);
  const std::string path = ::testing::TempDir() + "solve_" + builder + "_" + family + ".inp";
  {
    std::ofstream out(path);
    write_inp(built.model, out);
  }
  Solved s{read_inp(path, registry), {}};
  std::remove(path.c_str());
  s.results = run_static_analysis(s.model, registry, SolveOptions{}, nullptr, nullptr);
  return s;
}

// Moment about z of the reactions of a node set.
double reaction_moment(const Model& model, const IncrementResult& inc, const std::string& set) {
  double m = 0.0;
  for (int n : model.nsets.at(set).nodes)
    m += model.coords[n][0] * inc.RF[n][1] - model.coords[n][1] * inc.RF[n][0];
  return m;
}

class JointSolve : public ::testing::Test {
 protected:
  test::Elements elements_;
};

// SPEC §4.4: frictionless flanks carry M = 1000 N m. The reactions at the fixed shaft end and the
// contact forces on the hub each balance the rim torque (to 1e-6: the solve's round-off), and only
// the flank of each groove that the hub's tooth turns against closes: the slave (hub) nodes in
// contact lie on the flank at the angle -asin(w / 2 rho) of their nearest spline, none on the
// other side, with closed nodes on all 6 splines. For every contact family: C3D21 (SPEC's), C3D28
// (its layers closed through the root transition and the hub's sector lines) and C3D14.
class SplineSolve : public ::testing::TestWithParam<std::string> {
 protected:
  test::Elements elements_;
};

TEST_P(SplineSolve, FlanksCarryTheTorque) {
  const Solved s = build_and_solve("spline-joint", GetParam(),
                                   {{"tooth", "2"},
                                    {"groove", "2"},
                                    {"flank-rows", "1"},
                                    {"arm-rows", "2"},
                                    {"flange-rows", "2"},
                                    {"shaft-rows", "2"},
                                    {"hub-rings", "1"},
                                    {"flange-rings", "2"}},
                                   elements_.registry);
  ASSERT_FALSE(s.results.increments.empty());
  const IncrementResult& inc = s.results.increments.back();
  EXPECT_NEAR(reaction_moment(s.model, inc, "SHAFT_END"), -kTorque, 1e-6 * kTorque);
  ASSERT_EQ(inc.contact_pairs.size(), 1u);
  EXPECT_NEAR(inc.contact_pairs[0].moment[2], -kTorque, 1e-6 * kTorque);
  std::map<int, int> closed_per_spline;
  int closed = 0;
  for (const ContactNodeResult& c : inc.contact) {
    if (c.status == ContactStatus::Open) continue;
    ++closed;
    const Vec3& x = s.model.coords[c.node];
    const double angle = std::atan2(x[1], x[0]);
    const int spline = static_cast<int>(std::lround(angle / (kPi / 3)) + 6) % 6;
    const double local = angle - std::lround(angle / (kPi / 3)) * kPi / 3;
    EXPECT_LT(local, 0.0) << "closed node on the unloaded flank, spline " << spline;
    EXPECT_NEAR(std::hypot(x[0], x[1]) * std::sin(-local), 12.48 / 2, 1e-6) << "off the flank";
    ++closed_per_spline[spline];
  }
  EXPECT_GT(closed, 0);
  EXPECT_EQ(closed_per_spline.size(), 6u);
}

INSTANTIATE_TEST_SUITE_P(Families, SplineSolve, ::testing::Values("C3D21", "C3D28", "C3D14"));

// SPEC §4.5: max total displacement 0.41 mm at the flange rim, asserted to 10 % (the stand-in
// geometry and a coarse mesh: the default mesh gives 0.389, this one 0.385). The contact recedes:
// under the torque most of the bore lifts off (77 % of the slave nodes on the default mesh, 78 %
// here; asserted: more than half, not all).
TEST_F(JointSolve, P3gRimDisplacementAndRecedingContact) {
  const Solved s = build_and_solve("p3g-joint", "C3D21",
                                   {{"around", "36"},
                                    {"arm-rows", "2"},
                                    {"flange-rows", "2"},
                                    {"shaft-rows", "2"},
                                    {"hub-rings", "3"},
                                    {"flange-rings", "4"}},
                                   elements_.registry);
  ASSERT_FALSE(s.results.increments.empty());
  const IncrementResult& inc = s.results.increments.back();
  EXPECT_NEAR(reaction_moment(s.model, inc, "SHAFT_END"), -kTorque, 1e-6 * kTorque);
  EXPECT_NEAR(inc.contact_pairs.at(0).moment[2], -kTorque, 1e-6 * kTorque);
  double max_rim = 0.0, max_all = 0.0;
  for (int n = 0; n < s.model.node_count(); ++n)
    max_all = std::max(max_all, std::hypot(inc.U[n][0], inc.U[n][1], inc.U[n][2]));
  for (int n : s.model.nsets.at("FLANGE_RIM").nodes)
    max_rim = std::max(max_rim, std::hypot(inc.U[n][0], inc.U[n][1], inc.U[n][2]));
  EXPECT_EQ(max_rim, max_all) << "the largest displacement is on the flange rim";
  EXPECT_NEAR(max_rim, 0.41, 0.041);
  int open = 0;
  for (const ContactNodeResult& c : inc.contact) open += c.status == ContactStatus::Open;
  const int total = static_cast<int>(inc.contact.size());
  EXPECT_GT(open, total / 2);
  EXPECT_LT(open, total);
}

}  // namespace
}  // namespace styk
