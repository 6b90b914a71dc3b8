// Builder of the SPEC §4.6 bolted flange with gasket, 1/32 model (bolted_flange_mesh.hpp has the
// geometry). Contacts gasket-flange and bolt head-flange; symmetry on the two sector planes in
// the cylindrical system (*TRANSFORM, TYPE=C: tangential displacement held) and on the gasket's
// mid-plane; step PRELOAD shortens the bolt by a prescribed displacement of its cut end, step
// PRESSURE applies the internal pressure in fixed increments with the neck-top end-cap tension.
//
// The preload: the bolt's cut end (z = 0) is pulled down by delta, i.e. the whole bolt is
// shortened by 2 delta (the nut turned), and stays there in step 2 (the nut does not turn
// further, so the bolt force follows the joint as in Rötscher's model). With coincident contact
// nodes (zero gaps) and only delta loading step 1, the contact problem is positively homogeneous:
// the bolt force is c * delta exactly, whatever opens. The builder finds c by solving step 1 at
// delta = 1 (the second calibration point is the origin) and writes delta = F / c, so the deck's
// bolt force after step 1 is the target to the solver's tolerance (`--preload-by calibration`).
// `--preload-by estimate` takes delta from the 1D springs instead (no solve; for quick decks).
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bolted_flange_mesh.hpp"
#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "contact_support.hpp"
#include "sector_support.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

