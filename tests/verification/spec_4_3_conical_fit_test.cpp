// SPEC §4.3 conical fit (pin pushed into a 1:10 taper), the builder's default quarter model
// (`styk mesh conical-fit`: 528 elements, 96 + 96 C3D21 in contact), 20 MPa on the pin top.
// SPEC, "The conical fit": the pin is held by the axial component of the normal contact force
// (N sin alpha) plus friction (mu N cos alpha); with alpha = 2.86 deg friction is not what holds
// it. A solver that treats the pin as held by friction alone reports a false loss of capacity
// ("friction capacity exceeded": the failure of samples/spec-4.3-conical-fit-c3d21-mu0.2.inp
// before the fix). Checked for mu = 0, 0.2, 0.4:
// - the step converges and the pin is held: the sleeve base's axial reaction balances the push
//   (the pressure's resultant on the quarter, 20 MPa x pi 11.25^2 / 4 = 1988.05 N to 1e-4, the
//   quadratic faces' interpolation of the circle) to 1e-8;
// - the contact carries it: normal plus tangential forces on the pin, axially, equal the push;
// - the hand formula of SPEC's note: the normal forces N hold the push F through
//   N (sin alpha + mu cos alpha) = F when every node slips axially (tan alpha = 0.05). Frictionless
//   this is exact: sum N sin alpha = F to 1e-6 (the nodal normals of the quadratic cone are exact);
//   with friction a sticking node carries less than mu N, so sum N (sin alpha + mu cos alpha) >= F;
// - with friction the normal force needed falls (published: max Mises 58, 42, 35 MPa falls with
//   mu): the summed normal contact force decreases with mu, and so does the pin's largest Mises
//   stress in its lower part (below mid-engagement): measured 336.6, 65.6, 37.7 MPa (asserted to
//   1 %: the mesh and the load are fixed, so this guards the numbers quoted in docs/contact.md).
//   Those stresses scale with the normal force: Mises x (sin alpha + mu cos alpha) is the same for
//   the three within 5 % (16.8, 16.4, 16.9). The published 58 / 42 / 35 do not follow that ratio
//   (1.66 : 1.2 : 1 against the wedge's 9 : 1.8 : 1): the thesis' pin cannot have been free to
//   seat itself in the taper (its support is in the lost figure); at mu = 0.4 the two agree within
//   8 %.
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

double mises(const Tensor6& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

struct ConeResult {
  double push = 0;           // the applied load's downward resultant
  double base_reaction = 0;  // sum of RF3 over SLEEVE_BASE
  double normal_sum = 0;     // sum of the normal contact forces
  double max_mises = 0;      // largest integration-point Mises stress in the pin below z = 15
  int iterations = 0;
};

ConeResult solve_cone(const std::string& mu) {
  const auto registry = test::registry_with_plugins();
  const mesher::BuildResult built =
      mesher::run_builder("conical-fit", {{"mu", mu}}, registry->registry);
  const Model& model = built.model;
  const Results results =
      run_static_analysis(model, registry->registry, SolveOptions{}, nullptr, nullptr);
  const IncrementResult& inc = results.increments.back();
  ConeResult r;
  r.push = -inc.contact_equilibrium.applied[2];
  for (int n : model.nsets.at("SLEEVE_BASE").nodes) r.base_reaction += inc.RF[n][2];
  for (const ContactNodeResult& c : inc.contact) r.normal_sum += c.pressure * c.area;
  for (int e : model.elsets.at("PIN").elements) {
    const int* nodes = model.element_nodes(e);
    double z = 0;
    for (int k = 0; k < model.elements[e].node_count; ++k) z += model.coords[nodes[k]][2];
    if (z / model.elements[e].node_count > 15) continue;
    for (int i = inc.ip_offset[e]; i < inc.ip_offset[e + 1]; ++i)
      r.max_mises = std::max(r.max_mises, mises(inc.S[i]));
  }
  return r;
}

TEST(Spec43ConicalFit, PinHeldByTheTaperForEveryFrictionCoefficient) {
  const double nominal = 20.0 * kPi * 11.25 * 11.25 / 4;  // top radius 9.25 + 0.05 x 40
  std::map<std::string, ConeResult> by_mu;
  for (const std::string mu : {"0", "0.2", "0.4"}) {
    SCOPED_TRACE("mu = " + mu);
    const ConeResult r = solve_cone(mu);
    const double push = r.push;
    EXPECT_NEAR(push, nominal, 1e-4 * nominal);
    EXPECT_NEAR(r.base_reaction, push, 1e-8 * push);
    const double alpha = std::atan(0.05), m = std::stod(mu);
    if (m == 0)
      EXPECT_NEAR(r.normal_sum * std::sin(alpha), push, 1e-6 * push);
    else
      EXPECT_GE(r.normal_sum * (std::sin(alpha) + m * std::cos(alpha)), push * (1 - 1e-9));
    std::printf(
        "conical fit mu %s: push %.2f N, normal forces %.1f N, pin Mises below z = 15 %.2f MPa\n",
        mu.c_str(), push, r.normal_sum, r.max_mises);
    by_mu[mu] = r;
  }
  // Friction shares the load, so less normal force is needed.
  EXPECT_GT(by_mu["0"].normal_sum, by_mu["0.2"].normal_sum);
  EXPECT_GT(by_mu["0.2"].normal_sum, by_mu["0.4"].normal_sum);
  EXPECT_GT(by_mu["0"].max_mises, by_mu["0.2"].max_mises);
  EXPECT_GT(by_mu["0.2"].max_mises, by_mu["0.4"].max_mises);
  EXPECT_NEAR(by_mu["0"].max_mises, 336.6, 0.01 * 336.6);
  EXPECT_NEAR(by_mu["0.2"].max_mises, 65.6, 0.01 * 65.6);
  EXPECT_NEAR(by_mu["0.4"].max_mises, 37.7, 0.01 * 37.7);
  const double alpha = std::atan(0.05);
  std::vector<double> scaled;
  for (const auto& [mu, r] : by_mu)
    scaled.push_back(r.max_mises * (std::sin(alpha) + std::stod(mu) * std::cos(alpha)));
  const double mean = (scaled[0] + scaled[1] + scaled[2]) / 3;
  for (double v : scaled) EXPECT_NEAR(v, mean, 0.05 * mean);
}

}  // namespace
}  // namespace styk
