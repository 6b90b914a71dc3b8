// Element conversion: C3D8 -> C3D14, C3D20 layers -> C3D21 / C3D28 (re-orientation so the face
// becomes S1, closure of the C3D28 layer), C3D20 -> C3D20R.
#include <cmath>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/hex_topology.hpp"

namespace styk::mesher {
namespace {

// A 2 x 2 x 2 C3D20 block on [0,2] x [0,2] x [0,1] with a slightly curved top (so positions on
// the C3D20 geometry are not just averages).
Mesh cube_block(const std::string& type, Block* out = nullptr) {
  Mesh mesh;
  const BlockMap map = [](const Vec3& xi) {
    const double x = xi[0] + 1, y = xi[1] + 1, z = 0.5 * (xi[2] + 1);
    return Vec3{x, y, z * (1 + 0.05 * x * y)};
  };
  const Block b = mesh_block(mesh, map, {type, {2, 2, 2}, {1, 1, 1}, "EALL"});
  mesh.add_to_surface("TOP", b.side_faces(2, +1));
  mesh.add_to_surface("XMAX", b.side_faces(0, +1));
  if (out) *out = b;
  return mesh;
}

void expect_valid(const Mesh& mesh) {
  const test::Elements elements;
  const Model model = to_model(mesh);
  EXPECT_GT(test::volume(model, elements.registry), 0.0);
  EXPECT_EQ(test::conformity_problem(model, elements.registry), "");
  EXPECT_EQ(test::free_nodes(model), 0);
}

TEST(Rotation, EveryFaceCanBecomeTheBottom) {
  for (int f = 0; f < 6; ++f) {
    const CubeRotation R = rotation_to_bottom(f);
    EXPECT_EQ(rotated_face(R, f), 0) << f;
    const std::vector<int> perm = rotated_numbering("C3D20", R);
    // The new S1 nodes are exactly the old face f nodes.
    std::vector<int> new_bottom;
    for (int local : face_local_nodes("C3D20", 0)) new_bottom.push_back(perm[local]);
    std::vector<int> old_face = face_local_nodes("C3D20", f);
    std::sort(new_bottom.begin(), new_bottom.end());
    EXPECT_EQ(new_bottom, old_face) << f;
  }
}

TEST(Convert, C3D8ToC3D14SharesFaceCentres) {
  Mesh mesh = cube_block("C3D8");
  const std::size_t nodes = mesh.nodes.size();
  convert_to_c3d14(mesh);
  // 2x2x2 elements: faces = 3 * 2*2*3 = 36, one centre node each.
  EXPECT_EQ(mesh.nodes.size(), nodes + 36);
  for (const MeshElement& e : mesh.elements) EXPECT_EQ(e.type, "C3D14");
  expect_valid(mesh);
}

TEST(Convert, C3D21LayerOnAnyFace) {
  for (const char* surface : {"TOP", "XMAX"}) {
    Mesh mesh = cube_block("C3D20");
    const std::size_t nodes = mesh.nodes.size();
    convert_layer_to_c3d21(mesh, surface);
    EXPECT_EQ(mesh.nodes.size(), nodes + 4);
    int c3d21 = 0;
    for (const MeshElement& e : mesh.elements) c3d21 += e.type == "C3D21";
    EXPECT_EQ(c3d21, 4);
    for (const FaceRef& f : mesh.surfaces.at(surface)) EXPECT_EQ(f.face, 0);
    // The face-centre node lies on the C3D20 face (z = 1.05... at the curved top).
    const FaceRef f = mesh.surfaces.at(surface)[0];
    const MeshElement& e = mesh.elements[f.element];
    const Vec3& centre = mesh.nodes[e.nodes[20]];
    if (std::string(surface) == "TOP") {
      EXPECT_NEAR(centre[2], 1 + 0.05 * centre[0] * centre[1], 1e-3);
    } else {
      EXPECT_NEAR(centre[0], 2.0, 1e-14);
    }
    expect_valid(mesh);
  }
}

TEST(Convert, OtherSurfacesFollowTheReorientation) {
  Mesh mesh = cube_block("C3D20");
  convert_layer_to_c3d21(mesh, "XMAX");
  // The TOP faces of the converted elements are still the faces at the top.
  for (const FaceRef& f : mesh.surfaces.at("TOP")) {
    const MeshElement& e = mesh.elements[f.element];
    for (int local : face_local_nodes(e.type, f.face))
      EXPECT_GT(mesh.nodes[e.nodes[local]][2], 0.99);
  }
}

TEST(Convert, C3D28LayerReplacesMidEdgesByGllNodes) {
  Mesh mesh = cube_block("C3D20");
  const std::size_t nodes = mesh.nodes.size();
  const std::vector<int> converted = convert_layer_to_c3d28(mesh, "TOP");
  EXPECT_EQ(converted.size(), 4u);
  // Top face of the block: 12 mid-edge nodes removed; 2 GLL nodes on each of the 12 edges and
  // 4 interior nodes on each of the 4 faces added.
  EXPECT_EQ(mesh.nodes.size(), nodes - 12 + 24 + 16);
  const double a = 1 / std::sqrt(5.0);
  const MeshElement& e = mesh.elements[converted[0]];
  ASSERT_EQ(e.type, "C3D28");
  // Node 17 sits at xi = -a on the edge 1-2 of the (new) bottom face.
  const Vec3& n1 = mesh.nodes[e.nodes[0]];
  const Vec3& n2 = mesh.nodes[e.nodes[1]];
  const Vec3& n17 = mesh.nodes[e.nodes[16]];
  const double t =
      std::hypot(n17[0] - n1[0], n17[1] - n1[1]) / std::hypot(n2[0] - n1[0], n2[1] - n1[1]);
  EXPECT_NEAR(t, (1 - a) / 2, 1e-12);
  expect_valid(mesh);
}

TEST(Convert, C3D28LayerIsClosedOverItsSideNeighbours) {
  // Only one element of the top face named: its three top-face neighbours that border it join.
  Mesh mesh = cube_block("C3D20");
  const FaceRef one = mesh.surfaces.at("TOP")[0];
  mesh.surfaces["ONE"] = {one};
  const std::vector<int> converted = convert_layer_to_c3d28(mesh, "ONE");
  EXPECT_EQ(converted.size(), 4u);
  EXPECT_EQ(mesh.surfaces.at("ONE").size(), 4u);
  expect_valid(mesh);
}

TEST(Convert, C3D28LayerThatCannotCloseIsAnErrorNamingTheElement) {
  // A layer on an interior face set: the side neighbour has no free face along the edge.
  Block b(1, {1, 1, 1}, {}, {});
  Mesh mesh = cube_block("C3D20", &b);
  mesh.surfaces["MID"] = {{b.element_at(0, 0, 0), 1}};  // S2 of a bottom element: interior face
  try {
    convert_layer_to_c3d28(mesh, "MID");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be closed: element"), std::string::npos)
        << e.what();
  }
}

TEST(Convert, C3D20RIsANameChangeAndBadInputIsRefused) {
  Mesh mesh = cube_block("C3D20");
  const auto before = mesh.elements[0].nodes;
  convert_to_c3d20r(mesh);
  EXPECT_EQ(mesh.elements[0].type, "C3D20R");
  EXPECT_EQ(mesh.elements[0].nodes, before);
  EXPECT_THROW(convert_to_c3d14(mesh, {0}), std::invalid_argument);  // a C3D20R
  EXPECT_THROW(convert_layer_to_c3d21(mesh, "NOPE"), std::invalid_argument);
  EXPECT_THROW(convert_layer_to_c3d21(mesh, "TOP"), std::invalid_argument);  // not C3D20 any more
}

}  // namespace
}  // namespace styk::mesher
