// read_inp on the contact keywords: *SURFACE, *SURFACE INTERACTION, *SURFACE BEHAVIOR,
// *FRICTION, *CONTACT PAIR, *CLEARANCE, *CONTACT PRINT — what lands in the Model and what is
// refused (with the line that is wrong).
#include <gtest/gtest.h>

#include "deck_errors.hpp"
#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"

namespace styk {
namespace {

using test::fake_registry;
using test::line_of;
using test::write_deck;

// Two unit cubes stacked in z, not sharing nodes: block A (element 1, nodes 1-8) below,
// block B (element 2, nodes 11-18) above. A's top is its face S2, B's bottom its face S1.
const char* const kTwoBlocks = R"(*NODE, NSET=ALL
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
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=A, MATERIAL=STEEL
*SOLID SECTION, ELSET=B, MATERIAL=STEEL
)";

const char* const kStep = "*STEP\n*STATIC\n*END STEP\n";

// The line of `text` (1-based) that contains `marker` (the first one).
Model read(const std::string& name, const std::string& text,
           const ElementRegistry& registry = fake_registry()) {
  return read_inp(write_deck(name, text), registry);
}

// The deck's InputError; fails the test when there is none.
InputError error_of(const std::string& name, const std::string& text,
                    const ElementRegistry& registry = fake_registry()) {
  try {
    read(name, text, registry);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << name << ": accepted";
  return InputError({}, "");
}

void expect_error(const std::string& name, const std::string& text, const std::string& marker,
                  const std::string& substring) {
  const InputError e = error_of(name, text);
  EXPECT_EQ(e.where().line, line_of(text, marker)) << e.what();
  EXPECT_NE(e.message().find(substring), std::string::npos) << e.what();
}

const char* const kContact = R"(*SURFACE, NAME=A_TOP
A, S2
*SURFACE, NAME=B_BOTTOM, TYPE=ELEMENT
2, s1
*SURFACE, NAME=B_NODES, TYPE=NODE
B_BOTTOM
*CONTACT PAIR, INTERACTION=GREASED, TYPE=SURFACE TO SURFACE, ADJUST=1e-3
B_BOTTOM, A_TOP
*CONTACT PAIR, INTERACTION=dry, ADJUST=B_BOTTOM
B_NODES, A_TOP
*CLEARANCE, SLAVE=B_BOTTOM, MASTER=A_TOP, VALUE=-2.5e-3
*SURFACE INTERACTION, NAME=GREASED
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*FRICTION
0.15, 20000.
*SURFACE INTERACTION, NAME=DRY
*FRICTION, ANISOTROPIC, ORIENTATION=GROOVES
0.1, 0.3
*SURFACE INTERACTION, NAME=GLUED
*FRICTION, ROUGH
*SURFACE INTERACTION, NAME=SLICK
*ORIENTATION, NAME=GROOVES, SYSTEM=RECTANGULAR
1., 1., 0., -1., 1., 0.
)";

TEST(ContactInput, SurfacesInteractionsPairsAndClearanceLandInTheModel) {
  const std::string text = std::string(kTwoBlocks) + kContact +
                           "*STEP\n*STATIC\n*CONTACT PRINT\nCSTR, cdis\nCSTATUS, CSTR\n*END STEP\n";
  const Model m = read("contact.inp", text);

  ASSERT_EQ(m.surfaces.size(), 3u);
  const Surface& top = m.surfaces.at("A_TOP");
  EXPECT_EQ(top.kind, Surface::Kind::ElementFaces);
  ASSERT_EQ(top.faces.size(), 1u);
  EXPECT_EQ(top.faces[0].element, m.element_index(1));
  EXPECT_EQ(top.faces[0].face, 2);
  EXPECT_EQ(top.where.line, line_of(text, "*SURFACE, NAME=A_TOP"));
  EXPECT_EQ(m.surfaces.at("B_BOTTOM").faces[0].face, 1);
  const Surface& nodes = m.surfaces.at("B_NODES");
  EXPECT_EQ(nodes.kind, Surface::Kind::Nodes);
  EXPECT_EQ(nodes.nodes, (std::vector<int>{m.node_index(11), m.node_index(12), m.node_index(13),
                                           m.node_index(14)}));

  ASSERT_EQ(m.contact_pairs.size(), 2u);
  const ContactPair& p0 = m.contact_pairs[0];
  EXPECT_EQ(p0.type, ContactPair::Type::SurfaceToSurface);
  EXPECT_EQ(p0.slave, "B_BOTTOM");
  EXPECT_EQ(p0.master, "A_TOP");
  EXPECT_EQ(p0.interaction, "GREASED");
  ASSERT_TRUE(p0.adjust_tolerance.has_value());
  EXPECT_EQ(*p0.adjust_tolerance, 1e-3);
  EXPECT_TRUE(p0.adjust_nset.empty());
  ASSERT_TRUE(p0.clearance.has_value());
  EXPECT_EQ(*p0.clearance, -2.5e-3);
  EXPECT_EQ(p0.clearance_where.line, line_of(text, "*CLEARANCE"));
  EXPECT_EQ(p0.where.line, line_of(text, "B_BOTTOM, A_TOP"));
  const ContactPair& p1 = m.contact_pairs[1];
  EXPECT_EQ(p1.type, ContactPair::Type::NodeToSurface);  // the CalculiX default
  EXPECT_EQ(p1.interaction, "DRY");
  EXPECT_EQ(p1.adjust_nset, "B_BOTTOM");
  EXPECT_FALSE(p1.adjust_tolerance.has_value());
  EXPECT_FALSE(p1.clearance.has_value());

  ASSERT_EQ(m.surface_interactions.size(), 4u);
  const Friction& greased = *m.surface_interactions.at("GREASED").friction;
  EXPECT_EQ(greased.kind, Friction::Kind::Isotropic);
  EXPECT_EQ(greased.mu, 0.15);
  EXPECT_EQ(greased.stick_slope, 20000.0);
  const Friction& dry = *m.surface_interactions.at("DRY").friction;
  EXPECT_EQ(dry.kind, Friction::Kind::Anisotropic);
  EXPECT_EQ(dry.mu, 0.1);
  EXPECT_EQ(dry.mu2, 0.3);
  EXPECT_EQ(dry.orientation, "GROOVES");
  EXPECT_EQ(m.surface_interactions.at("GLUED").friction->kind, Friction::Kind::Rough);
  EXPECT_FALSE(m.surface_interactions.at("SLICK").friction.has_value());

  const Orientation& grooves = m.orientations.at("GROOVES");
  EXPECT_EQ(grooves.axes.system, CoordinateSystem::Rectangular);
  EXPECT_EQ(grooves.axes.a, (Vec3{1.0, 1.0, 0.0}));
  EXPECT_EQ(grooves.axes.b, (Vec3{-1.0, 1.0, 0.0}));

  ASSERT_EQ(m.steps[0].outputs.size(), 1u);
  const OutputRequest& print = m.steps[0].outputs[0];
  EXPECT_EQ(print.kind, OutputRequest::Kind::ContactPrint);
  EXPECT_EQ(print.vars, (std::vector<std::string>{"CSTR", "CDIS", "CSTATUS"}));
}

TEST(ContactInput, FaceLabelsAreCheckedAgainstTheElementType) {
  // S6 exists on a hexahedron, not on a wedge (five faces).
  const std::string wedge = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 0., 1., 0.
4, 0., 0., 1.
5, 1., 0., 1.
6, 0., 1., 1.
*ELEMENT, TYPE=C3D6, ELSET=W
1, 1, 2, 3, 4, 5, 6
*MATERIAL, NAME=STEEL
*ELASTIC
1., 0.
*SOLID SECTION, ELSET=W, MATERIAL=STEEL
*SURFACE, NAME=SIDE
W, S5
)";
  const ElementRegistry registry = test::fake_registry_with_wedge();
  EXPECT_EQ(read("wedge_s5.inp", wedge + kStep, registry).surfaces.at("SIDE").faces[0].face, 5);
  const std::string bad = wedge + "W, S6\n" + kStep;
  const InputError e = error_of("wedge_s6.inp", bad, registry);
  EXPECT_EQ(e.where().line, line_of(bad, "W, S6"));
  EXPECT_NE(e.message().find("S6 is not a face of element 1 (C3D6 has faces S1..S5)"),
            std::string::npos)
      << e.what();

