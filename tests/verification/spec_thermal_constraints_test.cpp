// Thermal loads, *TRANSFORM and *EQUATION at model scale (contact issue, constraints part).
//
// SPEC §3.1.7 thick-walled cylinder, R1 = 3, R2 = 9, E = 1000, unit internal pressure, plane
// strain (uz = 0 at every node), meshed as a 22.5° sector of C3D20 (5 elements radially, 4:1
// grading as in SPEC, 2 along the arc, 1 axially). The cut faces are symmetry planes:
// - with *TRANSFORM, TYPE=C (cylindrical about z) on both cut faces and the hoop dof 2 held;
// - with *EQUATION cos(t) uy - sin(t) ux = 0 on the 22.5° face (the same constraint written in
//   global dofs) and uy = 0 on the 0° face.
// Expected: u(R1) = (1+nu) p R1^2 / (E (R2^2 - R1^2)) [R2^2/R1 + (1-2 nu) R1] (Lamé), which is
// 4.5825e-3 for nu = 0.3 and 5.0399e-3 for nu = 0.49 (SPEC §3.1.7 table). Tolerances: the
// discretisation error of this mesh (measured 9.1e-5 relative for nu = 0.3 and 1.3e-3 for
// nu = 0.49, where C3D20 starts to lock), asserted below 2e-4 and 3e-3. The two constraint
// forms must agree to 1e-10 relative, and CalculiX 2.20 (`ccx` on PATH) must reproduce both
// decks (written by write_inp) to 1e-6 relative to the largest displacement (measured 1.1e-7).
// CalculiX prints the displacements of transformed nodes in their local system, so ours are rotated
// into it before the comparison.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "styk/elements/builtin.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/solver/analysis.hpp"
#include "support/ccx_runner.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kR1 = 3.0;
constexpr double kR2 = 9.0;
constexpr double kYoung = 1000.0;
constexpr double kPressure = 1.0;
constexpr double kSector = 22.5 * M_PI / 180.0;

double lame_inner_displacement(double nu) {
  return (1.0 + nu) * kPressure * kR1 * kR1 / (kYoung * (kR2 * kR2 - kR1 * kR1)) *
         (kR2 * kR2 / kR1 + (1.0 - 2.0 * nu) * kR1);
}

enum class Symmetry { Transform, Equation };

Model sector(double nu, Symmetry symmetry) {
  using namespace mesher;
  Mesh mesh;
  // Profile: xi radial (R1 -> R2), eta from z = 1 down to 0, so that xi x eta x hoop is
  // right-handed; zeta runs over the sector angle.
  const PatchMap profile =
      quad_map({Vec3{kR1, 0, 1}, Vec3{kR2, 0, 1}, Vec3{kR2, 0, 0}, Vec3{kR1, 0, 0}});
  BlockSpec spec;
  spec.type = "C3D20";
  spec.divisions = {5, 1, 2};
  spec.grading = {4.0, 1.0, 1.0};
  spec.elset = "EALL";
  const Block block = mesh_block(mesh, revolve(profile, {0, 0, 0}, {0, 0, 1}, 0.0, kSector), spec);
  mesh.add_to_node_set("CUT0", block.side_nodes(2, -1));
  mesh.add_to_node_set("CUT1", block.side_nodes(2, +1));
  mesh.add_to_node_set("INNER", block.side_nodes(0, -1));
  std::vector<int> all(mesh.nodes.size());
  for (std::size_t n = 0; n < all.size(); ++n) all[n] = static_cast<int>(n);
  mesh.add_to_node_set("NALL", all);  // CalculiX's *NODE PRINT needs a set
  Model model = to_model(mesh, "sector.inp");

  Material material;
  material.name = "M";
  material.young = kYoung;
  material.poisson = nu;
  model.materials.push_back(material);
  Section section;
  section.elset = "EALL";
  section.material = "M";
  section.material_index = 0;
  model.sections.push_back(section);
  for (Element& e : model.elements) e.section = 0;

  for (int n = 0; n < model.node_count(); ++n) model.boundaries.push_back({n, 3, 0.0, {}});
  const std::vector<int>& cut0 = model.nsets.at("CUT0").nodes;
  const std::vector<int>& cut1 = model.nsets.at("CUT1").nodes;
  if (symmetry == Symmetry::Transform) {
    for (const char* name : {"CUT0", "CUT1"}) {
      Transform transform;
      transform.nset = name;
      transform.axes.system = CoordinateSystem::Cylindrical;
      transform.axes.a = {0, 0, 0};
      transform.axes.b = {0, 0, 1};
      model.transforms.push_back(transform);
    }
    for (const std::vector<int>* cut : {&cut0, &cut1})
      for (int n : *cut) model.boundaries.push_back({n, 2, 0.0, {}});
  } else {
    for (int n : cut0) model.boundaries.push_back({n, 2, 0.0, {}});
    for (int n : cut1) {
      Equation equation;
      equation.terms = {{n, 2, std::cos(kSector)}, {n, 1, -std::sin(kSector)}};
      model.equations.push_back(equation);
    }
  }

  Step step;
  step.name = "PRESSURE";
  step.has_procedure = true;
  for (const FaceRef& face : block.side_faces(0, -1))
    step.dloads.push_back({face.element, face.face + 1, kPressure, {}});
  OutputRequest print;
  print.kind = OutputRequest::Kind::NodePrint;
  print.set = "NALL";
  print.vars = {"U"};
  step.outputs.push_back(print);
  model.steps.push_back(step);
  return model;
}

