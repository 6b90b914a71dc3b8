// SPEC §2.2-2.4, thesis Tab 2.6-2.8: one contact element on the reference cube [-1, 1]^3
// (nu = 0.3; E drops out of the reactions), bottom face S1 supported in z only plus the minimal
// in-plane rigid-body removal (node 1: x, y; node 2: y), top face loaded by the thesis' point
// loads CF3. Solved through run_static_analysis; the bottom reactions RF3 must be positive, sum
// to the load 4 and equal the tables:
//   C3D14 (top corners -1/3, centre -8/3): corners 0.627497, centre 1.490013 (tolerance 1e-6,
//         the digits printed in elements-ref section 6),
//   C3D21 (top corners +1/3, mid-edges -4/3): corners 1/9, mid-edges 4/9, centre 16/9 (1e-9),
//   C3D28 (top as C3D21): corners 1/36, edge nodes 5/36, interior nodes 25/36 (1e-9).
// C3D21 and C3D28 carry consistent loads of a unit pressure, so their stress is uniform
// (s33 = -1, all else 0): checked at the integration points, the centroid and the nodes (methods
// I and II) to 1e-9.
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

struct SingleElement {
  Model model;
  IncrementResult result;
};

// `top_cf3`: 1-based element node -> CF3.
SingleElement solve_single(const test::FullRegistry& full, const std::string& type,
                           const std::map<int, double>& top_cf3) {
  test::HexModelBuilder builder(full.registry, 210000.0, 0.3);
  builder.add(type, {{{-1, -1, -1},
                      {1, -1, -1},
                      {1, 1, -1},
                      {-1, 1, -1},
                      {-1, -1, 1},
                      {1, -1, 1},
                      {1, 1, 1},
                      {-1, 1, 1}}});
  SingleElement out{builder.finish(), {}};
  Model& model = out.model;
  const int* nodes = model.element_nodes(0);
  for (int local : full.registry.find(type)->faces()[0].nodes)
    model.boundaries.push_back({nodes[local], 3, 0.0, {}});
  model.boundaries.push_back({nodes[0], 1, 0.0, {}});
  model.boundaries.push_back({nodes[0], 2, 0.0, {}});
  model.boundaries.push_back({nodes[1], 2, 0.0, {}});
  for (const auto& [local, force] : top_cf3)
    model.steps[0].cloads.push_back({nodes[local - 1], 3, force, {}});
  Results results = run_static_analysis(model, full.registry, SolveOptions{}, nullptr, nullptr);
  out.result = std::move(results.increments.at(0));
  return out;
}

double rf3(const SingleElement& s, int local) {
  return s.result.RF[s.model.element_nodes(0)[local - 1]][2];
}

void expect_total_load_carried(const SingleElement& s, const TElement& element) {
  double sum = 0.0;
  for (int local : element.faces()[0].nodes) {
    EXPECT_GT(rf3(s, local + 1), 0.0) << "node " << local + 1;
    sum += rf3(s, local + 1);
  }
  EXPECT_NEAR(sum, 4.0, 1e-9);
}

void expect_uniaxial(const std::vector<Tensor6>& field, const std::string& what) {
  ASSERT_FALSE(field.empty()) << what;
  for (std::size_t i = 0; i < field.size(); ++i)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(field[i][k], k == 2 ? -1.0 : 0.0, 1e-9) << what << "[" << i << "] comp " << k;
}

std::map<int, double> serendipity_top() {
  std::map<int, double> cf3;
  for (int corner = 5; corner <= 8; ++corner) cf3[corner] = 1.0 / 3.0;
  for (int mid = 13; mid <= 16; ++mid) cf3[mid] = -4.0 / 3.0;
  return cf3;
}

class SingleElementTest : public ::testing::Test {
 protected:
  void SetUp() override {
    full_ = test::registry_with_plugins();
    for (const PluginDiagnostic& d : full_->diagnostics) ADD_FAILURE() << d.message;
  }
  std::unique_ptr<test::FullRegistry> full_;
};

TEST_F(SingleElementTest, C3D14Table2_6) {
  const SingleElement s =
      solve_single(*full_, "C3D14",
                   {{5, -1.0 / 3}, {6, -1.0 / 3}, {7, -1.0 / 3}, {8, -1.0 / 3}, {10, -8.0 / 3}});
  expect_total_load_carried(s, *full_->registry.find("C3D14"));
  for (int corner = 1; corner <= 4; ++corner) EXPECT_NEAR(rf3(s, corner), 0.627497, 1e-6);
  EXPECT_NEAR(rf3(s, 9), 1.490013, 1e-6);
}

TEST_F(SingleElementTest, C3D21Table2_7) {
  const SingleElement s = solve_single(*full_, "C3D21", serendipity_top());
  expect_total_load_carried(s, *full_->registry.find("C3D21"));
  for (int node = 1; node <= 4; ++node) EXPECT_NEAR(rf3(s, node), 1.0 / 9.0, 1e-9);
  for (int node = 9; node <= 12; ++node) EXPECT_NEAR(rf3(s, node), 4.0 / 9.0, 1e-9);
  EXPECT_NEAR(rf3(s, 21), 16.0 / 9.0, 1e-9);
  expect_uniaxial(s.result.S, "S");
  expect_uniaxial(s.result.S_centroid, "S_centroid");
  expect_uniaxial(s.result.S_nodal_I, "S_nodal_I");
  expect_uniaxial(s.result.S_nodal_II, "S_nodal_II");
}

TEST_F(SingleElementTest, C3D28Table2_8) {
  const SingleElement s = solve_single(*full_, "C3D28", serendipity_top());
  expect_total_load_carried(s, *full_->registry.find("C3D28"));
  for (int node = 1; node <= 4; ++node) EXPECT_NEAR(rf3(s, node), 1.0 / 36.0, 1e-9);
  for (int node = 17; node <= 24; ++node) EXPECT_NEAR(rf3(s, node), 5.0 / 36.0, 1e-9);
  for (int node = 25; node <= 28; ++node) EXPECT_NEAR(rf3(s, node), 25.0 / 36.0, 1e-9);
  expect_uniaxial(s.result.S, "S");
  expect_uniaxial(s.result.S_centroid, "S_centroid");
  expect_uniaxial(s.result.S_nodal_I, "S_nodal_I");
  expect_uniaxial(s.result.S_nodal_II, "S_nodal_II");
}

}  // namespace
}  // namespace styk