  const std::string s7 = std::string(kTwoBlocks) + "*SURFACE, NAME=S\n2, S7\n" + kStep;
  expect_error("s7.inp", s7, "2, S7", "S7 is not a face of element 2 (C3D8 has faces S1..S6)");
  const std::string p1 = std::string(kTwoBlocks) + "*SURFACE, NAME=S\n2, P1\n" + kStep;
  expect_error("p1_label.inp", p1, "2, P1", "face label 'P1' is not known");
}

TEST(ContactInput, SurfaceErrorsNameTheLine) {
  const std::string base = kTwoBlocks;
  expect_error("surface_twice.inp",
               base + "*SURFACE, NAME=S\n1, S1\n*SURFACE, NAME=s\n2, S2\n" + kStep,
               "*SURFACE, NAME=s", "surface S is defined twice (first at");
  expect_error("surface_empty.inp", base + "*SURFACE, NAME=S\n" + kStep, "*SURFACE",
               "surface S is empty");
  expect_error("surface_type.inp", base + "*SURFACE, NAME=S, TYPE=CUTTING SURFACE\n1, S1\n" + kStep,
               "*SURFACE", "TYPE=CUTTING SURFACE is not supported");
  expect_error("surface_elset.inp", base + "*SURFACE, NAME=S\nC, S1\n" + kStep, "C, S1",
               "element set C is not defined");
  expect_error("surface_no_label.inp", base + "*SURFACE, NAME=S\n1\n" + kStep, "1\n*STEP",
               "expected element or element set, face label");
  expect_error("surface_in_step.inp", base + "*STEP\n*STATIC\n*SURFACE, NAME=S\n1, S1\n*END STEP\n",
               "*SURFACE", "*SURFACE is not allowed inside a step");
}