IncrementResult solve(const Model& model) {
  ElementRegistry registry = test::builtin_registry();
  return run_static_analysis(model, registry, {}, nullptr, nullptr).increments.at(0);
}

double radial(const Model& model, const IncrementResult& r, int n) {
  const Vec3& x = model.coords[n];
  const double rho = std::hypot(x[0], x[1]);
  return (r.U[n][0] * x[0] + r.U[n][1] * x[1]) / rho;
}

double hoop(const Model& model, const IncrementResult& r, int n) {
  const Vec3& x = model.coords[n];
  const double rho = std::hypot(x[0], x[1]);
  return (-r.U[n][0] * x[1] + r.U[n][1] * x[0]) / rho;
}

class LameSector : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(LameSector, TransformedCutFacesGiveLameDisplacement) {
  const auto [nu, tolerance] = GetParam();
  const Model model = sector(nu, Symmetry::Transform);
  const IncrementResult r = solve(model);
  const double expected = lame_inner_displacement(nu);
  double worst = 0.0;
  for (int n : model.nsets.at("INNER").nodes)
    worst = std::max(worst, std::abs(radial(model, r, n) - expected) / expected);
  std::printf("SPEC 3.1.7 sector, nu = %.2f: u(R1) theory %.5e, max relative error %.2e\n", nu,
              expected, worst);
  EXPECT_LT(worst, tolerance);
  // The symmetry holds exactly: no hoop displacement anywhere (axisymmetric solution).
  for (int n = 0; n < model.node_count(); ++n)
    ASSERT_NEAR(hoop(model, r, n), 0.0, 1e-12 * expected) << n;
}

TEST_P(LameSector, EquationsEqualTransforms) {
  const double nu = GetParam().first;
  const Model with_transform = sector(nu, Symmetry::Transform);
  const Model with_equation = sector(nu, Symmetry::Equation);
  const IncrementResult a = solve(with_transform);
  const IncrementResult b = solve(with_equation);
  const double scale = lame_inner_displacement(nu);
  for (int n = 0; n < with_transform.node_count(); ++n)
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(b.U[n][d], a.U[n][d], 1e-10 * scale) << n;
}

INSTANTIATE_TEST_SUITE_P(Spec317, LameSector,
                         ::testing::Values(std::make_pair(0.3, 2e-4), std::make_pair(0.49, 3e-3)));

