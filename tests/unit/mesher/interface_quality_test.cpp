// Interface generation (split along the faces between a set and the rest) and the quality report.
#include <cmath>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/interface.hpp"
#include "styk/mesher/merge.hpp"
#include "styk/mesher/quality.hpp"

namespace styk::mesher {
namespace {

BlockMap box(const Vec3& o, const Vec3& s) {
  return [o, s](const Vec3& xi) {
    return Vec3{o[0] + s[0] * 0.5 * (xi[0] + 1), o[1] + s[1] * 0.5 * (xi[1] + 1),
                o[2] + s[2] * 0.5 * (xi[2] + 1)};
  };
}

TEST(Interface, SplitGivesCoincidentPairsAndFacingSurfaces) {
  // A punch (upper block, 2 x 2) on a foundation (lower block, 2 x 2), merged, then split.
  Mesh mesh;
  mesh_block(mesh, box({0, 0, 0}, {2, 2, 1}), {"C3D20", {2, 2, 1}, {1, 1, 1}, "FOUNDATION"});
  mesh_block(mesh, box({0, 0, 1}, {2, 2, 1}), {"C3D20", {2, 2, 1}, {1, 1, 1}, "PUNCH"});
  merge_coincident_nodes(mesh);
  const std::size_t nodes = mesh.nodes.size();
  const Interface& i = split_interface(mesh, "punch", "contact");
  // The plane z = 1: 5 x 5 grid minus 4 face centres = 21 node pairs.
  EXPECT_EQ(i.pairs.size(), 21u);
  EXPECT_EQ(mesh.nodes.size(), nodes + 21);
  for (const auto& [a, b] : i.pairs) {
    EXPECT_NE(a, b);
    EXPECT_EQ(mesh.nodes[a], mesh.nodes[b]);
    EXPECT_NEAR(mesh.nodes[a][2], 1.0, 1e-15);
  }
  EXPECT_EQ(mesh.surfaces.at("CONTACT_A").size(), 4u);
  EXPECT_EQ(mesh.surfaces.at("CONTACT_B").size(), 4u);
  // Each facing surface is S1 / S2 of its body: the punch's bottom, the foundation's top.
  for (const FaceRef& f : mesh.surfaces.at("CONTACT_A")) EXPECT_EQ(f.face, 0);
  for (const FaceRef& f : mesh.surfaces.at("CONTACT_B")) EXPECT_EQ(f.face, 1);
  // Two bodies now: no face is shared across the interface, nothing is free.
  const test::Elements elements;
  const Model model = to_model(mesh);
  EXPECT_EQ(test::conformity_problem(model, elements.registry), "");
  EXPECT_EQ(test::free_nodes(model), 0);
  // The interface faces convert to C3D21 on both sides (the thesis' contact layers).
  convert_elements(mesh, elements.registry, "C3D21", "CONTACT_A");
  convert_elements(mesh, elements.registry, "C3D21", "CONTACT_B");
  EXPECT_GT(test::volume(to_model(mesh), elements.registry), 7.999);
  EXPECT_THROW(split_interface(mesh, "NOPE", "X"), std::invalid_argument);
}

TEST(Quality, ReportsRatiosAndNamesAnInvertedElement) {
  const test::Elements elements;
  Mesh mesh;
  mesh_block(mesh, box({0, 0, 0}, {4, 1, 1}), {"C3D8", {1, 1, 1}, {1, 1, 1}, ""});
  Model model = to_model(mesh);
  QualityReport q = assess_quality(model, elements.registry);
  EXPECT_NEAR(q.max_aspect_ratio, 4.0, 1e-12);
  EXPECT_NEAR(q.min_jacobian_ratio, 1.0, 1e-12);
  EXPECT_NEAR(q.max_warping_deg, 0.0, 1e-6);
  EXPECT_NEAR(q.volume, 4.0, 1e-12);
  // Lift one top corner: the top face warps, the Jacobian varies.
  model.coords[model.element_nodes(0)[6]][2] = 1.5;
  q = assess_quality(model, elements.registry);
  EXPECT_GT(q.max_warping_deg, 1.0);
  EXPECT_LT(q.min_jacobian_ratio, 1.0);
  // Push a node through the opposite face: inverted, an InputError naming element 1.
  model.coords[model.element_nodes(0)[6]][2] = -3.0;
  try {
    assess_quality(model, elements.registry);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace styk::mesher