TEST(ContactInput, FrictionErrors) {
  const std::string base = std::string(kTwoBlocks);
  expect_error("friction_outside.inp", base + "*FRICTION\n0.2\n" + kStep, "*FRICTION",
               "*FRICTION must follow *SURFACE INTERACTION");
  // A *FRICTION after another keyword no longer belongs to the interaction above.
  expect_error(
      "friction_after_surface.inp",
      base + "*SURFACE INTERACTION, NAME=I\n*SURFACE, NAME=S\n1, S1\n*FRICTION\n0.2\n" + kStep,
      "*FRICTION", "*FRICTION must follow *SURFACE INTERACTION");
  expect_error("friction_negative.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION\n-0.2\n" + kStep, "-0.2",
               "friction coefficient mu must not be negative");
  expect_error("friction_rough_mu.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION, ROUGH\n0.2\n" + kStep, "0.2",
               "ROUGH means no slip at all: it takes no friction coefficient");
  expect_error("friction_aniso_no_orientation.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION, ANISOTROPIC\n0.1, 0.2\n" + kStep,
               "*FRICTION", "ANISOTROPIC needs ORIENTATION=");
  expect_error("friction_aniso_one_mu.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION, ANISOTROPIC, ORIENTATION=O\n0.1\n" +
                   "*ORIENTATION, NAME=O\n1., 0., 0., 0., 1., 0.\n" + kStep,
               "0.1\n", "expected mu1, mu2");
  expect_error("friction_orientation_undefined.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION, ANISOTROPIC, ORIENTATION=O\n" +
                   "0.1, 0.2\n" + kStep,
               "*FRICTION", "ORIENTATION=O of *FRICTION is not defined; orientations: none");
  expect_error("friction_orientation_isotropic.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION, ORIENTATION=O\n0.1\n" + kStep,
               "*FRICTION", "add ANISOTROPIC or remove ORIENTATION=");
  expect_error("friction_rough_aniso.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION, ROUGH, ANISOTROPIC\n" + kStep,
               "*FRICTION", "exclude each other");
  expect_error("friction_twice.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION\n0.1\n*FRICTION\n0.2\n" + kStep,
               "*FRICTION\n0.2", "already has *FRICTION");
  expect_error("friction_stick_slope.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*FRICTION\n0.1, 0.\n" + kStep, "0.1, 0.",
               "stick slope must be positive");
  expect_error("behavior_tabular.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, " +
                   "PRESSURE-OVERCLOSURE=TABULAR\n0., 0.\n1., 1.\n" + kStep,
               "*SURFACE BEHAVIOR", "TABULAR pressure-overclosure tables are not supported");
  expect_error("interaction_twice.inp",
               base + "*SURFACE INTERACTION, NAME=I\n*SURFACE INTERACTION, NAME=i\n" + kStep,
               "*SURFACE INTERACTION, NAME=i", "surface interaction I is defined twice");
}

