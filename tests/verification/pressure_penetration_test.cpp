// Pressure penetration (*PRESSURE PENETRATION, docs/contact.md) on two stacked
// columns pressed together by a prescribed shortening, a fluid entering their interface at the
// edge x = 0, the LEAK set at the far edge x = 4.
//
// With nu = 0 each column is in uniaxial stress and the answer is closed-form (1D, Rötscher's
// springs with equal columns): a shortening delta of the pair, fixed at both ends, gives a normal
// force N + p A = E A delta / 2, so the contact pressure is q0 - p with q0 = E delta / 2 wherever
// the fluid acts, and the interface opens (leaks) at p = q0.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_model_kit.hpp"
#include "contact_path_agreement.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/interface.hpp"
#include "styk/mesher/merge.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

using test::near;

constexpr double kYoung = 1000.0;

// Columns [0, 4] x [0, 1] x [0, 1] (BASE) and x [1, 2] (TOP), C3D8, 4 x 1 x 1 each, split at
// z = 1 (coincident node pairs); TOP's bottom is the slave. Supports: the base's bottom in z, the
// nodes on x = 0 in x and on y = 0 in y (no lateral strain with nu = 0, so no reactions there).
Model columns(double top = 2, int along = 4) {
  mesher::Mesh mesh;
  test::add_box(mesh, {0, 0, 0}, {4, 1, 1}, {along, 1, 1}, "C3D8", "BASE");
  test::add_box(mesh, {0, 0, 1}, {4, 1, top}, {along, 1, 1}, "C3D8", "TOP");
  mesher::merge_coincident_nodes(mesh);
  mesher::split_interface(mesh, "TOP", "FACE");
  Model model = test::contact_model(mesh, {{"BASE", kYoung, 0.0}, {"TOP", kYoung, 0.0}});
  test::add_contact_pair(model, "FACE_A", "FACE_B", "SMOOTH", std::nullopt);
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return near(x[2], 0); }), {3});
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return near(x[0], 0); }), {1});
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return near(x[1], 0); }), {2});
  return model;
}

// Slave (TOP) / master (BASE) interface nodes with x = value.
std::vector<int> interface_nodes(const Model& model, const std::string& elset, double x) {
  std::vector<int> out;
  for (int n : test::nodes_of(model, elset))
    if (near(model.coords[n][2], 1) && near(model.coords[n][0], x)) out.push_back(n);
  return out;
}

// Step PRELOAD prescribes the top face's z displacement per node, step FLUID holds it and ramps
// the fluid to `pressure` in `increments` fixed increments.
void add_steps(Model& model, const std::function<double(double)>& top_uz, double pressure,
               double critical, int increments) {
  Step preload = model.steps.front();
  preload.name = "PRELOAD";
  for (int n : test::nodes_where(model, [](const Vec3& x) { return near(x[2], 2); }))
    preload.boundaries.push_back({n, 3, top_uz(model.coords[n][0]), {}});
  Step fluid;
  fluid.name = "FLUID";
  fluid.has_procedure = true;
  fluid.procedure.initial_increment = 1.0 / increments;
  fluid.procedure.fixed_increments = true;
  PressurePenetration pp;
  pp.slave = "FACE_A";
  pp.master = "FACE_B";
  pp.exposed_slave = interface_nodes(model, "TOP", 0);
  pp.exposed_master = interface_nodes(model, "BASE", 0);
  pp.pressure = pressure;
  pp.critical = critical;
  NodeSet far;
  far.name = "FAR";
  far.nodes = interface_nodes(model, "TOP", 4);
  model.nsets["FAR"] = far;
  pp.leak_nset = "FAR";
  fluid.penetrations.push_back(pp);
  model.steps = {preload, fluid};
}

Results solve(const Model& model, ContactSolveKind contact_solve = ContactSolveKind::Automatic) {
  const auto registry = test::registry_with_plugins();
  SolveOptions options;
  options.contact_solve = contact_solve;
  return run_static_analysis(model, registry->registry, options, nullptr, nullptr);
}

// A critical contact pressure above every contact pressure: the fluid reaches the whole interface
// at once, the far edge included (a leak from the first increment). q0 = E delta / 2 = 10 for
// delta = 0.02; the fluid ramps to 16 in 7 increments, so p = 16 k / 7 never equals q0. Expected:
// contact pressure q0 - p at every slave node to 1e-9 of q0 while p < q0, the fluid pressure p on
// every node; all open once p > q0 (first at 80 / 7 = 11.43, the increment before at 9.14 still
// closed).
TEST(PressurePenetration, UniformColumnsOpenWhenTheFluidPressureReachesTheContactPressure) {
  Model model = columns();
  const double q0 = 10.0;
  add_steps(
      model, [&](double) { return -2 * q0 / kYoung; }, 16.0, 1e6, 7);
  const Results results = solve(model);
  int open_increment = 0;
  for (const IncrementResult& inc : results.increments) {
    if (inc.step != 2) continue;
    ASSERT_EQ(inc.penetrations.size(), 1u);
    const PenetrationResult& pr = inc.penetrations[0];
    const double p = 16.0 * inc.step_time;
    EXPECT_NEAR(pr.pressure, p, 1e-12);
    EXPECT_EQ(pr.penetrated, pr.nodes);
    EXPECT_TRUE(pr.leaked);
    bool all_open = true;
    for (const ContactNodeResult& c : inc.contact) {
      EXPECT_NEAR(c.fluid_pressure, p, 1e-9 * q0);
      all_open = all_open && c.status == ContactStatus::Open;
      if (p < q0) {
        EXPECT_NE(c.status, ContactStatus::Open);
        EXPECT_NEAR(c.pressure, q0 - p, 1e-9 * q0) << "p = " << p;
      } else {
        EXPECT_EQ(c.status, ContactStatus::Open) << "p = " << p;
      }
    }
    if (all_open && open_increment == 0) open_increment = inc.increment;
    EXPECT_LT(inc.contact_equilibrium.relative_residual, 1e-8);
  }
  EXPECT_EQ(open_increment, 5);  // p = 80 / 7 = 11.43
}