using G = FlangeGeometry;
const std::vector<std::string> kFamilies = {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"};

// End-cap tension on the neck top per unit internal pressure: p pi 25^2 over the annulus
// pi (30^2 - 25^2) = 275 pi (SPEC: 2.2727 p).
constexpr double kNeckTension =
    G::kBore * G::kBore / (G::kNeckOuter * G::kNeckOuter - G::kBore * G::kBore);

struct FlangeParams {
  std::string family;
  FlangeLayout layout;
  double preload = 0;    // whole bolt, N
  double pressure = 0;   // MPa
  double increment = 0;  // MPa per increment
  double young = 0, young_gasket = 0, poisson = 0;
  std::string mu_text;
  std::optional<Friction> friction;
  bool calibrate = true;
  bool penetration = true;  // *PRESSURE PENETRATION of the gasket interface in step PRESSURE
  // The 45 deg sector around one whole bolt with a cyclic symmetry tie (N = 8) instead of the
  // 22.5 deg half with symmetry planes.
  bool cyclic = false;
  // The pipe's end-cap thrust p pi r_i^2 as a tension on the neck top (no: the pipe's axial load
  // is taken elsewhere, e.g. a pipe held at both ends; for measuring what the thrust does).
  bool end_cap = true;
};

FlangeParams read_params(const BuilderParams& p) {
  FlangeParams f;
  f.family = family(p, kFamilies);
  f.layout.gasket_half = 0.5 * p.positive("gasket-thickness");
  f.layout.gasket_rings = p.count("gasket-rings", 2);
  f.layout.neck_rings = p.count("neck-rings");
  if (f.layout.neck_rings >= f.layout.gasket_rings)
    p.fail(
        "--neck-rings must be smaller than --gasket-rings (the neck wall is part of the gasket's "
        "width)");
  f.layout.ring_layers = p.count("ring-layers", 2);
  f.layout.ring_thickness = p.positive("ring-thickness");
  f.end_cap = p.choice("end-cap", {"yes", "no"}) == "yes";
  f.layout.neck_layers = p.count("neck-layers");
  f.layout.gasket_layers = p.count("gasket-layers");
  f.layout.outer_rings = p.count("outer-rings");
  f.layout.shank_layers = p.count("shank-layers");
  f.layout.head_layers = p.count("head-layers");
  f.preload = 1000 * p.positive("preload");
  f.pressure = p.number("pressure");
  if (f.pressure < 0) p.fail("--pressure must be >= 0");
  f.increment = p.positive("pressure-increment");
  f.young = p.positive("young");
  f.young_gasket = p.positive("young-gasket");
  f.poisson = p.number("poisson");
  if (!(f.poisson > -1 && f.poisson < 0.5)) p.fail("--poisson must lie in (-1, 0.5)");
  f.mu_text = p.text("mu");
  f.friction = friction_parameter(p, "mu");
  f.calibrate = p.choice("preload-by", {"calibration", "estimate"}) == "calibration";
  // *PRESSURE PENETRATION is a Styk extension: the decks CalculiX must run (C3D8, C3D20) leave it
  // out unless asked for.
  const std::string penetration = p.choice("penetration", {"auto", "yes", "no"});
  f.penetration =
      penetration == "yes" || (penetration == "auto" && f.family != "C3D8" && f.family != "C3D20");
  f.cyclic = p.choice("sector", {"no", "yes"}) == "yes";
  return f;
}

// The nodes of an element set's elements that satisfy `where`.
std::vector<int> set_nodes_where(const Mesh& mesh, const std::string& elset,
                                 const std::function<bool(const Vec3&)>& where) {
  std::vector<int> out;
  for (int e : mesh.element_sets.at(elset))
    for (int node : mesh.elements[e].nodes)
      if (where(mesh.nodes[node])) out.push_back(node);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The half bolt's force in the model: minus the axial reactions at its cut end (the end is pulled
// down, the head pressed up), at the last increment of step `step`.
double sector_bolt_force(const Results& results, const std::vector<int>& bolt_end, int step) {
  const IncrementResult* last = nullptr;
  for (const IncrementResult& inc : results.increments)
    if (inc.step == step) last = &inc;
  if (!last) throw std::logic_error("bolted flange: step " + std::to_string(step) + " not solved");
  double force = 0;
  for (int node : bolt_end) force -= last->RF[node][2];
  return force;
}

// Rötscher's springs for the 1/32 model: half the shank over the half grip (mid-plane to the
// head), in series with the flange ring and the half gasket, both over the gasket's sector area
// (the cyclic sector: the whole shank over twice that area).
double estimated_shortening(const FlangeParams& f, double sector_force) {
  const double share = f.cyclic ? 2.0 : 1.0;
  const double grip = f.layout.gasket_half + f.layout.ring_thickness;
  const double bolt = share * 0.5 * 3.14159265358979323846 * G::kShankRadius * G::kShankRadius;
  const double gasket =
      share * 0.5 * G::kSector * (G::kGasketOuter * G::kGasketOuter - G::kBore * G::kBore);
  const double compliance = grip / (bolt * f.young) + f.layout.ring_thickness / (gasket * f.young) +
                            f.layout.gasket_half / (gasket * f.young_gasket);
  return sector_force * compliance;
}

Step preload_step(const std::string& family, const std::vector<int>& bolt_end, double delta) {
  Step step = static_step();
  step.name = "PRELOAD";
  for (int node : bolt_end) step.boundaries.push_back({node, 3, -delta, {}});
  step.outputs = {contact_print(family),
                  print_request(OutputRequest::Kind::NodePrint, "BOLT_END", {"RF"}, true)};
  return step;
}

// *PRESSURE PENETRATION of the gasket interface in step `pressure`: the fluid enters at the bore
// (r = 25) and leaks once it reaches the gasket's outer edge (r = 54) along some path of opened
// nodes (node sets GASKET_INNER, FLANGE_INNER, GASKET_OUTER).
void add_pressure_penetration(Model& model, const Mesh& mesh, double p, Step& pressure) {
  const double tol = 1e-7 * mesh.size();
  const auto at_radius = [&](const std::string& surface, double radius) {
    std::vector<int> out;
    for (int node : mesh.surface_nodes(surface))
      if (std::abs(std::hypot(mesh.nodes[node][0], mesh.nodes[node][1]) - radius) < tol)
        out.push_back(node);
    return out;
  };
  add_node_set(model, "GASKET_INNER", at_radius("GASKET_FACE", G::kBore));
  add_node_set(model, "FLANGE_INNER", at_radius("FLANGE_FACE", G::kBore));
  add_node_set(model, "GASKET_OUTER", at_radius("GASKET_FACE", G::kGasketOuter));
  PressurePenetration pp;
  pp.slave = "GASKET_FACE";
  pp.master = "FLANGE_FACE";
  pp.exposed_slave = model.nsets.at("GASKET_INNER").nodes;
  pp.exposed_master = model.nsets.at("FLANGE_INNER").nodes;
  pp.pressure = p;
  pp.leak_nset = "GASKET_OUTER";
  pressure.penetrations.push_back(pp);
}

// The mesh: gasket, flange and bolt, mirrored about the bolt's plane y = 0 for the cyclic sector
// (whose boundary faces, theta = -22.5 and +22.5 deg, are recorded for the tie), the bore and the
// neck top as load surfaces, the bodies split at their interfaces and the contact layers
// converted (SPEC: C3D21/C3D28 at the gasket, C3D21 under the bolt head: a C3D28 layer under the
// head could not close, the head's inner ring continuing into the shank).
void mesh_flange(Mesh& mesh, const ElementRegistry& registry, const FlangeParams& f,
                 const BuilderParams& p) {
  try {
    mesh_bolted_flange(mesh, base_type(registry, f.family), f.layout);
  } catch (const std::invalid_argument& e) {
    p.fail(e.what());
  }
  if (f.cyclic) mirror_about_xz(mesh);
  merge_coincident_nodes(mesh);
  const double tol = 1e-7 * mesh.size();
  if (f.cyclic) {
    mesh.add_to_surface(kCyclicSlaveFaces, faces_on_half_plane(mesh, -G::kSector, tol));
    mesh.add_to_surface(kCyclicMasterFaces, faces_on_half_plane(mesh, G::kSector, tol));
  }
  const double z_neck = f.layout.gasket_half + f.layout.ring_thickness + G::kNeckHeight;
  std::vector<int> walls = mesh.element_sets.at("FLANGE");
  walls.insert(walls.end(), mesh.element_sets.at("GASKET").begin(),
               mesh.element_sets.at("GASKET").end());
  mesh.add_to_surface("BORE", faces_where(mesh, walls, [&](const Vec3& x) {
                        return std::abs(std::hypot(x[0], x[1]) - G::kBore) < tol;
                      }));
  mesh.add_to_surface("NECK_TOP", faces_where(mesh, mesh.element_sets.at("FLANGE"),
                                              [&](const Vec3& x) { return x[2] > z_neck - tol; }));
  split_bodies(mesh, "GASKET", "GASKET_FACE", "FLANGE_FACE");
  split_bodies(mesh, "BOLT", "HEAD_FACE", "FLANGE_SEAT");
  for (const char* body : {"FLANGE", "GASKET", "BOLT"})
    mesh.add_to_element_set("EALL", mesh.element_sets.at(body));
  convert_contact_layers(mesh, registry, f.family, {"GASKET_FACE", "FLANGE_FACE"});
  convert_contact_layers(mesh, registry, f.family == "C3D28" ? "C3D21" : f.family,
                         {"HEAD_FACE", "FLANGE_SEAT"});
}

// Supports. The 1/32 model: both sector planes (theta = 0 and 22.5 deg) hold the tangential
// displacement in a cylindrical *TRANSFORM. The cyclic sector: the tie joins theta = -22.5 and
// 22.5 deg, and the bolt's plane y = 0 keeps its mirror symmetry (uy held): frictionless contacts
// cannot hold the parts' turn about the axis, which the tie leaves free. Both: the gasket's
// mid-plane in z; frictionless, the bolt's axis node at its cut end along x (nothing else holds
// the bolt radially; no force reaches it).
void add_flange_supports(Model& model, const Mesh& mesh, const FlangeParams& f,
                         const SectorBoundary* boundary) {
  const double tol = 1e-7 * mesh.size();
  if (boundary == nullptr) {
    const double s = std::sin(G::kSector), c = std::cos(G::kSector);
    const auto sector = nodes_where(mesh, [&](const Vec3& x) {
      return std::abs(x[1]) < tol || std::abs(-s * x[0] + c * x[1]) < tol;
    });
    add_node_set(model, "SECTOR_PLANES", sector);
    Transform cylindrical;
    cylindrical.nset = "SECTOR_PLANES";
    cylindrical.axes.system = CoordinateSystem::Cylindrical;
    cylindrical.axes.a = {0, 0, 0};
    cylindrical.axes.b = {0, 0, 1};
    model.transforms.push_back(cylindrical);
    fix(model, sector, {2});
  } else {
    const auto plane = nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; });
    add_node_set(model, "BOLT_PLANE", plane);
    fix(model, plane, {2});
  }
  const auto gasket_mid =
      set_nodes_where(mesh, "GASKET", [&](const Vec3& x) { return x[2] < tol; });
  add_node_set(model, "GASKET_MID", gasket_mid);
  if (boundary != nullptr)
    fix_in_sector(model, *boundary, gasket_mid, {3});
  else
    fix(model, gasket_mid, {3});
  if (f.friction) return;
  const auto axis = set_nodes_where(mesh, "BOLT", [&](const Vec3& x) {
    return std::hypot(x[0] - G::kPitchRadius, x[1]) < tol && x[2] < tol;
  });
  add_node_set(model, "BOLT_HOLD", axis);
  fix(model, axis, {1});
}