// Thermal (contact issue, "Thermal"): the plane-strain sector (uz = 0) heated uniformly by dT,
// no pressure, expands radially without in-plane stress: u_r = (1 + nu) alpha dT r,
// sigma_rr = sigma_tt = 0, sigma_zz = -E alpha dT. The field is linear, so C3D20 reproduces it
// on the curved mesh up to round-off (asserted 1e-9 relative).
TEST(ThermalSector, UniformHeatingExpandsWithoutInPlaneStress) {
  const double nu = 0.3, alpha = 1e-5, dT = 80.0;
  Model model = sector(nu, Symmetry::Transform);
  model.materials[0].expansion = alpha;
  model.steps[0].dloads.clear();
  for (int n = 0; n < model.node_count(); ++n) {
    model.initial_temperatures.push_back({n, 15.0, {}});
    model.steps[0].temperatures.push_back({n, 15.0 + dT, {}});
  }
  const IncrementResult r = solve(model);
  const double strain = (1.0 + nu) * alpha * dT;
  for (int n = 0; n < model.node_count(); ++n) {
    const double rho = std::hypot(model.coords[n][0], model.coords[n][1]);
    ASSERT_NEAR(radial(model, r, n), strain * rho, 1e-9 * strain * kR2) << n;
  }
  const double sigma_zz = -kYoung * alpha * dT;
  for (const Tensor6& s : r.S) {
    for (int c : {0, 1, 3, 4, 5}) ASSERT_NEAR(s[c], 0.0, 1e-9 * std::abs(sigma_zz));
    ASSERT_NEAR(s[2], sigma_zz, 1e-9 * std::abs(sigma_zz));
  }
}

// CalculiX on the same decks. Its .dat lists transformed nodes' displacements in their local
// system and marks those lines with a trailing "L" (CalculiX 2.20, seen on these decks), which
// styk's .dat reader does not take, so the block is parsed here. Ours are global and are rotated
// into the cylindrical system for the nodes of CUT0/CUT1 of the *TRANSFORM deck.
struct CcxDisplacement {
  Vec3 u{};
  bool local = false;
};

std::map<Id, CcxDisplacement> last_displacement_block(std::istream& dat) {
  std::map<Id, CcxDisplacement> block;
  std::string line;
  bool inside = false;
  while (std::getline(dat, line)) {
    if (line.find("displacements (vx,vy,vz)") != std::string::npos) {
      block.clear();
      inside = true;
      continue;
    }
    if (!inside) continue;
    std::istringstream fields(line);
    Id id = 0;
    CcxDisplacement d;
    if (!(fields >> id >> d.u[0] >> d.u[1] >> d.u[2])) {
      if (!block.empty()) inside = false;  // the blank line after the data ends the block
      continue;
    }
    std::string flag;
    d.local = static_cast<bool>(fields >> flag) && flag == "L";
    block[id] = d;
  }
  return block;
}
void cross_check_with_ccx(const Model& model, const std::string& job) {
  const std::filesystem::path dir =
      std::filesystem::path(STYK_BINARY_DIR) / "tests" / "verification" / ("ccx_" + job);
  std::filesystem::create_directories(dir);
  {
    std::ofstream deck(dir / (job + ".inp"));
    write_inp(model, deck);
  }
  ASSERT_EQ(test::run_ccx(dir, job).exit_code, 0)
      << "ccx failed in " << dir << " (" << test::kCcxMissing << "?)";
  std::ifstream dat(dir / (job + ".dat"));
  const std::map<Id, CcxDisplacement> theirs = last_displacement_block(dat);

  const IncrementResult ours = solve(model);
  std::vector<char> local(model.node_count(), 0);
  for (const Transform& t : model.transforms)
    for (int n : model.nsets.at(t.nset).nodes) local[n] = 1;
  double largest = 0.0, worst = 0.0;
  for (const Vec3& u : ours.U)
    for (double c : u) largest = std::max(largest, std::abs(c));
  ASSERT_EQ(theirs.size(), static_cast<std::size_t>(model.node_count()));
  for (int n = 0; n < model.node_count(); ++n) {
    const auto it = theirs.find(model.node_ids[n]);
    ASSERT_NE(it, theirs.end()) << "node " << model.node_ids[n] << " missing in ccx output";
    EXPECT_EQ(it->second.local, local[n] != 0) << "node " << model.node_ids[n];
    Vec3 u = ours.U[n];
    if (local[n]) u = {radial(model, ours, n), hoop(model, ours, n), u[2]};
    for (int d = 0; d < 3; ++d) worst = std::max(worst, std::abs(u[d] - it->second.u[d]) / largest);
  }
  std::printf("ccx cross-check %-20s max |u| %.6e  max difference / max |u| %.2e\n", job.c_str(),
              largest, worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(ConstraintsCcx, TransformSectorMatchesCalculix) {
  cross_check_with_ccx(sector(0.3, Symmetry::Transform), "sector_transform");
}

TEST(ConstraintsCcx, EquationSectorMatchesCalculix) {
  cross_check_with_ccx(sector(0.3, Symmetry::Equation), "sector_equation");
}

}  // namespace
}  // namespace styk
