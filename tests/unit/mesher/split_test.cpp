// Bricks split into tetrahedra and wedges (mesher/split.hpp): piece counts, conformity (every
// interior face shared by exactly two pieces with the same nodes), volume, no free nodes, the
// pieces' Jacobians positive, surfaces and element sets carried over, and a node numbering that
// runs every which way (the face rules depend on the face alone).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/split.hpp"

namespace styk::mesher {
namespace {

const test::Elements& elements() {
  static const test::Elements instance;
  return instance;
}
const ElementRegistry& registry() { return elements().registry; }

// A 3 x 2 x 2 block on [0,3] x [0,2] x [0,1] with a curved top (z (1 + 0.05 x y)): volume
// 6 + 0.05 * 2 * (9/2)(2) / 2 ... computed by quadrature below.
Mesh block(const std::string& type) {
  Mesh mesh;
  const BlockMap map = [](const Vec3& xi) {
    const double x = 1.5 * (xi[0] + 1), y = xi[1] + 1, z = 0.5 * (xi[2] + 1);
    return Vec3{x, y, z * (1 + 0.05 * x * y)};
  };
  const Block b = mesh_block(mesh, map, {type, {3, 2, 2}, {1, 1, 1}, "EALL"});
  mesh.add_to_surface("TOP", b.side_faces(2, +1));
  mesh.add_to_surface("XMIN", b.side_faces(0, -1));
  return mesh;
}

// The same mesh with its nodes renumbered at random.
void shuffle_nodes(Mesh& mesh, unsigned seed) {
  std::vector<int> order(mesh.nodes.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  mesh.renumber_nodes(order, static_cast<int>(order.size()));
}

void expect_valid(const Mesh& mesh, double volume) {
  const Model model = to_model(mesh);
  EXPECT_NEAR(test::volume(model, registry()), volume, 1e-12 * volume);
  EXPECT_EQ(test::conformity_problem(model, registry()), "");
  EXPECT_EQ(test::free_nodes(model), 0);
}

double block_volume(const std::string& type) {
  const Mesh mesh = block(type);
  return test::volume(to_model(mesh), registry());
}

TEST(Split, BricksIntoSixTetrahedra) {
  for (const char* brick : {"C3D8", "C3D20"}) {
    const std::string tet = std::string(brick) == "C3D8" ? "C3D4" : "C3D10";
    Mesh mesh = block(brick);
    const std::size_t bricks = mesh.elements.size();
    EXPECT_EQ(split_to_tetrahedra(mesh, registry(), tet), 0);  // structured: no centre nodes
    EXPECT_EQ(mesh.elements.size(), 6 * bricks);
    EXPECT_EQ(mesh.element_sets.at("EALL").size(), 6 * bricks);
    for (const MeshElement& e : mesh.elements) EXPECT_EQ(e.type, tet);
    // A brick face becomes two triangles: 6 top faces, 4 side faces.
    EXPECT_EQ(mesh.surfaces.at("TOP").size(), 12u);
    EXPECT_EQ(mesh.surfaces.at("XMIN").size(), 8u);
    for (int n : mesh.surface_nodes("TOP"))
      EXPECT_NEAR(mesh.nodes[n][2], 1 + 0.05 * mesh.nodes[n][0] * mesh.nodes[n][1], 1e-12);
    // C3D8 -> C3D4 keeps the nodes; the flat pieces of a curved brick have the same volume only
    // where the brick is flat, so the volume is compared for the quadratic split alone (C3D10 on
    // the C3D20 geometry reproduces its bilinear top exactly).
    if (tet == "C3D10")
      expect_valid(mesh, block_volume(brick));
    else {
      const Model model = to_model(mesh);
      EXPECT_EQ(test::conformity_problem(model, registry()), "");
      EXPECT_GT(test::volume(model, registry()), 0.0);
    }
  }
}

TEST(Split, AnyNodeNumberingStaysConforming) {
  for (unsigned seed : {1u, 2u, 3u}) {
    Mesh mesh = block("C3D20");
    shuffle_nodes(mesh, seed);
    const int centred = split_to_tetrahedra(mesh, registry(), "C3D10");
    // 12 bricks: those whose opposite faces are not cut in parallel got a centre node and 12
    // pieces.
    EXPECT_EQ(mesh.elements.size(), static_cast<std::size_t>(6 * (12 - centred) + 12 * centred));
    expect_valid(mesh, block_volume("C3D20"));
  }
}

TEST(Split, BricksIntoTwoWedges) {
  for (const char* brick : {"C3D8", "C3D20"}) {
    const std::string wedge = std::string(brick) == "C3D8" ? "C3D6" : "C3D15";
    for (int axis : {0, 1, 2}) {
      Mesh mesh = block(brick);
      shuffle_nodes(mesh, 7);
      split_to_wedges(mesh, registry(), wedge, axis);
      EXPECT_EQ(mesh.elements.size(), 24u);
      const Model model = to_model(mesh);
      EXPECT_EQ(test::conformity_problem(model, registry()), "") << brick << " axis " << axis;
      EXPECT_EQ(test::free_nodes(model), 0);
      if (wedge == "C3D15") {
        EXPECT_NEAR(test::volume(model, registry()), block_volume(brick),
                    1e-12 * block_volume(brick));
      }
      // The top faces: whole quadrilaterals on wedge sides, or two triangles each when the wedge
      // axis is z (the triangles lie in the top).
      EXPECT_EQ(mesh.surfaces.at("TOP").size(), axis == 2 ? 12u : 6u);
    }
  }
}

TEST(Split, UnknownOrUnfitTypesAreRefused) {
  Mesh mesh = block("C3D8");
  EXPECT_THROW(split_to_tetrahedra(mesh, registry(), "C3D99"), std::invalid_argument);
  EXPECT_THROW(split_to_tetrahedra(mesh, registry(), "C3D8"), std::invalid_argument);
  EXPECT_THROW(split_to_wedges(mesh, registry(), "C3D4"), std::invalid_argument);
  EXPECT_THROW(split_to_wedges(mesh, registry(), "C3D6", 3), std::invalid_argument);
}

}  // namespace
}  // namespace styk::mesher