// A lever like the flange's ring: a plate (TOP, 0.25 thick, 8 elements along x) loaded by 1 on
// the top of its right half and held in z at its end face x = 4 (the bolt), so after the preload
// it presses on the base under the loaded half and is open over the left half. The fluid enters
// at x = 0 and lifts the plate, which bends about the held end: the contact under the loaded half
// unloads from its left edge, so the penetrated zone grows with the pressure until it reaches the
// far node line x = 4 (the LEAK set). At every converged increment the zone is consistent with the
// contact state (default critical pressure 0): every penetrated node is open and carries the
// fluid pressure; the zone never shrinks; it leaks after the front has moved (measured: 8 of 18
// slave nodes penetrated at p = 0.05, all 18 and the leak at p = 0.5, increment 10 of 12).
// Without the fluid the same steps leave more of the interface closed.
TEST(PressurePenetration, FrontMovesWithTheFluidAndStaysConsistentWithTheContactState) {
  Model model = columns(1.25, 8);
  Step preload = model.steps.front();
  preload.name = "PRELOAD";
  // The load: 1 on the top of the plate's right half; the end face held in z (the bolt).
  for (int e : model.elsets.at("TOP").elements) {
    double x = 0;
    for (int k = 0; k < 8; ++k) x += model.coords[model.element_nodes(e)[k]][0] / 8;
    if (x > 2) preload.dloads.push_back({e, 2, 1.0, {}});
  }
  test::fix(
      model,
      test::nodes_where(model, [](const Vec3& x) { return near(x[0], 4) && x[2] > 1 + 1e-9; }),
      {3});
  Step fluid;
  fluid.name = "FLUID";
  fluid.has_procedure = true;
  fluid.procedure.initial_increment = 1.0 / 12;
  fluid.procedure.fixed_increments = true;
  PressurePenetration pp;
  pp.slave = "FACE_A";
  pp.master = "FACE_B";
  pp.exposed_slave = interface_nodes(model, "TOP", 0);
  pp.exposed_master = interface_nodes(model, "BASE", 0);
  pp.pressure = 0.6;
  NodeSet far;
  far.name = "FAR";
  far.nodes = interface_nodes(model, "TOP", 4);
  model.nsets["FAR"] = far;
  pp.leak_nset = "FAR";
  fluid.penetrations.push_back(pp);
  model.steps = {preload, fluid};
  const Results results = solve(model);
  int previous = 0, first = -1, leak_increment = 0;
  for (const IncrementResult& inc : results.increments) {
    if (inc.step != 2) continue;
    const PenetrationResult& pr = inc.penetrations.at(0);
    if (first < 0) first = pr.penetrated;
    EXPECT_GE(pr.penetrated, previous) << "the zone shrank at p = " << pr.pressure;
    previous = pr.penetrated;
    if (pr.leaked && leak_increment == 0) leak_increment = inc.increment;
    for (const ContactNodeResult& c : inc.contact) {
      if (c.fluid_pressure > 0) {
        EXPECT_EQ(c.status, ContactStatus::Open) << "p = " << pr.pressure;
        EXPECT_NEAR(c.fluid_pressure, pr.pressure, 1e-9 * pr.pressure);
      }
    }
    EXPECT_LT(inc.contact_equilibrium.relative_residual, 1e-8);
  }
  EXPECT_GT(previous, first) << "the front did not move";
  EXPECT_GT(leak_increment, 1);
  std::printf("lever: %d then %d penetrated nodes, leak in increment %d of 12 (p = %.2f)\n", first,
              previous, leak_increment, 0.6 * leak_increment / 12);

  Model dry = model;
  dry.steps[1].penetrations.clear();
  const Results without = solve(dry);
  const auto open = [](const IncrementResult& inc) {
    int n = 0;
    for (const ContactNodeResult& c : inc.contact) n += c.status == ContactStatus::Open;
    return n;
  };
  EXPECT_LT(open(without.increments.back()), open(results.increments.back()));
}

// The fluid's forces reach the contacts through S (the loads d0 - S f of the penetrated zone):
// the sparse contact solve applies S through the factor of K instead of a dense S, and must give
// the dense path's zone, statuses and pressures (docs/contact.md, "Sparse contact solve"; within
// 1e-8 of the largest pressure and displacement). The columns pressed harder towards x = 4
// (q0 = 10 .. 20) and wet all over (a critical pressure above every contact pressure) open from
// the fluid's edge as it rises to 16: the open front moves.
TEST(PressurePenetration, SparseContactSolveFollowsTheSameFront) {
  Model model = columns(2, 8);
  add_steps(
      model, [](double x) { return -2 * (10 + 2.5 * x) / kYoung; }, 16.0, 1e6, 8);
  const Results dense = solve(model, ContactSolveKind::Dense);
  const Results sparse = solve(model, ContactSolveKind::Sparse);
  int open = 0;
  for (const ContactNodeResult& c : dense.increments.back().contact)
    open += c.status == ContactStatus::Open;
  EXPECT_GT(open, 0);  // the fluid opens part of the interface
  EXPECT_LT(open, static_cast<int>(dense.increments.back().contact.size()));
  test::expect_same_contact_answer(dense, sparse, 1e-8);
}

}  // namespace
}  // namespace styk