TEST(ContactInput, ContactPairReferencesAreCheckedAtTheEndWithTheirLine) {
  const std::string surfaces = std::string(kTwoBlocks) +
                               "*SURFACE, NAME=A_TOP\n1, S2\n*SURFACE, NAME=B_BOTTOM\n2, S1\n" +
                               "*SURFACE, NAME=B_NODES, TYPE=NODE\nB_BOTTOM\n";
  const std::string interaction = "*SURFACE INTERACTION, NAME=I\n";
  expect_error("pair_unknown_surface.inp",
               surfaces + "*CONTACT PAIR, INTERACTION=I\nB_BOTOM, A_TOP\n" + interaction + kStep,
               "B_BOTOM, A_TOP",
               "names surface B_BOTOM, which is not defined; surfaces: A_TOP, B_BOTTOM, B_NODES");
  expect_error("pair_unknown_interaction.inp",
               surfaces + "*CONTACT PAIR, INTERACTION=J\nB_BOTTOM, A_TOP\n" + interaction + kStep,
               "B_BOTTOM, A_TOP", "INTERACTION=J of *CONTACT PAIR is not defined");
  expect_error("pair_node_master.inp",
               surfaces + interaction + "*CONTACT PAIR, INTERACTION=I\nA_TOP, B_NODES\n" + kStep,
               "A_TOP, B_NODES", "master surface B_NODES is a node surface");
  expect_error("pair_s2s_node_slave.inp",
               surfaces + interaction +
                   "*CONTACT PAIR, INTERACTION=I, TYPE=SURFACE TO SURFACE\nB_NODES, A_TOP\n" +
                   kStep,
               "B_NODES, A_TOP", "TYPE=SURFACE TO SURFACE needs element faces on both sides");
  expect_error("pair_self.inp",
               surfaces + interaction + "*CONTACT PAIR, INTERACTION=I\nA_TOP, A_TOP\n" + kStep,
               "A_TOP, A_TOP", "is both slave and master");
  expect_error("pair_no_data.inp",
               surfaces + interaction + "*CONTACT PAIR, INTERACTION=I\n" + kStep, "*CONTACT PAIR",
               "needs a data line: slave surface, master surface");
  expect_error("pair_linmortar.inp",
               surfaces + interaction +
                   "*CONTACT PAIR, INTERACTION=I, TYPE=LINMORTAR\nB_BOTTOM, A_TOP\n" + kStep,
               "*CONTACT PAIR",
               "TYPE=LINMORTAR is not supported; expected NODE TO SURFACE, SURFACE TO SURFACE or "
               "MORTAR");
  expect_error("pair_mortar_nodes.inp",
               surfaces + interaction +
                   "*CONTACT PAIR, INTERACTION=I, TYPE=MORTAR\nB_NODES, A_TOP\n" + kStep,
               "B_NODES, A_TOP", "TYPE=MORTAR needs element faces on both sides");
  expect_error("pair_adjust_negative.inp",
               surfaces + interaction +
                   "*CONTACT PAIR, INTERACTION=I, ADJUST=-1.\nB_BOTTOM, A_TOP\n" + kStep,
               "*CONTACT PAIR", "must not be negative");
  expect_error("pair_adjust_set.inp",
               surfaces + interaction +
                   "*CONTACT PAIR, INTERACTION=I, ADJUST=NOPE\nB_BOTTOM, A_TOP\n" + kStep,
               "*CONTACT PAIR", "ADJUST=NOPE of *CONTACT PAIR: node set is not defined");
  expect_error("pair_needs_interaction.inp",
               surfaces + interaction + "*CONTACT PAIR\nB_BOTTOM, A_TOP\n" + kStep, "*CONTACT PAIR",
               "*CONTACT PAIR needs INTERACTION=");
  const std::string pair =
      surfaces + interaction + "*CONTACT PAIR, INTERACTION=I\nB_BOTTOM, A_TOP\n";
  expect_error("clearance_no_pair.inp",
               pair + "*CLEARANCE, SLAVE=A_TOP, MASTER=B_BOTTOM, VALUE=0.1\n" + kStep, "*CLEARANCE",
               "no *CONTACT PAIR has them; pairs: B_BOTTOM, A_TOP");
  expect_error("clearance_twice.inp",
               pair + "*CLEARANCE, SLAVE=B_BOTTOM, MASTER=A_TOP, VALUE=0.1\n" +
                   "*CLEARANCE, SLAVE=B_BOTTOM, MASTER=A_TOP, VALUE=0.2\n" + kStep,
               "VALUE=0.2", "already has a *CLEARANCE");
  expect_error("clearance_value.inp",
               pair + "*CLEARANCE, SLAVE=B_BOTTOM, MASTER=A_TOP, VALUE=small\n" + kStep,
               "*CLEARANCE", "VALUE= of *CLEARANCE");
}

TEST(ContactInput, ContactPrintVariablesAndPlace) {
  const std::string base = std::string(kTwoBlocks);
  expect_error("contact_print_cels.inp",
               base + "*STEP\n*STATIC\n*CONTACT PRINT\nCSTR, CELS\n*END STEP\n", "CSTR, CELS",
               "output variable 'CELS' is not supported by *CONTACT PRINT; Styk writes CSTR, "
               "CDIS, CSTATUS (Styk does not write the contact elastic energy)");
  expect_error("contact_print_empty.inp", base + "*STEP\n*STATIC\n*CONTACT PRINT\n*END STEP\n",
               "*CONTACT PRINT", "*CONTACT PRINT needs a data line naming the variables");
  expect_error("contact_print_model.inp", base + "*CONTACT PRINT\nCSTR\n" + kStep, "*CONTACT PRINT",
               "*CONTACT PRINT is only allowed inside a step");
}

}  // namespace
}  // namespace styk
