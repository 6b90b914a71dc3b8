// Uniaxial tension of a block: the patch test of a linear static solve. Exact solution
// (elementary elasticity): u_x = sigma x / E, u_y = -nu sigma y / E, u_z = -nu sigma z / E,
// S11 = sigma everywhere, other stresses zero; the reactions balance the applied force. Both the
// linear and the quadratic hexahedron reproduce it exactly, so the tolerance is round-off: 1e-10.
#include <gtest/gtest.h>

#include <ostream>
#include <tuple>

#include "solver_test_support.hpp"

namespace styk {
namespace {

constexpr double kE = 210000.0;
constexpr double kNu = 0.3;
constexpr double kSigma = 150.0;
constexpr double kLx = 2.0, kLy = 1.5, kLz = 1.0;

enum class LoadKind { Pressure, NodalForces };

struct TensionCase {
  std::string type;
  int divisions;
  LoadKind load;
};

std::string case_name(const testing::TestParamInfo<TensionCase>& info) {
  return info.param.type + "_" + std::to_string(info.param.divisions) +
         (info.param.load == LoadKind::Pressure ? "_pressure" : "_cload");
}

// GoogleTest prints a parameter it has no printer for byte by byte, padding included (valgrind
// reports the padding as uninitialised); the case's name says it all.
void PrintTo(const TensionCase& c, std::ostream* out) {
  *out << c.type << " " << c.divisions << (c.load == LoadKind::Pressure ? " pressure" : " cload");
}

class CubeTension : public testing::TestWithParam<TensionCase> {};

// Tension on x = kLx as a negative pressure on face S4 (xi = +1) of the last element column.
void add_pressure(Model& model, int nx, Step& step) {
  for (int e = 0; e < model.element_count(); ++e)
    if (e % nx == nx - 1) step.dloads.push_back({e, 4, -kSigma, {}});
}

// Consistent nodal forces of the uniform traction on x = kLx, written out from the textbook
// face load vectors of a rectangular face of area A: 4-node face A/4 per corner; 8-node
// serendipity face -A/12 per corner and A/3 per mid-side node.
void add_nodal_forces(Model& model, const TensionCase& c, Step& step) {
  const int n = c.divisions;
  const double hy = kLy / n, hz = kLz / n;
  std::vector<double> force(model.node_count(), 0.0);
  for (int n_index : test::nodes_at(model, 0, kLx)) {
    const double y = model.coords[n_index][1] / hy, z = model.coords[n_index][2] / hz;
    const bool y_corner = std::abs(y - std::round(y)) < 1e-9;
    const bool z_corner = std::abs(z - std::round(z)) < 1e-9;
    // Number of faces around this node in y and z (1 on the boundary of the face, else 2).
    const int fy = y_corner ? ((std::round(y) == 0 || std::round(y) == n) ? 1 : 2) : 1;
    const int fz = z_corner ? ((std::round(z) == 0 || std::round(z) == n) ? 1 : 2) : 1;
    const double face_force = kSigma * hy * hz;
    double share = 0.0;
    if (c.type == "C3D8")
      share = 0.25;
    else
      share = (y_corner && z_corner) ? -1.0 / 12.0 : 1.0 / 3.0;
    force[n_index] += fy * fz * share * face_force;
  }
  for (int n_index = 0; n_index < model.node_count(); ++n_index)
    if (force[n_index] != 0.0) step.cloads.push_back({n_index, 1, force[n_index], {}});
}

TEST_P(CubeTension, MatchesExactSolution) {
  const TensionCase& c = GetParam();
  const ElementRegistry registry = test::builtin_registry();
  Model model = test::block(registry, c.type, c.divisions, c.divisions, c.divisions, kLx, kLy, kLz);
  test::add_symmetry_supports(model);
  Step step = test::static_step();
  if (c.load == LoadKind::Pressure)
    add_pressure(model, c.divisions, step);
  else
    add_nodal_forces(model, c, step);
  model.steps.push_back(step);

  AnalysisReport report;
  const Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, &report);
  ASSERT_EQ(results.increments.size(), 1u);
  const IncrementResult& r = results.increments[0];
  EXPECT_NE(report.linear_solver.find("CHOLMOD"), std::string::npos);

  // Displacements: exact linear field, relative tolerance 1e-10 of the largest displacement.
  const double scale = kSigma * kLx / kE;
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    EXPECT_NEAR(r.U[n][0], kSigma * x[0] / kE, 1e-10 * scale) << "node " << model.node_ids[n];
    EXPECT_NEAR(r.U[n][1], -kNu * kSigma * x[1] / kE, 1e-10 * scale);
    EXPECT_NEAR(r.U[n][2], -kNu * kSigma * x[2] / kE, 1e-10 * scale);
  }

  // Stresses and strains at every integration point.
  ASSERT_EQ(r.ip_offset.size(), static_cast<std::size_t>(model.element_count() + 1));
  ASSERT_EQ(r.S.size(), static_cast<std::size_t>(r.ip_offset.back()));
  for (std::size_t p = 0; p < r.S.size(); ++p) {
    EXPECT_NEAR(r.S[p][0], kSigma, 1e-10 * kSigma);
    for (int k = 1; k < 6; ++k) EXPECT_NEAR(r.S[p][k], 0.0, 1e-10 * kSigma);
    EXPECT_NEAR(r.E[p][0], kSigma / kE, 1e-10 * kSigma / kE);
    EXPECT_NEAR(r.E[p][1], -kNu * kSigma / kE, 1e-10 * kSigma / kE);
  }

  // Reactions: the x = 0 supports carry -F, F = sigma * ly * lz; every other sum vanishes, and a
  // node without prescribed dofs has no reaction.
  const double F = kSigma * kLy * kLz;
  Vec3 sum{0.0, 0.0, 0.0};
  for (int n = 0; n < model.node_count(); ++n)
    for (int d = 0; d < 3; ++d) sum[d] += r.RF[n][d];
  EXPECT_NEAR(sum[0], -F, 1e-10 * F);
  EXPECT_NEAR(sum[1], 0.0, 1e-10 * F);
  EXPECT_NEAR(sum[2], 0.0, 1e-10 * F);
  for (int n = 0; n < model.node_count(); ++n) {
    if (model.coords[n][0] > 0.0) {
      EXPECT_EQ(r.RF[n][0], 0.0) << "node " << model.node_ids[n];
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Solver, CubeTension,
                         testing::Values(TensionCase{"C3D8", 1, LoadKind::Pressure},
                                         TensionCase{"C3D8", 1, LoadKind::NodalForces},
                                         TensionCase{"C3D20", 1, LoadKind::Pressure},
                                         TensionCase{"C3D20", 1, LoadKind::NodalForces},
                                         TensionCase{"C3D8", 3, LoadKind::Pressure},
                                         TensionCase{"C3D20", 2, LoadKind::NodalForces}),
                         case_name);

}  // namespace
}  // namespace styk
