// SPEC §3.1.8: patch test on the unit cube of 7 irregular hexahedra (MacNeal-Harder: an inner
// hexahedron on the eight interior nodes listed in SPEC, and six hexahedra joining each of its
// faces to the matching cube face). E = 1e6, nu = 0.25; every boundary node gets
//   u = 1e-3 (2x + y + z) / 2,  v = 1e-3 (x + 2y + z) / 2,  w = 1e-3 (x + y + 2z) / 2,
// i.e. all strains and engineering shears 1e-3. Expected (SPEC, thesis Tab 3.13 "8 patch A"):
// sigma = 2000, tau = 400, Mises 1200 at every integration point and centroid; here also at every
// extrapolated element node and every node averaged by methods I and II (SPEC §5), all to 1e-9
// relative. Meshes: C3D8, C3D20 and C3D14 alone, C3D21 + C3D20 and C3D28 + C3D20 (the six outer
// elements of the contact type with their special face S1 on the cube boundary, the inner one
// C3D20, so every shared face is a C3D20 face); every other solid alone (C3D8R with hourglass
// control, C3D8I, C3D20R, C3D27); and TMPL8, the template plug-in of docs/plugins.md, loaded from
// the build's examples/ plug-in directory.
#include <array>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/core/tensor_ops.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

constexpr double kRelTol = 1e-9;
const Tensor6 kStress = {2000.0, 2000.0, 2000.0, 400.0, 400.0, 400.0};
const Tensor6 kStrain = {1e-3, 1e-3, 1e-3, 5e-4, 5e-4, 5e-4};  // tensor shears: gamma / 2

Vec3 patch_displacement(const Vec3& x) {
  return {1e-3 * (2 * x[0] + x[1] + x[2]) / 2, 1e-3 * (x[0] + 2 * x[1] + x[2]) / 2,
          1e-3 * (x[0] + x[1] + 2 * x[2]) / 2};
}

