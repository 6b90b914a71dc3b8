// Block meshing (counts, grid addresses, sides) and node merging across blocks.
#include <gtest/gtest.h>

#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher {
namespace {

BlockMap box(const Vec3& origin, const Vec3& size) {
  std::vector<Vec3> c;
  for (const Vec3& n : std::vector<Vec3>{
           {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}})
    c.push_back(
        {origin[0] + n[0] * size[0], origin[1] + n[1] * size[1], origin[2] + n[2] * size[2]});
  return hex_map(c);
}

TEST(Block, CountsAndSidesOfC3D8AndC3D20) {
  Mesh m8;
  const Block b8 =
      mesh_block(m8, box({0, 0, 0}, {3, 2, 1}), {"C3D8", {3, 2, 1}, {1, 1, 1}, "EALL"});
  EXPECT_EQ(m8.elements.size(), 6u);
  EXPECT_EQ(m8.nodes.size(), 4u * 3 * 2);
  EXPECT_EQ(b8.side_nodes(0, +1).size(), 6u);
  EXPECT_EQ(b8.side_faces(2, -1).size(), 6u);
  EXPECT_EQ(b8.side_faces(2, -1)[0].face, 0);  // S1
  EXPECT_EQ(b8.side_faces(0, +1)[0].face, 3);  // S4
  EXPECT_EQ(m8.element_sets.at("EALL").size(), 6u);

  Mesh m20;
  const Block b20 = mesh_block(m20, box({0, 0, 0}, {3, 2, 1}), {"C3D20", {3, 2, 1}, {2, 1, 1}, ""});
  // Serendipity grid 7 x 5 x 3 minus face/body centres.
  int expected = 0;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 7; ++i) expected += (i % 2) + (j % 2) + (k % 2) <= 1;
  EXPECT_EQ(static_cast<int>(m20.nodes.size()), expected);
  EXPECT_EQ(b20.node_at(1, 1, 0), -1);  // a face centre: no C3D20 node
  // Grading 2 along x: the last element is twice the first; mid-edge nodes at parameter midpoints.
  const double x1 = m20.nodes[b20.node_at(2, 0, 0)][0],
               x3 = m20.nodes[b20.node_at(6, 0, 0)][0] - m20.nodes[b20.node_at(4, 0, 0)][0];
  EXPECT_NEAR(x3 / x1, 2.0, 1e-12);
  EXPECT_NEAR(m20.nodes[b20.node_at(1, 0, 0)][0], x1 / 2, 1e-12);
  EXPECT_THROW(mesh_block(m20, box({0, 0, 0}, {1, 1, 1}), {"C3D10", {1, 1, 1}, {1, 1, 1}, ""}),
               std::invalid_argument);
  EXPECT_THROW(mesh_block(m20, box({0, 0, 0}, {1, 1, 1}), {"C3D8", {0, 1, 1}, {1, 1, 1}, ""}),
               std::invalid_argument);
}

TEST(Merge, TwoBlocksShareTheirFaceNodes) {
  Mesh mesh;
  mesh_block(mesh, box({0, 0, 0}, {1, 1, 1}), {"C3D20", {2, 2, 2}, {1, 1, 1}, "A"});
  mesh_block(mesh, box({1, 0, 0}, {1, 1, 1}), {"C3D20", {2, 2, 2}, {1, 1, 1}, "B"});
  mesh.add_to_node_set("ALL", [&] {
    std::vector<int> v(mesh.nodes.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int>(i);
    return v;
  }());
  const std::size_t before = mesh.nodes.size();
  // The shared face x = 1 of a 2 x 2 C3D20 side: 5 x 5 grid minus 4 centres = 21 nodes.
  EXPECT_EQ(merge_coincident_nodes(mesh), 21);
  EXPECT_EQ(mesh.nodes.size(), before - 21);
  EXPECT_EQ(mesh.node_sets.at("ALL").size(), mesh.nodes.size());
  // A second merge finds nothing; every element still has distinct nodes.
  EXPECT_EQ(merge_coincident_nodes(mesh), 0);
  EXPECT_EQ(mesh.remove_unused_nodes(), 0);
}

// An interface pair that loses a node when unused nodes go is dropped, the other pairs follow the
// renumbering: no pair may keep a -1 (the next renumbering would index old_to_new[-1], which ASan
// caught in the C3D28 bolted flange, whose two contact layers each remove their C3D20 mid-edges).
TEST(Merge, RemovingUnusedNodesDropsTheirInterfacePairs) {
  Mesh mesh;
  mesh_block(mesh, box({0, 0, 0}, {1, 1, 1}), {"C3D8", {1, 1, 1}, {1, 1, 1}, ""});
  const int stray = mesh.add_node({5, 5, 5});
  mesh.interfaces.push_back({"I", {{0, 1}, {2, stray}, {6, 7}}, "A", "B"});
  EXPECT_EQ(mesh.remove_unused_nodes(), 1);
  ASSERT_EQ(mesh.interfaces[0].pairs.size(), 2u);
  EXPECT_EQ(mesh.interfaces[0].pairs[0], std::make_pair(0, 1));
  EXPECT_EQ(mesh.interfaces[0].pairs[1], std::make_pair(6, 7));
  // A second removal with a pair on a node before the removed one: indices shift down by one.
  mesh.nodes.insert(mesh.nodes.begin(), Vec3{9, 9, 9});
  for (MeshElement& e : mesh.elements)
    for (int& n : e.nodes) ++n;
  for (auto& [a, b] : mesh.interfaces[0].pairs) ++a, ++b;
  EXPECT_EQ(mesh.remove_unused_nodes(), 1);
  ASSERT_EQ(mesh.interfaces[0].pairs.size(), 2u);
  EXPECT_EQ(mesh.interfaces[0].pairs[1], std::make_pair(6, 7));
}

TEST(Merge, ToleranceIsRelativeToTheModelSize) {
  for (double scale : {1e-3, 1.0, 1e4}) {
    Mesh mesh;
    mesh_block(mesh, box({0, 0, 0}, {scale, scale, scale}), {"C3D8", {1, 1, 1}, {1, 1, 1}, ""});
    mesh_block(mesh, box({scale * (1 + 1e-10), 0, 0}, {scale, scale, scale}),
               {"C3D8", {1, 1, 1}, {1, 1, 1}, ""});
    EXPECT_EQ(merge_coincident_nodes(mesh), 4) << scale;
    Mesh apart;
    mesh_block(apart, box({0, 0, 0}, {scale, scale, scale}), {"C3D8", {1, 1, 1}, {1, 1, 1}, ""});
    mesh_block(apart, box({scale * 1.001, 0, 0}, {scale, scale, scale}),
               {"C3D8", {1, 1, 1}, {1, 1, 1}, ""});
    EXPECT_EQ(merge_coincident_nodes(apart), 0) << scale;
  }
}

TEST(Merge, CollapsingAnElementIsAnError) {
  Mesh mesh;
  mesh_block(mesh, box({0, 0, 0}, {1, 1, 1e-12}), {"C3D8", {1, 1, 1}, {1, 1, 1}, ""});
  EXPECT_THROW(merge_coincident_nodes(mesh, 1e-6), std::invalid_argument);
}

}  // namespace
}  // namespace styk::mesher
