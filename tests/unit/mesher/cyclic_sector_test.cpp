// Cyclic symmetry (*TIE, CYCLIC SYMMETRY, docs/input.md): a sector model under a
// load that repeats in every sector gives the full model's answer on the same mesh. Checked:
// - linear: a solid shaft (O-grid, so nodes lie on the axis) twisted, pulled and pressed, once
//   full and once as its 90 deg sector: displacements equal to 1e-8 of the largest, and the
//   sector's reactions a quarter of the full model's (torque and axial force);
// - frictional contact: the shrink fit's model B (SPEC §4.2) heated and twisted by force couples,
//   full and as the builder's sector (--sector yes);
// - frictionless contact: the spline (SPEC §4.4) and P3G (SPEC §4.5) joints full and as their
//   120 deg sectors;
// - CalculiX solving the linear sector deck alike.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "builder_support.hpp"
#include "contact_support.hpp"
#include "mesher_checks.hpp"
#include "sector_support.hpp"
#include "styk/core/cyclic_symmetry.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/merge.hpp"
#include "styk/solver/analysis.hpp"
#include "support/ccx_runner.hpp"

namespace styk {
namespace {

using mesher::Mesh;
namespace detail = mesher::detail;

constexpr double kPi = 3.14159265358979323846;

// A solid shaft r = 10, z 0..30 of C3D20: four O-grid quarters (2 x 2 core, 2 rings), 4 rows.
Mesh shaft_mesh() {
  Mesh mesh;
  const auto o_grid = detail::quarter_o_grid(0.5);
  for (int quarter = 0; quarter < 4; ++quarter)
    for (int part = 0; part < 3; ++part)
      mesher::mesh_block(mesh,
                         detail::prism(
                             o_grid[part], 0, 30, [](double) { return 10.0; }, quarter * 0.5 * kPi),
                         {"C3D20", {2, 2, 4}, {1, 1, 1}, "EALL"});
  mesher::merge_coincident_nodes(mesh);
  return mesh;
}

// The shaft with its end z = 0 clamped, a torque, an axial pull and a radial squeeze on its top
// face as consistent tractions (each face contributes its own share, so a sector carries exactly
// its part), solved. Returns the model and the displacements.
struct Solved {
  Model model;
  Results results;
  double top_area = 0;  // the loaded face's area (sum of the nodal areas)
};

Solved solve_shaft(Mesh mesh, bool sector, const ElementRegistry& registry) {
  detail::SectorBoundary boundary;
  if (sector) {
    detail::cut_sector(mesh, 4, 0.0);
    boundary = detail::sector_boundary(mesh, 4, 1e-7 * mesh.size());
  }
  Solved s;
  s.model = mesher::finish_model(mesh, "shaft", 200000, 0.3);
  if (sector) detail::add_cyclic_symmetry(s.model, boundary);
  const double tol = 1e-7 * mesh.size();
  const auto base = detail::nodes_where(mesh, [&](const Vec3& x) { return x[2] < tol; });
  if (sector)
    detail::fix_in_sector(s.model, boundary, base, {1, 2, 3});
  else
    detail::fix(s.model, base, {1, 2, 3});
  // Top face: traction (tangential 2 r, axial 3, radial -1 r) per unit area.
  std::vector<mesher::FaceRef> top;
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
    for (const mesher::FaceRef& f :
         detail::faces_where(mesh, {e}, [&](const Vec3& x) { return x[2] > 30 - tol; }))
      top.push_back(f);
  const detail::NodalAreas areas = detail::equivalent_nodal_areas(s.model, registry, top);
  s.top_area = areas.sum;
  s.model.steps.push_back(detail::static_step());
  Step& step = s.model.steps.front();
  for (const auto& [node, a] : areas.area) {
    const Vec3& x = s.model.coords[node];
    const Vec3 f{a * (-2 * x[1] - x[0]), a * (2 * x[0] - x[1]), 3 * a};
    for (int d = 0; d < 3; ++d) step.cloads.push_back({node, d + 1, f[d], {}});
  }
  s.results = run_static_analysis(s.model, registry, SolveOptions{}, nullptr, nullptr);
  return s;
}

// The body (element set among `bodies`) of each node; "" for none.
std::vector<std::string> bodies_of(const Model& model, const std::vector<std::string>& bodies) {
  std::vector<std::string> out(model.node_count());
  for (const std::string& body : bodies) {
    const auto it = model.elsets.find(body);
    if (it == model.elsets.end()) continue;
    for (int e : it->second.elements)
      for (int k = 0; k < model.elements[e].node_count; ++k) out[model.element_nodes(e)[k]] = body;
  }
  return out;
}

// The node of `full` at the position x in body `body` (coincident nodes of two bodies in contact
// are told apart by their bodies).
int same_node(const Model& full, const std::vector<std::string>& full_bodies, const Vec3& x,
              const std::string& body) {
  for (int n = 0; n < full.node_count(); ++n)
    if (full_bodies[n] == body && std::hypot(full.coords[n][0] - x[0], full.coords[n][1] - x[1],
                                             full.coords[n][2] - x[2]) < 1e-9)
      return n;
  return -1;
}

double largest(const IncrementResult& inc) {
  double m = 0;
  for (const Vec3& u : inc.U) m = std::max(m, std::hypot(u[0], u[1], u[2]));
  return m;
}

TEST(CyclicSector, LinearShaftSectorEqualsFullModel) {
  const test::Elements elements;
  const Mesh mesh = shaft_mesh();
  const Solved full = solve_shaft(mesh, false, elements.registry);
  const Solved quarter = solve_shaft(mesh, true, elements.registry);
  const IncrementResult& f = full.results.increments.back();
  const IncrementResult& q = quarter.results.increments.back();
  const double scale = largest(f);
  ASSERT_GT(scale, 0);
  double worst = 0;
  const std::vector<std::string> fb = bodies_of(full.model, {"EALL"});
  const std::vector<std::string> qb = bodies_of(quarter.model, {"EALL"});
  for (int n = 0; n < quarter.model.node_count(); ++n) {
    const int m = same_node(full.model, fb, quarter.model.coords[n], qb[n]);
    ASSERT_GE(m, 0);
    for (int d = 0; d < 3; ++d) worst = std::max(worst, std::abs(q.U[n][d] - f.U[m][d]));
  }
  EXPECT_LE(worst, 1e-8 * scale) << "largest displacement " << scale;
  std::printf("linear shaft: sector - full displacement %.3g of the largest\n", worst / scale);
  // Reactions: the sector carries a quarter of the torque and of the axial force (its base's
  // reactions, slave-side nodes included: their RF is what crosses the boundary).
  const auto totals = [](const Model& model, const IncrementResult& inc) {
    double torque = 0, axial = 0;
    for (int n = 0; n < model.node_count(); ++n) {
      torque += model.coords[n][0] * inc.RF[n][1] - model.coords[n][1] * inc.RF[n][0];
      axial += model.coords[n][2] < 1e-9 ? inc.RF[n][2] : 0.0;
    }
    return std::make_pair(torque, axial);
  };
  const auto [full_torque, full_axial] = totals(full.model, f);
  const auto [sector_torque, sector_axial] = totals(quarter.model, q);
  EXPECT_NEAR(4 * sector_torque, full_torque, 1e-8 * std::abs(full_torque));
  EXPECT_NEAR(4 * sector_axial, full_axial, 1e-8 * std::abs(full_axial));
  EXPECT_NEAR(full_axial, -3 * full.top_area, 1e-8 * 3 * full.top_area);  // the pull: 3 x area
}

// Builds a deck with the builder, writes it, reads it back and solves it.
Solved build_and_solve(const std::string& builder, std::map<std::string, std::string> args,
                       const ElementRegistry& registry, const std::string& tag) {
  const mesher::BuildResult built = mesher::run_builder(builder, args, registry);
  const std::string path = ::testing::TempDir() + "cyclic_" + builder + "_" + tag + ".inp";
  {
    std::ofstream out(path);
    write_inp(built.model, out);
  }
  Solved s{read_inp(path, registry), {}};
  std::remove(path.c_str());
  s.results = run_static_analysis(s.model, registry, SolveOptions{}, nullptr, nullptr);
  return s;
}

// Compares the last increments of a sector and a full model node by node: the largest
// displacement difference over the largest displacement, and the contact statuses of the sector's
// slave nodes against the full model's.
struct Comparison {
  double displacement = 0;  // relative
  double pressure = 0;      // largest |p_sector - p_full| over the largest pressure
  int status_differences = 0;
  int contact_nodes = 0;
};

Comparison compare(const Solved& full, const Solved& sector,
                   const std::vector<std::string>& bodies) {
  Comparison c;
  const IncrementResult& f = full.results.increments.back();
  const IncrementResult& s = sector.results.increments.back();
  const std::vector<std::string> fb = bodies_of(full.model, bodies);
  const std::vector<std::string> sb = bodies_of(sector.model, bodies);
  for (int n = 0; n < sector.model.node_count(); ++n) {
    const int m = same_node(full.model, fb, sector.model.coords[n], sb[n]);
    EXPECT_GE(m, 0);
    if (m < 0) continue;
    for (int d = 0; d < 3; ++d)
      c.displacement = std::max(c.displacement, std::abs(s.U[n][d] - f.U[m][d]));
  }
  c.displacement /= largest(f);
  std::map<int, const ContactNodeResult*> by_node;
  double p_max = 0;
  for (const ContactNodeResult& r : f.contact) {
    by_node[r.node] = &r;
    p_max = std::max(p_max, std::abs(r.pressure));
  }
  for (const ContactNodeResult& r : s.contact) {
    const int m = same_node(full.model, fb, sector.model.coords[r.node], sb[r.node]);
    const auto it = by_node.find(m);
    EXPECT_NE(it, by_node.end());
    if (it == by_node.end()) continue;
    ++c.contact_nodes;
    c.status_differences += r.status != it->second->status ? 1 : 0;
    c.pressure = std::max(c.pressure, std::abs(r.pressure - it->second->pressure) / p_max);
  }
  return c;
}

// SPEC §4.2 model B, coarse (4 elements around a quarter, 3 along the fit), mu = 0.4: heating,
// then 300 N m as force couples on the sleeve's rim. Frictional, so the sector agrees within the
// active set's tolerance (a complementarity residual of 1e-9 of the largest force per increment):
// displacements (over the largest) and pressures (over the largest) to 1e-9, every status the
// same (measured 1.3e-11 and 7e-11).
TEST(CyclicSector, ShrinkFitModelBSectorEqualsFullModel) {
  const test::Elements elements;
  std::map<std::string, std::string> args = {
      {"model", "B"},    {"around", "4"},   {"shaft-rings", "2"}, {"sleeve-rings", "2"},
      {"fit-rows", "3"}, {"end-rows", "2"}, {"torques", "300"},   {"element", "C3D21"}};
  const Solved full = build_and_solve("shrink-fit", args, elements.registry, "full");
  args["sector"] = "yes";
  const Solved sector = build_and_solve("shrink-fit", args, elements.registry, "sector");
  ASSERT_EQ(sector.model.cyclic_symmetries.size(), 1u);
  EXPECT_EQ(sector.model.cyclic_symmetries[0].sectors, 4);
  const Comparison c = compare(full, sector, {"SHAFT", "SLEEVE"});
  std::printf("model B: %d contact nodes, displacement %.3g, pressure %.3g\n", c.contact_nodes,
              c.displacement, c.pressure);
  EXPECT_GT(c.contact_nodes, 0);
  EXPECT_EQ(c.status_differences, 0);
  EXPECT_LE(c.displacement, 1e-9);
  EXPECT_LE(c.pressure, 1e-9);
  // The contact moment about the axis: a quarter of the full model's (to the same tolerance).
  const double mf = full.results.increments.back().contact_pairs.at(0).moment[2];
  const double ms = sector.results.increments.back().contact_pairs.at(0).moment[2];
  EXPECT_NEAR(4 * ms, mf, 1e-9 * std::abs(mf));
}

// SPEC §4.5 P3G joint, coarse, frictionless: the 120 deg sector (N = 3) against the full model,
// to the active set's tolerance 1e-9 like model B (measured 4.5e-14 and 5.9e-14: the closed set
// is found exactly and the rest is linear).
TEST(CyclicSector, P3gSectorEqualsFullModel) {
  const test::Elements elements;
  std::map<std::string, std::string> args = {
      {"around", "18"},   {"arm-rows", "1"},     {"flange-rows", "1"}, {"shaft-rows", "1"},
      {"hub-rings", "2"}, {"flange-rings", "2"}, {"element", "C3D21"}};
  const Solved full = build_and_solve("p3g-joint", args, elements.registry, "full");
  args["sector"] = "yes";
  const Solved sector = build_and_solve("p3g-joint", args, elements.registry, "sector");
  const Comparison c = compare(full, sector, {"SHAFT", "HUB"});
  std::printf("P3G: %d contact nodes, displacement %.3g, pressure %.3g\n", c.contact_nodes,
              c.displacement, c.pressure);
  EXPECT_GT(c.contact_nodes, 0);
  EXPECT_EQ(c.status_differences, 0);
  EXPECT_LE(c.displacement, 1e-9);
  EXPECT_LE(c.pressure, 1e-9);
}

// SPEC §4.4 spline joint, coarse, frictionless flanks with the 0.1 radial clearance: the 120 deg
// sector (N = 3, two of the six splines) against the full model, to the active set's tolerance
// 1e-9 like the P3G joint (one flank side per spline closes; the rest is linear).
TEST(CyclicSector, SplineSectorEqualsFullModel) {
  const test::Elements elements;
  std::map<std::string, std::string> args = {
      {"tooth", "2"},     {"groove", "2"},       {"flank-rows", "1"},
      {"arm-rows", "1"},  {"flange-rows", "1"},  {"shaft-rows", "2"},
      {"hub-rings", "1"}, {"flange-rings", "2"}, {"element", "C3D21"}};
  const Solved full = build_and_solve("spline-joint", args, elements.registry, "full");
  args["sector"] = "yes";
  const Solved sector = build_and_solve("spline-joint", args, elements.registry, "sector");
  const Comparison c = compare(full, sector, {"SHAFT", "HUB"});
  std::printf("spline: %d contact nodes, displacement %.3g, pressure %.3g\n", c.contact_nodes,
              c.displacement, c.pressure);
  EXPECT_GT(c.contact_nodes, 0);
  EXPECT_EQ(c.status_differences, 0);
  EXPECT_LE(c.displacement, 1e-9);
  EXPECT_LE(c.pressure, 1e-9);
}

// The builders' sectors at their default densities (docs/mesher.md, "Sector models"): a third of
// the spline's 12000 and the P3G's 9504 elements, a quarter of model B's 12288, the cyclic tie
// with N = 3 / 4 about z, and every slave node of the tie paired with a master node (the two
// boundaries are images of each other; resolve_cyclic_symmetries throws otherwise).
TEST(CyclicSector, BuilderSectorsAtDefaultDensity) {
  const test::Elements elements;
  const struct {
    std::string builder;
    std::map<std::string, std::string> args;
    int elements, sectors;
  } cases[] = {{"spline-joint", {{"sector", "yes"}}, 4000, 3},
               {"p3g-joint", {{"sector", "yes"}}, 3168, 3},
               {"shrink-fit", {{"model", "B"}, {"sector", "yes"}}, 3072, 4}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.builder);
    const mesher::BuildResult built = mesher::run_builder(c.builder, c.args, elements.registry);
    EXPECT_EQ(built.model.element_count(), c.elements);
    ASSERT_EQ(built.model.cyclic_symmetries.size(), 1u);
    EXPECT_EQ(built.model.cyclic_symmetries[0].sectors, c.sectors);
    const std::vector<ResolvedCyclicSymmetry> ties =
        resolve_cyclic_symmetries(built.model, elements.registry);
    ASSERT_EQ(ties.size(), 1u);
    const Surface& slave = built.model.surfaces.at("CYCLIC_SLAVE");
    EXPECT_EQ(ties[0].pairs.size() + ties[0].axis_nodes.size(), slave.nodes.size());
    EXPECT_NEAR(std::abs(ties[0].angle), 2 * kPi / c.sectors, 1e-12);
    EXPECT_GT(ties[0].pairs.size(), 0u);
  }
}

// CalculiX reads the sector deck of the linear shaft (C3D20, *TIE, CYCLIC SYMMETRY, *CYCLIC
// SYMMETRY MODEL, N = 4) and solves it: its displacements equal Styk's to 1e-6 of the largest
// (ccx 2.20 in a static step applies the cyclic tie as nodal diameter 0, u_slave = Q^T u_master,
// the semantics docs/input.md states; a different reading would differ at the order of the
// displacements).
TEST(CyclicSector, CalculixSolvesTheSectorDeckAlike) {
  ASSERT_TRUE(test::ccx_on_path()) << test::kCcxMissing;
  const test::Elements elements;
  Solved quarter = solve_shaft(shaft_mesh(), true, elements.registry);
  NodeSet all;
  all.name = "NALL";
  for (int n = 0; n < quarter.model.node_count(); ++n) all.nodes.push_back(n);
  quarter.model.nsets["NALL"] = all;
  OutputRequest print;
  print.kind = OutputRequest::Kind::NodePrint;
  print.set = "NALL";
  print.vars = {"U"};
  quarter.model.steps.front().outputs = {print};
  const auto scratch = std::filesystem::path(::testing::TempDir()) / "styk_cyclic_ccx";
  std::filesystem::create_directories(scratch);
  {
    std::ofstream out(scratch / "sector.inp");
    write_inp(quarter.model, out);
  }
  ASSERT_EQ(test::run_ccx(scratch, "sector").exit_code, 0);
  std::ifstream dat(scratch / "sector.dat");
  const std::vector<DatDisplacements> ccx = parse_dat_displacements(dat);
  ASSERT_EQ(ccx.size(), 1u);
  const IncrementResult& styk = quarter.results.increments.back();
  const double scale = largest(styk);
  double worst = 0;
  for (int n = 0; n < quarter.model.node_count(); ++n) {
    const auto it = ccx[0].u.find(quarter.model.node_ids[n]);
    ASSERT_NE(it, ccx[0].u.end()) << "node " << quarter.model.node_ids[n];
    for (int d = 0; d < 3; ++d) worst = std::max(worst, std::abs(it->second[d] - styk.U[n][d]));
  }
  EXPECT_LE(worst, 1e-6 * scale);
  std::printf("linear shaft sector: CalculiX - Styk %.3g of the largest displacement\n",
              worst / scale);
  std::filesystem::remove_all(scratch);
}

}  // namespace
}  // namespace styk