// Step 1's shortening: calibrated with one solve at unit shortening, or estimated.
double preload_shortening(const Model& model, const FlangeParams& f, const BuilderParams& p,
                          const std::vector<int>& bolt_end, double bolt_force, std::string& note) {
  double delta = estimated_shortening(f, bolt_force);
  if (!f.calibrate) {
    note = "preload by estimate (1D springs): cut end moves by " + fmt_number(delta) +
           "; the bolt force after PRELOAD differs from " + fmt_number(bolt_force) +
           " N by the flange's bending. ";
    return delta;
  }
  Model unit = model;
  unit.steps = {preload_step(f.family, bolt_end, 1.0)};
  const Results solved = p.solve(unit, "--preload-by calibration", "--preload-by estimate");
  const double per_unit = sector_bolt_force(solved, bolt_end, 1);
  if (!(per_unit > 0))
    throw std::logic_error("bolted flange: calibration gave a bolt force of " +
                           fmt_number(per_unit) + " per unit shortening");
  delta = bolt_force / per_unit;
  note = "preload by calibration: a unit shortening of the bolt's cut end carries " +
         fmt_number(per_unit) + " N, so the cut end moves by " + fmt_number(delta) + " for " +
         fmt_number(bolt_force) + " N (" + (f.cyclic ? "the whole bolt" : "half of ") +
         (f.cyclic ? "" : fmt_number(f.preload) + " N") + "). ";
  return delta;
}

