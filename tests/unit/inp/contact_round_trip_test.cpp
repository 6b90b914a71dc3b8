// write_inp of the contact, constraint and temperature keywords: read -> write -> read gives the
// same model, and writing the re-read model gives the same text.
#include <gtest/gtest.h>

#include <sstream>

#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

namespace styk {
namespace {

using test::fake_registry;
using test::write_deck;

const char* const kDeck = R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
11, 0., 0., 1.
12, 1., 0., 1.
13, 1., 1., 1.
14, 0., 1., 1.
15, 0., 0., 2.
16, 1., 0., 2.
17, 1., 1., 2.
18, 0., 1., 2.
*ELEMENT, TYPE=C3D8, ELSET=A
1, 1, 2, 3, 4, 5, 6, 7, 8
*ELEMENT, TYPE=C3D8, ELSET=B
2, 11, 12, 13, 14, 15, 16, 17, 18
*NSET, NSET=B_BOTTOM
11, 12, 13, 14
*NSET, NSET=SECTOR
1, 4
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*EXPANSION, ZERO=20.
1.2e-5
*SOLID SECTION, ELSET=A, MATERIAL=STEEL
*SOLID SECTION, ELSET=B, MATERIAL=STEEL
*SURFACE, NAME=A_TOP
A, S2
1, S4
*SURFACE, NAME=B_BOTTOM
2, S1
*SURFACE, NAME=B_NODES, TYPE=NODE
B_BOTTOM
*SURFACE INTERACTION, NAME=GREASED
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*FRICTION
0.15, 20000.
*SURFACE INTERACTION, NAME=DRY
*FRICTION, ANISOTROPIC, ORIENTATION=GROOVES
0.1, 0.30000000000000004
*SURFACE INTERACTION, NAME=GLUED
*FRICTION, ROUGH
*SURFACE INTERACTION, NAME=SLICK
*SURFACE INTERACTION, NAME=PLAIN
*FRICTION
0.2
*ORIENTATION, NAME=GROOVES, SYSTEM=CYLINDRICAL
0., 0., 0., 0., 0., 1.
*ORIENTATION, NAME=FLAT
0.9238795325112867, 0.3826834323650898, 0., -0.3826834323650898, 0.9238795325112867, 0.
*CONTACT PAIR, INTERACTION=GREASED, TYPE=SURFACE TO SURFACE, ADJUST=1e-3
B_BOTTOM, A_TOP
*CONTACT PAIR, INTERACTION=DRY, ADJUST=B_BOTTOM
B_NODES, A_TOP
*CONTACT PAIR, INTERACTION=GLUED, TYPE=MORTAR
B_BOTTOM, A_TOP
*CLEARANCE, SLAVE=B_BOTTOM, MASTER=A_TOP, VALUE=-2.5e-3
*TRANSFORM, NSET=SECTOR, TYPE=R
0.9238795325112867, 0.3826834323650898, 0., -0.3826834323650898, 0.9238795325112867, 0.
*TRANSFORM, NSET=B_BOTTOM, TYPE=C
0., 0., 0., 0., 0., 1.
*EQUATION
2
5, 1, 1., 11, 1, -1.
5
6, 3, 1., 12, 3, -1., 7, 3, 0.5, 13, 3, -0.5
8, 2, 1e-7
*INITIAL CONDITIONS, TYPE=TEMPERATURE
ALL, 20.
*BOUNDARY
1, 1, 3
*STEP
*STATIC, DIRECT
0.25, 1., 0.25, 0.25
*TEMPERATURE
SECTOR, 20.
B_BOTTOM, 120.5
*CONTACT PRINT
CSTR, CDIS, CSTATUS
*END STEP
*STEP
*STATIC
0.1, 2., , 0.5
*TEMPERATURE, OP=NEW
*END STEP
*STEP
*STATIC
0.1, 2., 0.001
*TEMPERATURE, OP=NEW
5, -40.
*END STEP
)";

std::string written(const Model& m) {
  std::ostringstream out;
  write_inp(m, out);
  return out.str();
}

void expect_same_axes(const LocalAxes& x, const LocalAxes& y) {
  EXPECT_EQ(x.system, y.system);
  EXPECT_EQ(x.a, y.a);
  EXPECT_EQ(x.b, y.b);
}

void expect_same_temperatures(const std::vector<NodalTemperature>& x,
                              const std::vector<NodalTemperature>& y) {
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i].node, y[i].node);
    EXPECT_EQ(x[i].value, y[i].value);
  }
}

