// *SURFACE BEHAVIOR with CalculiX's penalty laws (PRESSURE-OVERCLOSURE=LINEAR, EXPONENTIAL, TIED;
// CalculiX manual, *SURFACE BEHAVIOR): what lands in the SurfaceInteraction, the refusals with
// their line, and the writer's round trip.
#include <sstream>

#include <gtest/gtest.h>

#include "deck_errors.hpp"
#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

namespace styk {
namespace {

using Law = PressureOverclosure::Law;
using test::expect_error;
using test::fake_registry;
using test::write_deck;

// One C3D8 with a surface interaction block; `behavior` is the *SURFACE BEHAVIOR card and data.
std::string deck(const std::string& behavior) {
  return "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 0.\n"
         "5, 0., 0., 1.\n6, 1., 0., 1.\n7, 1., 1., 1.\n8, 0., 1., 1.\n"
         "*ELEMENT, TYPE=C3D8, ELSET=A\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
         "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
         "*SOLID SECTION, ELSET=A, MATERIAL=STEEL\n"
         "*SURFACE INTERACTION, NAME=PEN\n" +
         behavior + "*STEP\n*STATIC\n*END STEP\n";
}

PressureOverclosure read_behavior(const std::string& name, const std::string& behavior) {
  const Model m = read_inp(write_deck(name, deck(behavior)), fake_registry());
  return m.surface_interactions.at("PEN").behavior;
}

TEST(PenaltyInput, LinearKeepsSlopeTensionAndClearanceFactor) {
  const PressureOverclosure b = read_behavior(
      "linear.inp", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n2.e6, 3., 0.01\n");
  EXPECT_EQ(b.law, Law::Linear);
  EXPECT_TRUE(b.penalty());
  EXPECT_EQ(b.slope, 2e6);
  ASSERT_TRUE(b.sigma_inf.has_value());
  EXPECT_EQ(*b.sigma_inf, 3.0);
  ASSERT_TRUE(b.c0.has_value());
  EXPECT_EQ(*b.c0, 0.01);
  const PressureOverclosure only_k =
      read_behavior("linear_k.inp", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=linear\n5.e5\n");
  EXPECT_EQ(only_k.slope, 5e5);
  EXPECT_FALSE(only_k.sigma_inf.has_value());
  EXPECT_FALSE(only_k.c0.has_value());
}

TEST(PenaltyInput, ExponentialAndTiedKeepTheirParameters) {
  const PressureOverclosure e = read_behavior(
      "exponential.inp", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n1.e-4, 0.1\n");
  EXPECT_EQ(e.law, Law::Exponential);
  EXPECT_EQ(e.c0.value_or(0.0), 1e-4);
  EXPECT_EQ(e.p0, 0.1);
  const PressureOverclosure t =
      read_behavior("tied.inp", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n1.e7\n");
  EXPECT_EQ(t.law, Law::Tied);
  EXPECT_EQ(t.slope, 1e7);
  const PressureOverclosure h =
      read_behavior("hard.inp", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n");
  EXPECT_EQ(h.law, Law::Hard);
  EXPECT_FALSE(h.penalty());
}

TEST(PenaltyInput, BadDataIsRefusedAtItsLine) {
  const std::string card = "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=";
  expect_error("linear_negative.inp", deck(card + "LINEAR\n-1.e6\n"), "-1.e6",
               "the slope K of the pressure-overclosure curve must be positive, read -1.e6");
  expect_error("linear_zero.inp", deck(card + "LINEAR\n0.\n"), "0.\n*STEP", "must be positive");
  expect_error("linear_missing.inp", deck(card + "LINEAR\n"), card,
               "needs a data line: K [, sigma_inf [, c0]]");
  expect_error("linear_tension.inp", deck(card + "LINEAR\n1.e6, -2.\n"), "1.e6, -2.",
               "sigma_inf (tension at large clearances) must not be negative");
  expect_error("linear_fields.inp", deck(card + "LINEAR\n1.e6, 1., 1e-3, 4.\n"), "1.e6, 1.",
               "K [, sigma_inf [, c0]]");
  expect_error("linear_text.inp", deck(card + "LINEAR\nstiff\n"), "stiff", "K of the");
  expect_error("exponential_one.inp", deck(card + "EXPONENTIAL\n1.e-4\n"), "1.e-4", "c0, p0");
  expect_error("exponential_p0.inp", deck(card + "EXPONENTIAL\n1.e-4, 0.\n"), "1.e-4, 0.",
               "p0 (contact pressure at zero clearance) must be positive");
  expect_error("tied_missing.inp", deck(card + "TIED\n"), card, "needs a data line: K");
  expect_error("hard_data.inp", deck(card + "HARD\n1.e6\n"), "1.e6", "takes no data line");
  expect_error("tabular.inp", deck(card + "TABULAR\n0., 0.\n"), card,
               "TABULAR pressure-overclosure tables are not supported");
  expect_error("twice.inp", deck(card + "LINEAR\n1.e6\n" + card + "HARD\n"), card + "HARD",
               "already has *SURFACE BEHAVIOR");
}

TEST(PenaltyInput, WriterWritesEveryLawBack) {
  const char* const cards[] = {
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n2.e6, 3., 0.01\n",
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n2.e6\n",
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n2.e6, , 0.01\n",
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n1.e-4, 0.1\n",
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n1.e7\n",
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n",
  };
  int k = 0;
  for (const char* card : cards) {
    const std::string name = "round_trip_" + std::to_string(k++) + ".inp";
    const Model m = read_inp(write_deck(name, deck(card)), fake_registry());
    std::ostringstream first;
    write_inp(m, first);
    const Model again = read_inp(write_deck("again_" + name, first.str()), fake_registry());
    const PressureOverclosure& a = m.surface_interactions.at("PEN").behavior;
    const PressureOverclosure& b = again.surface_interactions.at("PEN").behavior;
    EXPECT_EQ(a.law, b.law) << card;
    EXPECT_EQ(a.slope, b.slope) << card;
    EXPECT_EQ(a.sigma_inf, b.sigma_inf) << card;
    EXPECT_EQ(a.c0, b.c0) << card;
    EXPECT_EQ(a.p0, b.p0) << card;
    std::ostringstream second;
    write_inp(again, second);
    // Writing is stable (after the first line, which names the file written from).
    const auto body = [](const std::string& text) { return text.substr(text.find('\n')); };
    EXPECT_EQ(body(first.str()), body(second.str())) << card;
  }
}

}  // namespace
}  // namespace styk