// Step 2: internal pressure in fixed increments of at most `increment` MPa, with the end-cap
// tension on the neck top and, when asked, the pressure penetrating the gasket interface.
Step pressure_step(Model& model, const Mesh& mesh, const FlangeParams& f) {
  Step pressure = static_step();
  pressure.name = "PRESSURE";
  const int increments = std::max(1, static_cast<int>(std::ceil(f.pressure / f.increment - 1e-9)));
  pressure.procedure.initial_increment = 1.0 / increments;
  pressure.procedure.fixed_increments = true;
  pressure_on(pressure, mesh, "BORE", f.pressure);
  if (f.end_cap) pressure_on(pressure, mesh, "NECK_TOP", -kNeckTension * f.pressure);
  pressure.outputs = model.steps.back().outputs;
  if (f.penetration) add_pressure_penetration(model, mesh, f.pressure, pressure);
  return pressure;
}

BuildResult bolted_flange(const BuilderParams& p, const ElementRegistry& registry) {
  const FlangeParams f = read_params(p);
  BuildResult r;
  Mesh& mesh = r.mesh;
  mesh_flange(mesh, registry, f, p);
  // The 1/32 model holds half the bolt; the cyclic sector a whole one.
  const double bolt_force = f.cyclic ? f.preload : 0.5 * f.preload;
  r.model = contact_model(
      mesh,
      "SPEC 4.6 bolted flange with gasket, " +
          std::string(f.cyclic ? "1/16 model (45 deg sector around one bolt, cyclic symmetry, N = "
                                 "8; half joint), "
                               : "1/32 model (22.5 deg sector, half joint), ") +
          f.family + ": flange D50/D165 x " + fmt_number(f.layout.ring_thickness) +
          ", neck D60/D50 x 30, gasket D50/D108 x " + fmt_number(2 * f.layout.gasket_half) +
          " (E " + fmt_number(f.young_gasket) + "), M16 on PCD 130, mu = " + f.mu_text +
          "; preload " + fmt_number(f.preload / 1000) + " kN (" + fmt_number(bolt_force / 1000) +
          " kN in the " + (f.cyclic ? "sector's bolt" : "half bolt of the sector") + "), then " +
          fmt_number(f.pressure) + " MPa inside" +
          (f.end_cap ? "" : " without the end-cap thrust") +
          (f.penetration ? ", penetrating the opened gasket interface" : "") +
          ". Published: leak at 16 MPa (experiment 16.5)",
      {{"FLANGE", "STEEL_FLANGE", f.young, f.poisson, {}},
       {"GASKET", "ALUMINIUM", f.young_gasket, f.poisson, {}},
       {"BOLT", "STEEL_BOLT", f.young, f.poisson, {}}});
  add_surfaces(r.model, mesh,
               {"GASKET_FACE", "FLANGE_FACE", "HEAD_FACE", "FLANGE_SEAT", "BORE", "NECK_TOP"});
  add_contact(r.model, "GASKET", "GASKET_FACE", "FLANGE_FACE", f.friction);
  add_contact(r.model, "HEAD", "HEAD_FACE", "FLANGE_SEAT", f.friction);
  const double tol = 1e-7 * mesh.size();
  SectorBoundary boundary;
  if (f.cyclic) {
    boundary = sector_boundary(mesh, 8, tol);
    add_cyclic_symmetry(r.model, boundary);
  }
  add_flange_supports(r.model, mesh, f, f.cyclic ? &boundary : nullptr);
  const auto bolt_end = set_nodes_where(mesh, "BOLT", [&](const Vec3& x) { return x[2] < tol; });
  add_node_set(r.model, "BOLT_END", bolt_end);

  const double delta = preload_shortening(r.model, f, p, bolt_end, bolt_force, r.note);
  r.model.steps.push_back(preload_step(f.family, bolt_end, delta));
  r.model.steps.push_back(pressure_step(r.model, mesh, f));
  if (!f.penetration)
    r.note +=
        "Not modelled: pressure penetration (the pressure acting on gasket/flange faces once "
        "they separate; --penetration yes adds the Styk-only *PRESSURE PENETRATION).";
  return r;
}

}  // namespace

