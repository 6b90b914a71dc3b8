// resolve_shell_normals (styk/core/shell_normals.hpp, docs/elements.md "Nodal normals of
// shells"): averaging over the shells sharing a node within 20 degrees, folds beyond, *NORMAL
// lines replacing, reversing or warned of; models without curved shells resolve nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "styk/core/shell_normals.hpp"
#include "styk/elements/builtin.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Mesh {
  Model model;
  std::vector<const TElement*> formulation;
};

int add_node(Model& m, Id id, double x, double y, double z) {
  m.node_ids.push_back(id);
  m.coords.push_back({x, y, z});
  return m.node_count() - 1;
}

void add_element(Mesh& mesh, const ElementRegistry& registry, const std::string& type, Id id,
                 const std::vector<int>& nodes) {
  Element e;
  e.id = id;
  e.type = type;
  e.first_node = static_cast<int>(mesh.model.connectivity.size());
  e.node_count = static_cast<int>(nodes.size());
  mesh.model.elements.push_back(e);
  mesh.model.connectivity.insert(mesh.model.connectivity.end(), nodes.begin(), nodes.end());
  mesh.formulation.push_back(registry.find(type));
}

// A quarter cylinder (radius 1, axis z) of `n` flat S4 facets around and one along.
Mesh faceted_cylinder(const ElementRegistry& registry, int n) {
  Mesh mesh;
  for (int k = 0; k <= n; ++k) {
    const double phi = 0.5 * kPi * k / n;
    add_node(mesh.model, 2 * k + 1, std::cos(phi), std::sin(phi), 0.0);
    add_node(mesh.model, 2 * k + 2, std::cos(phi), std::sin(phi), 1.0);
  }
  for (int k = 0; k < n; ++k)  // outward normals: (around) x (along) points away from the axis
    add_element(mesh, registry, "S4", k + 1, {2 * k, 2 * k + 2, 2 * k + 3, 2 * k + 1});
  return mesh;
}

Eigen::Vector3d at(const ShellNormals& normals, const Model& m, int e, int a) {
  const Vec3& v = normals.at_slot[m.elements[e].first_node + a];
  return {v[0], v[1], v[2]};
}

TEST(ShellNormals, FacetedCylinderGetsRadialNormalsInsideAndFacetNormalsAtItsEdges) {
  const ElementRegistry registry = test::builtin_registry();
  const Mesh mesh = faceted_cylinder(registry, 6);  // 15-degree facets: within 20, averaged
  const ShellNormals normals = resolve_shell_normals(mesh.model, mesh.formulation);
  ASSERT_TRUE(normals.any());
  EXPECT_TRUE(normals.fold_nodes.empty());
  EXPECT_TRUE(normals.warnings.empty());
  for (int e = 0; e < 6; ++e)
    for (int a = 0; a < 4; ++a) {
      const int node = mesh.model.element_nodes(e)[a];
      const Vec3& x = mesh.model.coords[node];
      const Eigen::Vector3d radial(x[0], x[1], 0.0);
      const Eigen::Vector3d n = at(normals, mesh.model, e, a);
      EXPECT_NEAR(n.norm(), 1.0, 1e-14);
      const bool edge = node <= 1 || node >= 12;  // the arc's ends: one facet each
      if (edge) {
        // The facet's own normal: 7.5 degrees from the radius.
        EXPECT_NEAR(std::acos(n.dot(radial)) * 180.0 / kPi, 7.5, 1e-9) << node;
      } else {
        EXPECT_NEAR((n - radial).norm(), 0.0, 1e-14) << node;
      }
    }
}

TEST(ShellNormals, FacetsFurtherApartThanTwentyDegreesAreFolds) {
  const ElementRegistry registry = test::builtin_registry();
  const Mesh mesh = faceted_cylinder(registry, 2);  // 45-degree facets
  const ShellNormals normals = resolve_shell_normals(mesh.model, mesh.formulation);
  EXPECT_EQ(normals.fold_nodes, (std::vector<Id>{3, 4}));  // the shared edge
  // Each facet keeps its own normal at the fold: element 1's at 22.5 degrees, element 2's at 67.5.
  const Eigen::Vector3d first = at(normals, mesh.model, 0, 1),
                        second = at(normals, mesh.model, 1, 0);
  EXPECT_NEAR(std::atan2(first[1], first[0]) * 180.0 / kPi, 22.5, 1e-9);
  EXPECT_NEAR(std::atan2(second[1], second[0]) * 180.0 / kPi, 67.5, 1e-9);
}