void expect_equivalent_extras(const Model& a, const Model& b) {
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (const auto& [name, s] : a.surfaces) {
    ASSERT_EQ(b.surfaces.count(name), 1u) << name;
    const Surface& t = b.surfaces.at(name);
    EXPECT_EQ(s.kind, t.kind);
    EXPECT_EQ(s.nodes, t.nodes);
    ASSERT_EQ(s.faces.size(), t.faces.size());
    for (std::size_t i = 0; i < s.faces.size(); ++i) {
      EXPECT_EQ(s.faces[i].element, t.faces[i].element);
      EXPECT_EQ(s.faces[i].face, t.faces[i].face);
    }
  }
  ASSERT_EQ(a.surface_interactions.size(), b.surface_interactions.size());
  for (const auto& [name, i] : a.surface_interactions) {
    ASSERT_EQ(b.surface_interactions.count(name), 1u) << name;
    const SurfaceInteraction& j = b.surface_interactions.at(name);
    ASSERT_EQ(i.friction.has_value(), j.friction.has_value()) << name;
    if (!i.friction) continue;
    EXPECT_EQ(i.friction->kind, j.friction->kind);
    EXPECT_EQ(i.friction->mu, j.friction->mu);
    EXPECT_EQ(i.friction->mu2, j.friction->mu2);
    EXPECT_EQ(i.friction->stick_slope, j.friction->stick_slope);
    EXPECT_EQ(i.friction->orientation, j.friction->orientation);
  }
  ASSERT_EQ(a.contact_pairs.size(), b.contact_pairs.size());
  for (std::size_t i = 0; i < a.contact_pairs.size(); ++i) {
    const ContactPair& p = a.contact_pairs[i];
    const ContactPair& q = b.contact_pairs[i];
    EXPECT_EQ(p.type, q.type);
    EXPECT_EQ(p.slave, q.slave);
    EXPECT_EQ(p.master, q.master);
    EXPECT_EQ(p.interaction, q.interaction);
    EXPECT_EQ(p.adjust_nset, q.adjust_nset);
    EXPECT_EQ(p.adjust_tolerance, q.adjust_tolerance);
    EXPECT_EQ(p.clearance, q.clearance);
  }
  ASSERT_EQ(a.orientations.size(), b.orientations.size());
  for (const auto& [name, o] : a.orientations) {
    ASSERT_EQ(b.orientations.count(name), 1u) << name;
    expect_same_axes(o.axes, b.orientations.at(name).axes);
  }
  ASSERT_EQ(a.transforms.size(), b.transforms.size());
  for (std::size_t i = 0; i < a.transforms.size(); ++i) {
    EXPECT_EQ(a.transforms[i].nset, b.transforms[i].nset);
    expect_same_axes(a.transforms[i].axes, b.transforms[i].axes);
  }
  ASSERT_EQ(a.equations.size(), b.equations.size());
  for (std::size_t i = 0; i < a.equations.size(); ++i) {
    ASSERT_EQ(a.equations[i].terms.size(), b.equations[i].terms.size());
    for (std::size_t k = 0; k < a.equations[i].terms.size(); ++k) {
      EXPECT_EQ(a.equations[i].terms[k].node, b.equations[i].terms[k].node);
      EXPECT_EQ(a.equations[i].terms[k].dof, b.equations[i].terms[k].dof);
      EXPECT_EQ(a.equations[i].terms[k].coefficient, b.equations[i].terms[k].coefficient);
    }
  }
  expect_same_temperatures(a.initial_temperatures, b.initial_temperatures);
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t s = 0; s < a.steps.size(); ++s) {
    const Step& x = a.steps[s];
    const Step& y = b.steps[s];
    EXPECT_EQ(x.procedure.initial_increment, y.procedure.initial_increment);
    EXPECT_EQ(x.procedure.total_time, y.procedure.total_time);
    EXPECT_EQ(x.procedure.min_increment, y.procedure.min_increment);
    EXPECT_EQ(x.procedure.max_increment, y.procedure.max_increment);
    EXPECT_EQ(x.procedure.fixed_increments, y.procedure.fixed_increments);
    expect_same_temperatures(x.temperatures, y.temperatures);
    EXPECT_EQ(x.temperature_op_new, y.temperature_op_new);
    ASSERT_EQ(x.outputs.size(), y.outputs.size());
    for (std::size_t i = 0; i < x.outputs.size(); ++i) {
      EXPECT_EQ(x.outputs[i].kind, y.outputs[i].kind);
      EXPECT_EQ(x.outputs[i].vars, y.outputs[i].vars);
    }
  }
}

TEST(ContactRoundTrip, EveryNewKeywordReadsBackAndWritingIsStable) {
  const ElementRegistry registry = fake_registry();
  const Model original = read_inp(write_deck("contact_everything.inp", kDeck), registry);
  // The deck exercises what it should: a non-trivial value of every new field.
  ASSERT_EQ(original.contact_pairs.size(), 3u);
  ASSERT_EQ(original.contact_pairs[2].type, ContactPair::Type::Mortar);
  ASSERT_EQ(original.surfaces.at("A_TOP").faces.size(), 2u);
  ASSERT_EQ(original.equations.size(), 2u);
  ASSERT_EQ(original.equations[1].terms.size(), 5u);
  ASSERT_TRUE(original.steps[0].procedure.fixed_increments);
  ASSERT_FALSE(original.steps[1].procedure.min_increment.has_value());
  ASSERT_TRUE(original.steps[1].procedure.max_increment.has_value());
  ASSERT_TRUE(original.steps[2].procedure.min_increment.has_value());
  ASSERT_FALSE(original.steps[2].procedure.max_increment.has_value());

  const std::string text = written(original);
  const Model again = read_inp(write_deck("contact_everything_written.inp", text), registry);
  expect_equivalent_extras(original, again);
  EXPECT_EQ(again.surface_interactions.at("DRY").friction->mu2, 0.30000000000000004);
  const std::string rewritten = written(again);
  EXPECT_EQ(rewritten.substr(rewritten.find('\n')), text.substr(text.find('\n')));
}

}  // namespace
}  // namespace styk