void add_bolted_flange_builder(std::vector<BuilderInfo>& all) {
  all.push_back(
      {"bolted-flange",
       "§4.6",
       "Bolted flange with gasket (stand-in JIS 10K 50A-like), 1/32 model: preload, then internal "
       "pressure",
       {family_param("C3D21", kFamilies),
        {"preload", "15", "bolt preload in kN (whole bolt; the sector carries half; 7.5, 10, 20)"},
        {"preload-by", "calibration",
         "calibration (one solve at unit shortening: exact bolt force) or estimate (1D springs)"},
        {"pressure", "16", "internal pressure p in MPa (step 2; neck top pulled by 2.2727 p)"},
        {"pressure-increment", "2", "largest pressure increment in MPa (fixed increments)"},
        {"penetration", "auto",
         "the internal pressure penetrates the opened gasket interface (*PRESSURE PENETRATION, "
         "Styk-only; leak when it reaches the gasket's outer edge): yes, no, auto = yes except "
         "for the CalculiX families C3D8 and C3D20"},
        {"gasket-thickness", "5", "gasket thickness (the model holds half; variant 3.5)"},
        {"ring-thickness", "20", "flange ring thickness (stand-in; the thesis' figure is lost)"},
        {"end-cap", "yes",
         "yes: the end-cap thrust p pi 25^2 pulls the neck top (2.2727 p); no: left out (the "
         "pipe's axial load taken elsewhere)"},
        {"sector", "no",
         "yes: the 45 deg sector around one whole bolt with *TIE, CYCLIC SYMMETRY (N = 8) "
         "instead of the 22.5 deg half with symmetry planes (the bolt's plane keeps its mirror "
         "symmetry)"},
        {"mu", "0", "friction coefficient of both contacts (0 = frictionless; 'rough')"},
        {"young", "206000", "E of flange and bolt (MPa)"},
        {"young-gasket", "68700", "E of the aluminium gasket (MPa)"},
        {"poisson", "0.3", "Poisson's ratio of all parts"},
        {"gasket-rings", "8", "radial elements of the gasket (8 x 8 contact elements)"},
        {"neck-rings", "3", "radial elements of the neck wall"},
        {"ring-layers", "20", "elements through the flange ring's thickness (>= 2)"},
        {"neck-layers", "15", "elements along the neck"},
        {"gasket-layers", "3", "elements through the half gasket"},
        {"outer-rings", "1", "radial elements between the bolt region and the rim"},
        {"shank-layers", "6", "elements along the half shank"},
        {"head-layers", "2", "elements through the bolt head"}},
       bolted_flange});
}

}  // namespace styk::mesher::detail
