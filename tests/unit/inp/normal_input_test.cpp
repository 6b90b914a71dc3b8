// read_inp on *NORMAL (CalculiX/Abaqus, TYPE=ELEMENT; docs/input.md): nodal normals of shell
// elements by element or element set and node or node set, written back by write_inp, and the
// refusals with their lines.
#include <gtest/gtest.h>

#include <sstream>

#include "deck_errors.hpp"
#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

namespace styk {
namespace {

using test::expect_error;
using test::fake_registry;
using test::write_deck;

// Two S4 shells sharing the edge 2-5, a C3D8 brick and a B31 beam for the refusals.
const char* const kMesh = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 2., 0., 0.
6, 2., 1., 0.
11, 0., 0., 5.
12, 1., 0., 5.
13, 1., 1., 5.
14, 0., 1., 5.
15, 0., 0., 6.
16, 1., 0., 6.
17, 1., 1., 6.
18, 0., 1., 6.
*ELEMENT, TYPE=S4, ELSET=PLATE
1, 1, 2, 3, 4
2, 2, 5, 6, 3
*ELEMENT, TYPE=C3D8, ELSET=BRICK
3, 11, 12, 13, 14, 15, 16, 17, 18
*ELEMENT, TYPE=B31, ELSET=BAR
4, 1, 5
*NSET, NSET=EDGE
2, 3
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL
0.1
*SOLID SECTION, ELSET=BRICK, MATERIAL=STEEL
*BEAM SECTION, ELSET=BAR, MATERIAL=STEEL, SECTION=RECT
0.1, 0.1
0., 0., 1.
)";
const char* const kStep = "*STEP\n*STATIC\n*END STEP\n";

Model read(const std::string& name, const std::string& text) {
  const ElementRegistry registry = fake_registry();
  return read_inp(write_deck(name, text), registry);
}

TEST(NormalInput, ElementAndNodeSetsExpandToEveryNodeTheElementsShare) {
  const Model m = read("normal_sets.inp", std::string(kMesh) +
                                              "*NORMAL\n"
                                              "1, 1, 0., 0., 2.\n"
                                              "PLATE, EDGE, 0.1, 0., 1.\n" +
                                              kStep);
  // Line 1: element 1 at node 1; line 2: nodes 2 and 3 of elements 1 and 2 (4 entries).
  ASSERT_EQ(m.normals.size(), 5u);
  EXPECT_EQ(m.elements[m.normals[0].element].id, 1);
  EXPECT_EQ(m.node_ids[m.normals[0].node], 1);
  EXPECT_EQ(m.normals[0].direction, (Vec3{0.0, 0.0, 2.0}));  // kept as given, not normalised
  int on_second_element = 0;
  for (std::size_t k = 1; k < m.normals.size(); ++k) {
    const Id node = m.node_ids[m.normals[k].node];
    EXPECT_TRUE(node == 2 || node == 3) << node;
    EXPECT_EQ(m.normals[k].direction, (Vec3{0.1, 0.0, 1.0}));
    on_second_element += m.elements[m.normals[k].element].id == 2;
  }
  EXPECT_EQ(on_second_element, 2);
}

TEST(NormalInput, WrittenDeckReadsBackTheSameNormals) {
  const Model m =
      read("normal_write.inp",
           std::string(kMesh) + "*NORMAL, TYPE=ELEMENT\n2, 5, 0.25, -0.5, 1.\n" + kStep);
  std::ostringstream out;
  write_inp(m, out);
  EXPECT_NE(out.str().find("*NORMAL\n2, 5, 0.25, -0.5, 1\n"), std::string::npos) << out.str();
  const Model back = read("normal_write_back.inp", out.str());
  ASSERT_EQ(back.normals.size(), 1u);
  EXPECT_EQ(back.elements[back.normals[0].element].id, 2);
  EXPECT_EQ(back.node_ids[back.normals[0].node], 5);
  EXPECT_EQ(back.normals[0].direction, (Vec3{0.25, -0.5, 1.0}));
}

// Abaqus' *NODE form: fields 5-7 give the normal at the node. It becomes a *NORMAL entry of
// every shell at the node (elements 1 and 2 share node 2; the beam there takes none), ahead of
// the deck's *NORMAL lines, which therefore win; a zero normal is no normal (CalculiX ignores
// the fields); written back as *NORMAL lines, which ccx reads.
TEST(NormalInput, NodeLinesCarryAbaqusNormals) {
  std::string mesh = kMesh;
  mesh.replace(mesh.find("2, 1., 0., 0.\n"), 14, "2, 1., 0., 0., 0., 0.1, 1.\n");
  mesh.replace(mesh.find("3, 1., 1., 0.\n"), 14, "3, 1., 1., 0., 0., 0., 0.\n");
  const Model m = read("node_normals.inp", mesh + "*NORMAL\n1, 2, 0., 0., 1.\n" + kStep);
  ASSERT_EQ(m.normals.size(), 3u);
  const int node2 = m.node_index(2);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(m.normals[k].element, k);
    EXPECT_EQ(m.normals[k].node, node2);
    EXPECT_EQ(m.normals[k].direction, (Vec3{0.0, 0.1, 1.0}));
    EXPECT_EQ(m.normals[k].where.line, 3);
  }
  EXPECT_EQ(m.normals[2].element, 0);
  EXPECT_EQ(m.normals[2].direction, (Vec3{0.0, 0.0, 1.0}));
  std::ostringstream written;
  write_inp(m, written);
  const Model back = read("node_normals_back.inp", written.str());
  ASSERT_EQ(back.normals.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(back.normals[k].direction, m.normals[k].direction) << k;
  // Node 11 belongs to the brick only: the normal would be lost.
  std::string brick = kMesh;
  brick.replace(brick.find("11, 0., 0., 5.\n"), 15, "11, 0., 0., 5., 0., 0., 1.\n");
  expect_error("node_normal_brick.inp", brick + kStep, "11, 0., 0., 5., 0., 0., 1.",
               "node 11 has a normal (fields 5-7) but belongs to no curved shell");
}

TEST(NormalInput, RefusesWhatItCannotUseAtTheLine) {
  const std::string mesh = kMesh;
  expect_error("normal_contact.inp", mesh + "*NORMAL, TYPE=CONTACT SURFACE\n1, 1, 0., 0., 1.\n",
               "*NORMAL, TYPE", "TYPE=CONTACT SURFACE is not supported");
  expect_error("normal_brick.inp", mesh + "*NORMAL\n3, 11, 0., 0., 1.\n", "3, 11, 0.",
               "shell elements only");
  expect_error("normal_beam.inp", mesh + "*NORMAL\n4, 1, 0., 0., 1.\n", "4, 1, 0.",
               "*BEAM SECTION");
  expect_error("normal_foreign_node.inp", mesh + "*NORMAL\n1, 5, 0., 0., 1.\n", "1, 5, 0.",
               "names no node of 1");
  expect_error("normal_zero.inp", mesh + "*NORMAL\n1, 1, 0., 0., 0.\n", "1, 1, 0., 0., 0.",
               "must not be zero");
  expect_error("normal_fields.inp", mesh + "*NORMAL\n1, 1, 0., 1.\n", "1, 1, 0., 1.", "nx, ny, nz");
  expect_error("normal_empty.inp", mesh + "*NORMAL\n" + kStep, "*NORMAL", "needs data lines");
  expect_error("normal_undefined_set.inp", mesh + "*NORMAL\nNOSUCH, 1, 0., 0., 1.\n", "NOSUCH",
               "element set NOSUCH is not defined");
}

}  // namespace
}  // namespace styk