TEST(ShellNormals, GivenNormalsReplaceReverseAndWarn) {
  const ElementRegistry registry = test::builtin_registry();
  Mesh mesh = faceted_cylinder(registry, 2);  // facet normals at 22.5 and 67.5 degrees
  const auto direction = [](double degrees) {
    return Vec3{std::cos(degrees * kPi / 180.0), std::sin(degrees * kPi / 180.0), 0.0};
  };
  // Element 1 at the fold node 3 (index 2, its local node 2): 10 degrees off its facet, used
  // silently; element 2 at the fold node 4 (index 3, its local node 4): its facet normal turned
  // by 175 degrees, taken reversed; element 1 at node 1 (index 0): 60 degrees off, used and
  // warned of with its line.
  mesh.model.normals.push_back({0, 2, direction(32.5), {"deck.inp", 40}});
  mesh.model.normals.push_back({1, 3, direction(67.5 + 175.0), {"deck.inp", 41}});
  mesh.model.normals.push_back({0, 0, direction(82.5), {"deck.inp", 42}});
  const ShellNormals normals = resolve_shell_normals(mesh.model, mesh.formulation);
  const auto angle = [](const Eigen::Vector3d& n) { return std::atan2(n[1], n[0]) * 180.0 / kPi; };
  EXPECT_NEAR(angle(at(normals, mesh.model, 0, 1)), 32.5, 1e-12);
  EXPECT_NEAR(angle(at(normals, mesh.model, 1, 3)), 67.5 - 5.0, 1e-12);  // -(67.5 + 175)
  EXPECT_NEAR(angle(at(normals, mesh.model, 0, 0)), 82.5, 1e-12);
  ASSERT_EQ(normals.warnings.size(), 1u);
  EXPECT_NE(normals.warnings[0].find("deck.inp:42"), std::string::npos) << normals.warnings[0];
  EXPECT_NE(normals.warnings[0].find("60.0 degrees"), std::string::npos) << normals.warnings[0];
}

TEST(ShellNormals, QuadraticShellsOnACylinderAverageToTheRadius) {
  // Two S8R elements over 2 x 30 degrees: each element's own normal at the shared nodes comes from
  // its parabolic arc (off the radius by ~0.1 degree); the average is radial by symmetry.
  const ElementRegistry registry = test::builtin_registry();
  Mesh mesh;
  const auto point = [&](Id id, double degrees, double z) {
    return add_node(mesh.model, id, std::cos(degrees * kPi / 180.0),
                    std::sin(degrees * kPi / 180.0), z);
  };
  std::vector<int> ring[3];
  for (int k = 0; k <= 4; ++k)
    for (int j = 0; j < 3; ++j) ring[j].push_back(point(10 * j + k + 1, 15.0 * k, 0.5 * j));
  for (int e = 0; e < 2; ++e) {
    const int k = 2 * e;
    add_element(mesh, registry, "S8R", e + 1,
                {ring[0][k], ring[0][k + 2], ring[2][k + 2], ring[2][k], ring[0][k + 1],
                 ring[1][k + 2], ring[2][k + 1], ring[1][k]});
  }
  const ShellNormals normals = resolve_shell_normals(mesh.model, mesh.formulation);
  const Eigen::Vector3d shared = at(normals, mesh.model, 0, 1);  // node at 30 degrees, z = 0
  EXPECT_NEAR((shared - Eigen::Vector3d(std::cos(kPi / 6.0), std::sin(kPi / 6.0), 0.0)).norm(), 0.0,
              1e-14);
  EXPECT_NEAR((at(normals, mesh.model, 1, 0) - shared).norm(), 0.0, 1e-15);
}

TEST(ShellNormals, ModelsWithoutCurvedShellsResolveNothing) {
  const ElementRegistry registry = test::builtin_registry();
  Mesh mesh;
  for (int k = 0; k < 3; ++k) add_node(mesh.model, k + 1, k, 0.0, 0.0);
  add_element(mesh, registry, "B31", 1, {0, 1});
  add_element(mesh, registry, "STRI3", 2, {0, 1, 2});
  mesh.model.coords[2] = {0.0, 1.0, 0.0};
  EXPECT_FALSE(resolve_shell_normals(mesh.model, mesh.formulation).any());
}

}  // namespace
}  // namespace styk
