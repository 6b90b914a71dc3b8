// SPEC §4.2 model B (mu = 0.4, the shaft heated by 100) twisted to and past its friction capacity,
// as the builder's 90 deg sector with cyclic symmetry on a coarse mesh (4 elements around the
// quarter, 4 along the fit). The hand capacity of SPEC §4.2 is mu pi d^2 l p / 2 = 559-614 N m
// for the Lamé pressure p = 111-122 MPa (plane stress / plane strain).
// - Rotation control (--load-case rotation, 1.5 deg): every increment converges (no cut-back
//   below 1/20 of the step, which automatic increments would otherwise report), the slipping share
//   never falls, full slip is reached, and the torque on the whole joint (4 x the sector's contact
//   moment) then stays within 0.5 % of its value at full slip and inside the hand band.
// - Force control (--load-case torque, 300 and 850 N m): 300 N m holds; 850 N m exceeds the
//   capacity, so the analysis stops in that step naming the sliding of the sleeve about the axis,
//   with a moment inside the hand band.
// The measured figures docs/contact.md quotes (569.4 N m at full slip, 568.9 at 1.5 deg, capacity
// 568.8 N m under force control) are asserted to 0.5 %.
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

std::map<std::string, std::string> coarse_sector() {
  return {{"model", "B"},    {"sector", "yes"},    {"around", "4"},       {"fit-rows", "4"},
          {"end-rows", "3"}, {"shaft-rings", "2"}, {"sleeve-rings", "2"}, {"element", "C3D21"}};
}

TEST(Spec42ModelB, RotationControlReachesFullSlipAndHoldsTheCapacity) {
  const auto registry = test::registry_with_plugins();
  std::map<std::string, std::string> args = coarse_sector();
  args["load-case"] = "rotation";
  const mesher::BuildResult built = mesher::run_builder("shrink-fit", args, registry->registry);
  const Results results =
      run_static_analysis(built.model, registry->registry, SolveOptions{}, nullptr, nullptr);
  double onset = 0, previous_time = 0, last = 0;
  int previous_slipping = 0;
  for (const IncrementResult& inc : results.increments) {
    if (inc.step != 2) continue;
    EXPECT_GE(inc.step_time - previous_time, 0.05 - 1e-12) << "cut back at t = " << inc.step_time;
    previous_time = inc.step_time;
    const double torque = -4 * inc.contact_pairs.at(0).moment[2] / 1000.0;  // N m, whole joint
    int closed = 0, slipping = 0;
    for (const ContactNodeResult& c : inc.contact) {
      closed += c.status != ContactStatus::Open;
      slipping += c.status == ContactStatus::Slip;
    }
    EXPECT_GE(slipping, previous_slipping) << "t = " << inc.step_time;
    previous_slipping = slipping;
    if (onset > 0) {
      EXPECT_NEAR(torque, onset, 0.005 * onset) << "t = " << inc.step_time;
    }
    if (onset == 0 && slipping == closed) onset = torque;
    last = torque;
  }
  ASSERT_GT(onset, 0) << "no full slip by 1.5 deg";
  EXPECT_GE(onset, 559.0);
  EXPECT_LE(onset, 614.0);
  // The figures docs/contact.md quotes for this mesh (measured 2026-11-26), to 0.5 %: the
  // increment in which full slip is first seen moves the onset by at most one increment's growth.
  EXPECT_NEAR(onset, 569.4, 0.005 * 569.4);
  EXPECT_NEAR(last, 568.9, 0.005 * 568.9);
  std::printf("coarse model B sector: full slip at %.1f N m, %.1f N m at 1.5 deg\n", onset, last);
}

TEST(Spec42ModelB, ForceControlStopsAtTheCapacity) {
  const auto registry = test::registry_with_plugins();
  std::map<std::string, std::string> args = coarse_sector();
  args["load-case"] = "torque";
  args["torques"] = "300,850";
  const mesher::BuildResult built = mesher::run_builder("shrink-fit", args, registry->registry);
  try {
    run_static_analysis(built.model, registry->registry, SolveOptions{}, nullptr, nullptr);
    ADD_FAILURE() << "850 N m held";
  } catch (const NotConvergedError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("contact step 3"), std::string::npos) << message;
    EXPECT_NE(message.find("slides"), std::string::npos) << message;
    EXPECT_NE(message.find("rotation"), std::string::npos) << message;
    // "..., moment applied A, capacity C, along its free rotation ...": the sector's moment, a
    // quarter of the joint's.
    const std::size_t at = message.rfind(", capacity ");
    ASSERT_NE(at, std::string::npos) << message;
    const double capacity = 4 * std::stod(message.substr(at + 11)) / 1000.0;
    EXPECT_GE(capacity, 559.0) << message;
    EXPECT_LE(capacity, 614.0) << message;
    EXPECT_NEAR(capacity, 568.8, 0.005 * 568.8) << message;  // docs/contact.md, to 0.5 %
    std::printf("coarse model B sector under 850 N m: capacity %.1f N m\n", capacity);
  }
}

}  // namespace
}  // namespace styk