// The MacNeal-Harder cube. Interior node k lies near cube corner k (Abaqus corner order).
Model patch_cube(const ElementRegistry& registry, const std::string& inner,
                 const std::string& outer) {
  const test::HexCorners cube = {
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  const test::HexCorners interior = {{{0.249, 0.342, 0.192},
                                      {0.826, 0.288, 0.288},
                                      {0.850, 0.649, 0.263},
                                      {0.273, 0.750, 0.230},
                                      {0.320, 0.186, 0.643},
                                      {0.677, 0.305, 0.683},
                                      {0.788, 0.693, 0.644},
                                      {0.165, 0.745, 0.702}}};
  // Faces S1..S6 of a hexahedron (0-based corners), circling with the normal pointing into it.
  const int faces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                           {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  test::HexModelBuilder builder(registry, 1e6, 0.25);
  builder.add(inner, interior);
  // Outer element of cube face f: bottom (S1) on the cube face, top on the inner element's face.
  // The face order turns the normal into the cube, i.e. from the bottom to the top: positive
  // Jacobian in Abaqus order.
  for (const auto& face : faces) {
    test::HexCorners corners;
    for (int k = 0; k < 4; ++k) {
      corners[k] = cube[face[k]];
      corners[k + 4] = interior[face[k]];
    }
    builder.add(outer, corners);
  }
  Model model = builder.finish();
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    bool on_boundary = false;
    for (double c : x) on_boundary = on_boundary || std::abs(c) < 1e-12 || std::abs(c - 1) < 1e-12;
    if (!on_boundary) continue;
    const Vec3 u = patch_displacement(x);
    for (int d = 0; d < 3; ++d) model.boundaries.push_back({n, d + 1, u[d], {}});
  }
  return model;
}

void expect_tensor(const Tensor6& value, const Tensor6& expected, const std::string& where) {
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(value[k], expected[k], kRelTol * std::abs(expected[0])) << where << " comp " << k;
}

// Every stored stress and strain of the increment equals the patch state.
void expect_patch_state(const Model& model, const IncrementResult& inc) {
  const std::vector<std::pair<const char*, const std::vector<Tensor6>*>> stresses = {
      {"S", &inc.S},
      {"S_element_nodes", &inc.S_element_nodes},
      {"S_centroid", &inc.S_centroid},
      {"S_nodal_I", &inc.S_nodal_I},
      {"S_nodal_II", &inc.S_nodal_II}};
  const std::vector<std::pair<const char*, const std::vector<Tensor6>*>> strains = {
      {"E", &inc.E},
      {"E_element_nodes", &inc.E_element_nodes},
      {"E_centroid", &inc.E_centroid},
      {"E_nodal_I", &inc.E_nodal_I},
      {"E_nodal_II", &inc.E_nodal_II}};
  const std::size_t sizes[5] = {static_cast<std::size_t>(inc.ip_offset.back()),
                                model.connectivity.size(), model.elements.size(),
                                model.coords.size(), model.coords.size()};
  for (int f = 0; f < 5; ++f) {
    ASSERT_EQ(stresses[f].second->size(), sizes[f]) << stresses[f].first;
    ASSERT_EQ(strains[f].second->size(), sizes[f]) << strains[f].first;
    for (std::size_t i = 0; i < sizes[f]; ++i) {
      const std::string where = std::string(stresses[f].first) + "[" + std::to_string(i) + "]";
      expect_tensor((*stresses[f].second)[i], kStress, where);
      expect_tensor((*strains[f].second)[i], kStrain, "strain " + where);
      EXPECT_NEAR(mises((*stresses[f].second)[i]), 1200.0, kRelTol * 1200.0) << where;
    }
  }
}

struct PatchCase {
  const char* inner;
  const char* outer;
};

class PatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(PatchTest, ConstantStressEverywhere) {
  const auto full = test::registry_with_plugins();
  for (const PluginDiagnostic& d : full->diagnostics) ADD_FAILURE() << d.message;
  const Model model = patch_cube(full->registry, GetParam().inner, GetParam().outer);
  ASSERT_EQ(model.element_count(), 7);
  // 8 interior nodes free (plus the mid-edge/face nodes inside the cube for quadratic meshes).
  int free_nodes = 0;
  std::vector<bool> held(model.node_count(), false);
  for (const Boundary& b : model.boundaries) held[b.node] = true;
  for (int n = 0; n < model.node_count(); ++n) free_nodes += held[n] ? 0 : 1;
  EXPECT_GE(free_nodes, 8);

  const Results results =
      run_static_analysis(model, full->registry, SolveOptions{}, nullptr, nullptr);
  ASSERT_EQ(results.increments.size(), 1u);
  const IncrementResult& inc = results.increments[0];
  // The free nodes follow the linear field (the patch test proper).
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3 u = patch_displacement(model.coords[n]);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(inc.U[n][d], u[d], kRelTol * 2e-3) << "node " << n;
  }
  expect_patch_state(model, inc);
}

INSTANTIATE_TEST_SUITE_P(
    Spec3_1_8, PatchTest,
    ::testing::Values(PatchCase{"C3D8", "C3D8"}, PatchCase{"C3D20", "C3D20"},
                      PatchCase{"C3D14", "C3D14"}, PatchCase{"C3D20", "C3D21"},
                      PatchCase{"C3D20", "C3D28"}, PatchCase{"C3D8R", "C3D8R"},
                      PatchCase{"C3D8I", "C3D8I"}, PatchCase{"C3D20R", "C3D20R"},
                      PatchCase{"C3D27", "C3D27"}, PatchCase{"TMPL8", "TMPL8"}),
    [](const ::testing::TestParamInfo<PatchCase>& param_info) {
      return std::string(param_info.param.outer) + "_in_" + param_info.param.inner;
    });

}  // namespace
}  // namespace styk
