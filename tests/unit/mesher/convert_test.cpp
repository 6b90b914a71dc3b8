// Element conversion as the target types describe it (TElement::conversion()): C3D8 -> C3D14,
// C3D20 layers -> C3D21 / C3D28 (re-orientation so the face becomes S1, closure of the C3D28
// layer), C3D20 -> C3D20R, and a test plug-in type the mesher converts with no code of its own.
#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/hex_topology.hpp"
#include "support/element_registries.hpp"

namespace styk::mesher {
namespace {

const test::Elements& elements() {
  static const test::Elements instance;
  return instance;
}
const ElementRegistry& registry() { return elements().registry; }

std::vector<int> convert(Mesh& mesh, const std::string& type, const std::string& surface = "",
                         const std::vector<int>& which = {}) {
  return convert_elements(mesh, registry(), type, surface, which);
}

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
  const Model model = to_model(mesh);
  EXPECT_GT(test::volume(model, registry()), 0.0);
  EXPECT_EQ(test::conformity_problem(model, registry()), "");
  EXPECT_EQ(test::free_nodes(model), 0);
}

// Every face of a brick can become the contact face: the converted element's S1 carries exactly
// the nodes of the old face (and the element stays right-handed: expect_valid).
TEST(Convert, EveryFaceCanBecomeTheContactFace) {
  for (int f = 0; f < 6; ++f) {
    Mesh mesh;
    const Block b = mesh_block(mesh, [](const Vec3& xi) { return xi; },
                               {"C3D20", {1, 1, 1}, {1, 1, 1}, "EALL"});
    const std::vector<int> old_face_nodes = [&] {
      std::vector<int> nodes;
      for (int local : face_local_nodes("C3D20", f)) nodes.push_back(mesh.elements[0].nodes[local]);
      std::sort(nodes.begin(), nodes.end());
      return nodes;
    }();
    std::vector<Vec3> old_positions;
    for (int n : old_face_nodes) old_positions.push_back(mesh.nodes[n]);
    mesh.surfaces["F"] = {{b.element_at(0, 0, 0), f}};
    convert(mesh, "C3D21", "F");
    const MeshElement& e = mesh.elements[0];
    ASSERT_EQ(e.type, "C3D21");
    EXPECT_EQ(mesh.surfaces.at("F"), (std::vector<FaceRef>{{0, 0}})) << f;
    // S1 of C3D21: the 4 corners, 4 mid-edges and the centre node 21; the first 8 sit where the
    // old face's nodes were.
    const std::vector<int>& s1 = mesh.faces_of_type.at("C3D21")[0];
    ASSERT_EQ(s1.size(), 9u);
    for (int k = 0; k < 8; ++k) {
      const Vec3& x = mesh.nodes[e.nodes[s1[k]]];
      EXPECT_TRUE(std::any_of(
          old_positions.begin(), old_positions.end(),
          [&](const Vec3& p) { return std::hypot(p[0] - x[0], p[1] - x[1], p[2] - x[2]) < 1e-14; }))
          << "face " << f << " node " << s1[k];
    }
    expect_valid(mesh);
  }
}

TEST(Convert, C3D8ToC3D14SharesFaceCentres) {
  Mesh mesh = cube_block("C3D8");
  const std::size_t nodes = mesh.nodes.size();
  convert(mesh, "C3D14");
  // 2x2x2 elements: faces = 3 * 2*2*3 = 36, one centre node each.
  EXPECT_EQ(mesh.nodes.size(), nodes + 36);
  for (const MeshElement& e : mesh.elements) EXPECT_EQ(e.type, "C3D14");
  expect_valid(mesh);
}

TEST(Convert, C3D21LayerOnAnyFace) {
  for (const char* surface : {"TOP", "XMAX"}) {
    Mesh mesh = cube_block("C3D20");
    const std::size_t nodes = mesh.nodes.size();
    convert(mesh, "C3D21", surface);
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
  convert(mesh, "C3D21", "XMAX");
  // The TOP faces of the converted elements are still the faces at the top.
  for (const FaceRef& f : mesh.surfaces.at("TOP")) {
    const MeshElement& e = mesh.elements[f.element];
    for (int local : mesh.faces_of_type.at(e.type)[f.face])
      EXPECT_GT(mesh.nodes[e.nodes[local]][2], 0.99);
  }
}

TEST(Convert, C3D28LayerReplacesMidEdgesByGllNodes) {
  Mesh mesh = cube_block("C3D20");
  const std::size_t nodes = mesh.nodes.size();
  const std::vector<int> converted = convert(mesh, "C3D28", "TOP");
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
  const std::vector<int> converted = convert(mesh, "C3D28", "ONE");
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
    convert(mesh, "C3D28", "MID");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be closed: element"), std::string::npos)
        << e.what();
  }
}

TEST(Convert, C3D20RIsANameChangeAndBadInputIsRefused) {
  Mesh mesh = cube_block("C3D20");
  const auto before = mesh.elements[0].nodes;
  convert(mesh, "C3D20R");
  EXPECT_EQ(mesh.elements[0].type, "C3D20R");
  EXPECT_EQ(mesh.elements[0].nodes, before);
  EXPECT_THROW(convert(mesh, "C3D14", "", {0}), std::invalid_argument);  // a C3D20R
  EXPECT_THROW(convert(mesh, "C3D21", "NOPE"), std::invalid_argument);
  EXPECT_THROW(convert(mesh, "C3D21", "TOP"), std::invalid_argument);  // not C3D20 any more
  EXPECT_THROW(convert(mesh, "C3D8"), std::invalid_argument);          // describes no conversion
  EXPECT_THROW(convert(mesh, "C3D99"), std::invalid_argument);         // not registered
}

// A type the mesher has never heard of converts because it describes itself: a 27-node brick
// made from C3D20 bricks by adding face and body centres (the C3D27 layout under another name,
// registered as a plug-in would).
class Brick27FromC3D20 : public TElement {
 public:
  explicit Brick27FromC3D20(const TElement& c3d27) : c3d27_(c3d27) {}
  std::string name() const override { return "TEST27"; }
  std::string description() const override { return "test plug-in"; }
  int node_count() const override { return 27; }
  const std::vector<Vec3>& natural_nodes() const override { return c3d27_.natural_nodes(); }
  const std::vector<FaceDef>& faces() const override { return c3d27_.faces(); }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override {
    c3d27_.der(xi, N, dN);
  }
  IntegrationRule rule(RuleKind kind) const override { return c3d27_.rule(kind); }
  int face_rule_order() const override { return 3; }
  std::optional<ElementConversion> conversion() const override {
    return ElementConversion{"C3D20", -1};
  }

 private:
  const TElement& c3d27_;
};

TEST(Convert, APluginTypeConvertsFromItsOwnDescription) {
  ElementRegistry local = test::builtin_registry();
  local.add(std::make_unique<Brick27FromC3D20>(*local.find("C3D27")), "test plug-in");
  EXPECT_EQ(conversions_from(local, "C3D20"),
            (std::vector<std::string>{"C3D20R", "C3D27", "TEST27"}));
  Mesh mesh = cube_block("C3D20");
  const std::size_t nodes = mesh.nodes.size();
  convert_elements(mesh, local, "TEST27");
  // 2x2x2 bricks: 36 faces, each with one shared centre node, and 8 body centres.
  EXPECT_EQ(mesh.nodes.size(), nodes + 36 + 8);
  // The face centres lie on the C3D20 geometry: the top one on the curved top surface.
  const FaceRef top = mesh.surfaces.at("TOP")[0];
  const Vec3& centre = mesh.nodes[mesh.elements[top.element].nodes[21]];  // S2 centre
  EXPECT_NEAR(centre[2], 1 + 0.05 * centre[0] * centre[1], 2e-3);
  const Model model = to_model(mesh);
  EXPECT_GT(test::volume(model, local), 0.0);
  EXPECT_EQ(test::conformity_problem(model, local), "");
}

}  // namespace
}  // namespace styk::mesher
