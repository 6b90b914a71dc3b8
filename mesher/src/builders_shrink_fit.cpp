// Builder of the SPEC §4.2 shrink fit: shaft L 60, Ø20, sleeve L 20, Ø20/Ø30, centred; model A
// (quarter, symmetry planes x = 0 and y = 0) and model B (full). The shaft's cross-section is an
// O-grid (a square core and two ring blocks per quarter); the full model is four quarters merged.
// Step 1 heats the shaft by dT (alpha = 2e-5: interference 0.02 on the radius); the next steps push
// the sleeve axially (load case axial) or twist it (load case torque), one step per load level.
// The notched variants I and II (SPEC §4.2, Fig 4.20-4.23; their geometry is in the thesis' lost
// figures) are stand-ins: I cuts a relief groove into each end face of the sleeve next to the bore,
// II turns the sleeve's outer diameter down towards both end faces; both soften the fit's edges.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "contact_support.hpp"
#include "sector_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

constexpr double kShaftRadius = 10, kSleeveRadius = 15, kShaftLength = 60;
constexpr double kFitStart = 20, kFitEnd = 40;

struct FitMesh {
  int around = 12;      // elements around a quarter (even)
  int shaft_rings = 5;  // radial elements of the shaft's outer ring blocks
  int sleeve_rings = 4;
  int fit_rows = 12;  // axial elements along the sleeve
  int end_rows = 7;   // axial elements of each free shaft end
  double core = 0.5;  // core half-width / shaft radius
};

// The notched variants' stand-in geometry (the thesis' Fig 4.20 / 4.22 are lost). Variant I: a
// relief groove cut axially into each end face of the sleeve, `groove_width` wide radially at
// `groove_lip` outside the bore and `groove_depth` deep (rounded to whole fit rows, so the
// sleeve's bore keeps the shaft's node rows): the bore's edge becomes a flexible lip. Variant II:
// the sleeve's outer radius falls linearly from R_o over the last `relief_length` at each end to
// R_o - `relief_depth` at the end faces.
enum class Notch { None, FaceGroove, SleeveRelief };
struct NotchShape {
  Notch notch = Notch::None;
  double groove_lip = 1.5, groove_width = 1.0, groove_depth = 5.0;
  double relief_depth = 2.5, relief_length = 5.0;

  double sleeve_outer_radius(double z) const {
    if (notch != Notch::SleeveRelief) return kSleeveRadius;
    const double to_edge = std::min(z - kFitStart, kFitEnd - z);
    return kSleeveRadius - relief_depth * std::max(0.0, 1 - to_edge / relief_length);
  }
  // Variant I: fit rows each groove takes (at least one, leaving at least one between them).
  int groove_rows(int fit_rows) const {
    const double row = (kFitEnd - kFitStart) / fit_rows;
    return std::max(1, static_cast<int>(std::lround(groove_depth / row)));
  }
};

// The sleeve's block between the wall fractions f0 and f1 (r = R_i + f (R_o(z) - R_i)) and the
// heights z0, z1, turned by `angle` over `sweep`.
BlockMap sleeve_block(const NotchShape& notch, double f0, double f1, double z0, double z1,
                      double angle, double sweep) {
  return [=](const Vec3& xi) {
    const double height = z0 + (z1 - z0) * 0.5 * (xi[2] + 1);
    const double f = f0 + (f1 - f0) * 0.5 * (xi[0] + 1), a = angle + sweep * 0.5 * (xi[1] + 1);
    const double r = kShaftRadius + f * (notch.sleeve_outer_radius(height) - kShaftRadius);
    return Vec3{r * std::cos(a), r * std::sin(a), height};
  };
}

// The sleeve: one block, or (variant I) three radial bands (lip, groove, rest) times three axial
// segments with the groove band left out of the two end segments.
void mesh_sleeve(Mesh& mesh, const std::string& type, const FitMesh& m, const NotchShape& notch,
                 double angle, double sweep, int around) {
  if (notch.notch != Notch::FaceGroove) {
    const Block b = mesh_block(mesh, sleeve_block(notch, 0, 1, kFitStart, kFitEnd, angle, sweep),
                               {type, {m.sleeve_rings, around, m.fit_rows}, {1, 1, 1}, "SLEEVE"});
    mesh.add_to_surface("SLEEVE_TOP", b.side_faces(2, +1));
    return;
  }
  const double wall = kSleeveRadius - kShaftRadius;
  const double f_lip = notch.groove_lip / wall, f_groove = f_lip + notch.groove_width / wall;
  const double bands[4] = {0, f_lip, f_groove, 1};
  const int band_rings[3] = {1, 1, std::max(1, m.sleeve_rings - 2)};
  const int g = notch.groove_rows(m.fit_rows);
  const double h = g * (kFitEnd - kFitStart) / m.fit_rows;
  const double z[4] = {kFitStart, kFitStart + h, kFitEnd - h, kFitEnd};
  const int rows[3] = {g, m.fit_rows - 2 * g, g};
  for (int band = 0; band < 3; ++band)
    for (int seg = 0; seg < 3; ++seg) {
      if (band == 1 && seg != 1) continue;  // the grooves
      const Block b = mesh_block(
          mesh, sleeve_block(notch, bands[band], bands[band + 1], z[seg], z[seg + 1], angle, sweep),
          {type, {band_rings[band], around, rows[seg]}, {1, 1, 1}, "SLEEVE"});
      if (seg == 2) mesh.add_to_surface("SLEEVE_TOP", b.side_faces(2, +1));
    }
}

// A sector of the shaft and the sleeve from `angle` over `sweep` (at most 90 deg) with `around`
// elements around (even): the quarter of models A and B, or model C's thin sector.
void mesh_sector(Mesh& mesh, const std::string& type, const FitMesh& m, const NotchShape& notch,
                 double angle, double sweep, int around) {
  const int n = around / 2;
  const auto shaft = [](double) { return kShaftRadius; };
  const std::vector<SectionPatch> o_grid = sector_o_grid(m.core, sweep);
  const double z[4] = {0, kFitStart, kFitEnd, kShaftLength};
  const int rows[3] = {m.end_rows, m.fit_rows, m.end_rows};
  for (int k = 0; k < 3; ++k)
    for (int part = 0; part < 3; ++part)
      mesh_block(mesh, prism(o_grid[part], z[k], z[k + 1], shaft, angle),
                 {type, {part == 0 ? n : m.shaft_rings, n, rows[k]}, {1, 1, 1}, "SHAFT"});
  mesh_sleeve(mesh, type, m, notch, angle, sweep, around);
}

std::vector<double> number_list(const BuilderParams& p, const std::string& name) {
  std::vector<double> out;
  std::stringstream in(p.text(name));
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v))
      p.fail("--" + name + ": expected comma-separated numbers, not '" + p.text(name) + "'");
    out.push_back(v);
  }
  if (out.empty()) p.fail("--" + name + " is empty");
  return out;
}

// Tangential nodal forces on the ring of nodes at radius r, height z (a closed circle, or an open
// arc from the lowest angle to the highest: a sector's): a uniform line load of total moment
// `torque` about z, distributed as the consistent loads of the element edges (linear edges:
// halves; quadratic: 1/6, 2/3, 1/6).
std::vector<ConcentratedLoad> torque_loads(const Mesh& mesh, const std::vector<int>& ring, double r,
                                           double torque, bool quadratic, bool closed) {
  std::vector<std::pair<double, int>> by_angle;
  for (int node : ring) {
    double a = std::atan2(mesh.nodes[node][1], mesh.nodes[node][0]);
    if (a < -1e-9) a += 2 * kPi;
    by_angle.push_back({a, node});
  }
  std::sort(by_angle.begin(), by_angle.end());
  const int count = static_cast<int>(by_angle.size());
  const int step = quadratic ? 2 : 1;
  // A closed circle: every node starts one edge piece; an arc: all but the last.
  const int edges = closed ? count / step : (count - 1) / step;
  std::vector<double> weight(count, 0.0);
  for (int e = 0; e < edges; ++e) {
    const int i0 = e * step;
    if (quadratic) {
      weight[i0] += 1.0 / 6;
      weight[i0 + 1] += 2.0 / 3;
      weight[(i0 + 2) % count] += 1.0 / 6;
    } else {
      weight[i0] += 0.5;
      weight[(i0 + 1) % count] += 0.5;
    }
  }
  std::vector<ConcentratedLoad> loads;
  const double per_edge = torque / r / edges;  // tangential force per edge piece
  for (int i = 0; i < count; ++i) {
    // Components below 1e-12 of the force are round-off of sin/cos at multiples of 90 deg:
    // written as such they need more than CalculiX's 20-character fields.
    const double a = by_angle[i].first, f = per_edge * weight[i];
    const double fx = -f * std::sin(a), fy = f * std::cos(a);
    if (std::abs(fx) > 1e-12 * std::abs(f)) loads.push_back({by_angle[i].second, 1, fx, {}});
    if (std::abs(fy) > 1e-12 * std::abs(f)) loads.push_back({by_angle[i].second, 2, fy, {}});
  }
  return loads;
}

// Model C's symmetry planes: theta = 0 holds y; theta = sweep holds the tangential displacement
// through a cylindrical *TRANSFORM (the heating and the axial load are axisymmetric, so a sector
// sees what the whole joint sees); the nodes on the axis lie on both planes and hold x and y.
void hold_sector_planes(Model& model, const Mesh& mesh, double sweep, double tol) {
  std::vector<int> axis, first, second;
  for (int node = 0; node < static_cast<int>(mesh.nodes.size()); ++node) {
    const Vec3& x = mesh.nodes[node];
    const double r = std::hypot(x[0], x[1]);
    if (r < tol)
      axis.push_back(node);
    else if (std::abs(x[1]) < tol)
      first.push_back(node);
    else if (std::abs(x[0] * std::sin(sweep) - x[1] * std::cos(sweep)) < tol)
      second.push_back(node);
  }
  fix(model, axis, {1, 2});
  fix(model, first, {2});
  add_node_set(model, "SECTOR_PLANE", second);
  Transform t;
  t.nset = "SECTOR_PLANE";
  t.axes.system = CoordinateSystem::Cylindrical;
  t.axes.a = {0, 0, 0};
  t.axes.b = {0, 0, 1};
  model.transforms.push_back(t);
  fix(model, second, {2});
}

// Model B as a 90 deg sector (N = 4): the quarter 0..90 deg of the full mesh with a cyclic
// symmetry tie between its faces y = 0 (slave) and x = 0 (master).
constexpr int kFitSectors = 4;

// The builder's parameters, checked.
struct FitCase {
  std::string family, model_name, load_case, fit, mu_text;
  std::string base;          // the brick type the family is meshed from (C3D8 or C3D20)
  bool full = false;         // model B
  bool sector = false;       // model B as a 90 deg sector with cyclic symmetry (--sector yes)
  bool thin = false;         // model C: a thin sector between two symmetry planes
  int thin_around = 2;       // model C: elements around
  double sweep = 0.5 * kPi;  // angle of a quarter, or of model C's sector
  FitMesh mesh;
  NotchShape notch;
  double alpha = 0, dT = 0;
  std::optional<Friction> friction;
};

FitCase read_fit_case(const BuilderParams& p, const ElementRegistry& registry) {
  FitCase c;
  c.family = family(p, kAllHexFamilies);
  c.base = base_type(registry, c.family);
  c.model_name = to_upper(p.choice("model", {"A", "B", "C"}));
  c.full = c.model_name == "B";
  c.thin = c.model_name == "C";
  c.load_case = p.choice("load-case", {"auto", "axial", "torque", "rotation", "fit"});
  if (c.load_case == "auto") c.load_case = c.full ? "torque" : "axial";
  if ((c.load_case == "torque" || c.load_case == "rotation") && !c.full)
    p.fail("--load-case " + c.load_case + " needs --model B: a " +
           std::string(c.thin ? "sector" : "quarter") +
           " model with symmetry planes cannot carry a torque (model B with --sector yes is the "
           "quarter with cyclic symmetry)");
  c.sector = p.choice("sector", {"no", "yes"}) == "yes";
  if (c.sector && !c.full) p.fail("--sector yes needs --model B (model A is already a quarter)");
  c.fit = p.choice("fit", {"thermal", "clearance"});
  const std::string notch = to_upper(p.choice("notch", {"none", "I", "II"}));
  c.notch.notch = notch == "I"    ? Notch::FaceGroove
                  : notch == "II" ? Notch::SleeveRelief
                                  : Notch::None;
  c.notch.groove_lip = p.positive("groove-lip");
  c.notch.groove_width = p.positive("groove-width");
  c.notch.groove_depth = p.positive("groove-depth");
  c.notch.relief_depth = p.positive("relief-depth");
  c.notch.relief_length = p.positive("relief-length");
  if (c.notch.groove_lip + c.notch.groove_width >= kSleeveRadius - kShaftRadius)
    p.fail("--groove-lip + --groove-width must stay below the sleeve's wall 5");
  if (c.notch.relief_depth >= kSleeveRadius - kShaftRadius ||
      c.notch.relief_length > 0.5 * (kFitEnd - kFitStart))
    p.fail(
        "--relief-depth must stay below the sleeve's wall 5 and --relief-length at most half "
        "the sleeve's length 10");
  if (c.notch.notch == Notch::SleeveRelief &&
      (c.load_case == "torque" || c.load_case == "rotation"))
    p.fail("--notch II turns the sleeve's outer diameter down at its ends, where load case " +
           c.load_case + " acts on the outer circle of radius 15: use --notch none or I");
  c.mesh.around = p.count("around", 2);
  if (c.mesh.around % 2 != 0) p.fail("--around must be even (two O-grid blocks per quarter)");
  c.thin_around = p.count("sector-around", 2);
  if (c.thin_around % 2 != 0 || c.thin_around > c.mesh.around)
    p.fail("--sector-around must be even (two O-grid blocks) and at most --around (" +
           std::to_string(c.mesh.around) + ")");
  if (c.thin) c.sweep = 0.5 * kPi * c.thin_around / c.mesh.around;
  c.mesh.shaft_rings = p.count("shaft-rings");
  c.mesh.sleeve_rings = p.count("sleeve-rings");
  c.mesh.fit_rows = p.count("fit-rows");
  c.mesh.end_rows = p.count("end-rows");
  if (c.notch.notch == Notch::FaceGroove &&
      2 * c.notch.groove_rows(c.mesh.fit_rows) >= c.mesh.fit_rows)
    p.fail("--groove-depth " + fmt_number(c.notch.groove_depth) + " takes " +
           std::to_string(c.notch.groove_rows(c.mesh.fit_rows)) + " of the " +
           std::to_string(c.mesh.fit_rows) +
           " fit rows at each end: the grooves must leave rows between them");
  c.alpha = p.positive("alpha");
  c.dT = p.number("dT");
  c.mu_text = p.text("mu");
  if (to_upper(c.mu_text) == "AUTO")
    c.mu_text = c.load_case == "torque" || c.load_case == "rotation" ? "0.4" : "0.2";
  c.friction = friction_value(p, "mu", c.mu_text);
  return c;
}

void add_cylindrical_transform(Model& model, const std::string& nset) {
  Transform t;
  t.nset = nset;
  t.axes.system = CoordinateSystem::Cylindrical;
  t.axes.a = {0, 0, 0};
  t.axes.b = {0, 0, 1};
  model.transforms.push_back(t);
}

// Supports: the shaft base axially; model A its symmetry planes, model B the base centre across
// and the rest of the base tangentially (cylindrical *TRANSFORM: carries the torque, leaves the
// thermal growth free); frictionless, one sleeve node along (and about) the axis. In the sector
// (`boundary` not null) the slave side follows its master side and the tie holds the axis nodes
// on the axis, so fix_in_sector skips them.
void add_fit_supports(Model& model, const Mesh& mesh, const FitCase& c,
                      const SectorBoundary* boundary) {
  const double tol = 1e-7 * mesh.size();
  const auto hold = [&](const std::vector<int>& nodes, std::initializer_list<int> dofs) {
    if (boundary != nullptr)
      fix_in_sector(model, *boundary, nodes, dofs);
    else
      fix(model, nodes, dofs);
  };
  const auto base = nodes_where(mesh, [&](const Vec3& x) { return x[2] < tol; });
  const auto end = nodes_where(mesh, [&](const Vec3& x) { return x[2] > kShaftLength - tol; });
  add_node_set(model, "SHAFT_BASE", base);
  add_node_set(model, "SHAFT_END", end);
  hold(base, {3});
  if (c.thin) {
    hold_sector_planes(model, mesh, c.sweep, tol);
  } else if (!c.full) {
    fix(model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol; }), {1});
    fix(model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; }), {2});
  } else {
    std::vector<int> centre, ring;
    for (int node : base)
      (std::hypot(mesh.nodes[node][0], mesh.nodes[node][1]) < tol ? centre : ring).push_back(node);
    if (boundary == nullptr) fix(model, centre, {1, 2});
    add_node_set(model, "SHAFT_BASE_RING", ring);
    add_cylindrical_transform(model, "SHAFT_BASE_RING");
    hold(ring, {2});
  }
  if (c.friction) return;
  // Frictionless: nothing holds the sleeve along (and, in model B, about) the axis. One node on
  // its outer mid-plane is held there; with mu = 0 no force can reach it. (The sector takes the
  // node on its master side, x = 0, where x is the tangential direction.)
  const bool sector = boundary != nullptr;
  const auto hold_node = nodes_where(mesh, [&](const Vec3& x) {
    const double along = sector ? x[1] : x[0], across = sector ? x[0] : x[1];
    return std::abs(along - kSleeveRadius) < tol && std::abs(across) < tol &&
           std::abs(x[2] - 0.5 * (kFitStart + kFitEnd)) <
               0.5 * (kFitEnd - kFitStart) / c.mesh.fit_rows + tol;
  });
  add_node_set(model, "SLEEVE_HOLD", {hold_node.at(0)});
  if (c.full)
    fix(model, {hold_node.at(0)}, {sector ? 1 : 2, 3});
  else
    fix(model, {hold_node.at(0)}, {3});
}

// Step FIT: the shaft heated by dT (thermal fit), or nothing but the *CLEARANCE closing.
Step heating_step(Model& model, const Mesh& mesh, const FitCase& c) {
  Step heat = static_step();
  heat.name = "FIT";
  heat.procedure.initial_increment = 0.25;
  if (c.fit != "thermal") return heat;
  for (int node = 0; node < model.node_count(); ++node)
    model.initial_temperatures.push_back({node, 0.0, {}});
  for (int e : mesh.element_sets.at("SHAFT"))
    for (int node : mesh.elements[e].nodes) heat.temperatures.push_back({node, c.dT, {}});
  std::sort(heat.temperatures.begin(), heat.temperatures.end(),
            [](const NodalTemperature& a, const NodalTemperature& b) { return a.node < b.node; });
  heat.temperatures.erase(std::unique(heat.temperatures.begin(), heat.temperatures.end(),
                                      [](const NodalTemperature& a, const NodalTemperature& b) {
                                        return a.node == b.node;
                                      }),
                          heat.temperatures.end());
  return heat;
}

// The load steps after FIT: axial pushes, torques as force couples on the sleeve's rim, or the
// rim turned by a prescribed angle (rotation control: the rim circle's nodes turn about the axis,
// tangential displacement r theta in their cylindrical system with radial and axial free, so the
// torque follows from the reactions and the curve continues past the friction capacity;
// automatic increments of at most 1/20 of the angle).
void add_load_steps(Model& model, const Mesh& mesh, const FitCase& c, const BuilderParams& p,
                    const std::vector<int>& rim, const std::vector<OutputRequest>& outputs,
                    const SectorBoundary* boundary) {
  const bool quadratic = c.base == "C3D20";
  const int parts = boundary != nullptr ? kFitSectors : 1;  // 1/parts of the joint's torque
  int index = 1;
  if (c.load_case == "fit") return;
  if (c.load_case == "axial") {
    for (double pressure : number_list(p, "pressures")) {
      Step push = static_step();
      push.name = "PUSH" + std::to_string(index++);
      push.procedure.initial_increment = 0.25;
      pressure_on(push, mesh, "SLEEVE_TOP", pressure);
      push.outputs = outputs;
      model.steps.push_back(push);
    }
    return;
  }
  if (c.load_case == "torque") {
    for (double torque : number_list(p, "torques")) {
      Step twist = static_step();
      twist.name = "TORQUE" + std::to_string(index++);
      twist.procedure.initial_increment = 0.25;
      twist.cloads = torque_loads(mesh, rim, kSleeveRadius, torque * 1000.0 / parts, quadratic,
                                  boundary == nullptr);
      twist.outputs = outputs;
      model.steps.push_back(twist);
    }
    return;
  }
  add_cylindrical_transform(model, "SLEEVE_RIM");
  const double degrees = p.number("rotation");
  if (!(degrees > 0)) p.fail("--rotation must be positive (degrees)");
  Step twist = static_step();
  twist.name = "TWIST";
  twist.procedure.initial_increment = 0.05;
  twist.procedure.max_increment = 0.05;
  twist.procedure.min_increment = 1e-4;
  const double u = kSleeveRadius * degrees * kPi / 180.0;
  for (int node : rim)
    if (boundary == nullptr || !boundary->is_slave(node))
      twist.boundaries.push_back({node, 2, u, {}});
  twist.outputs = outputs;
  model.steps.push_back(twist);
}

std::string fit_heading(const FitCase& c, double young, double poisson, double interference) {
  const std::string loading = c.load_case == "axial"    ? "axial pressure on the sleeve top"
                              : c.load_case == "torque" ? "torque on the sleeve"
                              : c.load_case == "fit"
                                  ? "nothing more"
                                  : "the sleeve's lower outer circle turned by a prescribed angle";
  const std::string model_text =
      c.full   ? (c.sector ? " (90 deg sector with cyclic symmetry, N = 4)" : " (full)")
      : c.thin ? " (sector of " + fmt_number(c.sweep * 180 / kPi) + " deg)"
               : " (quarter)";
  return "SPEC 4.2 shrink fit, model " + c.model_name + model_text + ", " + c.family +
         ": shaft 60 x D20, sleeve 20 x D20/D30 centred, E = " + fmt_number(young) +
         ", nu = " + fmt_number(poisson) + ", mu = " + c.mu_text + "; step 1 " +
         (c.fit == "thermal"
              ? "heats the shaft by " + fmt_number(c.dT) + " (alpha " + fmt_number(c.alpha) + ")"
              : "closes a radial interference " + fmt_number(interference)) +
         ", then " + loading +
         ". Tab 4.1 shaft end (thermal): elongation 0.1268 (C3D21), diametral growth 0.0401";
}

BuildResult shrink_fit(const BuilderParams& p, const ElementRegistry& registry) {
  const FitCase c = read_fit_case(p, registry);
  BuildResult r;
  Mesh& mesh = r.mesh;
  for (int quarter = 0; quarter < (c.full ? 4 : 1); ++quarter)
    mesh_sector(mesh, c.base, c.mesh, c.notch, quarter * 0.5 * kPi, c.sweep,
                c.thin ? c.thin_around : c.mesh.around);
  merge_coincident_nodes(mesh);
  if (c.sector) cut_sector(mesh, kFitSectors, 0.0);
  split_bodies(mesh, "SLEEVE", "SLEEVE_BORE", "SHAFT_FIT");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("SHAFT"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("SLEEVE"));
  convert_contact_layers(mesh, registry, c.family, {"SLEEVE_BORE", "SHAFT_FIT"});

  const double E = p.positive("young"), nu = p.number("poisson");
  const double interference = c.alpha * c.dT * kShaftRadius;
  r.model = contact_model(mesh, fit_heading(c, E, nu, interference),
                          {{"SHAFT", "SHAFT", E, nu,
                            c.fit == "thermal" ? std::optional<double>(c.alpha) : std::nullopt},
                           {"SLEEVE", "SLEEVE", E, nu, {}}});
  add_surfaces(r.model, mesh, {"SLEEVE_BORE", "SHAFT_FIT", "SLEEVE_TOP"});
  add_contact(r.model, "FIT", "SLEEVE_BORE", "SHAFT_FIT", c.friction,
              c.fit == "clearance" ? std::optional<double>(-interference) : std::nullopt);

  const double tol = 1e-7 * mesh.size();
  SectorBoundary boundary;
  if (c.sector) {
    boundary = sector_boundary(mesh, kFitSectors, tol);
    add_cyclic_symmetry(r.model, boundary);
  }
  const SectorBoundary* sector = c.sector ? &boundary : nullptr;
  add_fit_supports(r.model, mesh, c, sector);

  Step heat = heating_step(r.model, mesh, c);
  std::vector<OutputRequest> outputs = {
      contact_print(c.family), print_request(OutputRequest::Kind::NodePrint, "SHAFT_END", {"U"}),
      print_request(OutputRequest::Kind::NodePrint, "SHAFT_BASE", {"RF"}, true)};
  const auto rim = nodes_where(mesh, [&](const Vec3& x) {
    return std::abs(std::hypot(x[0], x[1]) - kSleeveRadius) < tol &&
           std::abs(x[2] - kFitStart) < tol;
  });
  if (c.load_case != "axial") {
    add_node_set(r.model, "SLEEVE_RIM", rim);
    outputs.push_back(print_request(OutputRequest::Kind::NodePrint, "SLEEVE_RIM", {"RF"}, true));
  }
  heat.outputs = outputs;
  r.model.steps.push_back(heat);
  add_load_steps(r.model, mesh, c, p, rim, outputs, sector);
  if (c.sector)
    r.note =
        "90 deg sector of model B with cyclic symmetry (N = 4): loads and reactions are a "
        "quarter of the joint's. ";
  return r;
}

}  // namespace

void add_shrink_fit_builder(std::vector<BuilderInfo>& all) {
  all.push_back(
      {"shrink-fit",
       "§4.2",
       "Shrink fit: shaft 60 x Ø20, sleeve 20 x Ø20/Ø30; model A quarter, model B full",
       {family_param("C3D21", kAllHexFamilies),
        {"model", "A",
         "A: quarter (3072 elements, 144 contact pairs), B: full (12288), C: a thin sector of "
         "--sector-around elements around (symmetry planes; heating and axial load only)"},
        {"load-case", "auto",
         "axial (step 2A, pressure on the sleeve top), torque (2B, model B: force couples), "
         "rotation (model B: the sleeve's rim turned by --rotation, torque as reaction) or fit "
         "(the "
         "heating step alone); auto: A and C axial, B torque"},
        {"sector-around", "2",
         "model C: elements around the thin sector (even; 2 = 15 deg with --around 12)"},
        {"fit", "thermal", "thermal (heat the shaft by dT) or clearance (*CLEARANCE -alpha dT r)"},
        {"notch", "none",
         "none (plain), I (a relief groove in each end face of the sleeve, leaving a lip at the "
         "bore) or II (the sleeve's outer diameter turned down towards both ends); SPEC 4.2 "
         "variants I/II, stand-in geometry"},
        {"groove-lip", "1.5", "variant I: the lip's thickness between the bore and the groove"},
        {"groove-width", "1", "variant I: the groove's radial width"},
        {"groove-depth", "5", "variant I: the groove's axial depth (rounded to whole fit rows)"},
        {"relief-depth", "2.5", "variant II: how far the outer radius falls at the end faces"},
        {"relief-length", "5", "variant II: the length of each turned-down end"},
        {"mu", "auto", "friction coefficient (auto: 0.2 axial, 0.4 torque; 'rough')"},
        {"pressures", "52.5,72", "axial pressures on the sleeve's top annulus, one step each"},
        {"torques", "300,850", "torques on the sleeve in Nm, one step each (1000: capacity lost)"},
        {"rotation", "1.5",
         "load case rotation: the angle (degrees) the sleeve's lower outer circle is turned by"},
        {"sector", "no",
         "model B: yes = the 90 deg sector with *TIE, CYCLIC SYMMETRY (N = 4) instead of the "
         "full model"},
        {"dT", "100", "shaft heating"},
        {"alpha", "2e-5", "shaft expansion coefficient"},
        {"around", "12", "elements around a quarter (even; contact elements per row)"},
        {"shaft-rings", "5", "radial elements of the shaft's outer O-grid ring"},
        {"sleeve-rings", "4", "radial elements of the sleeve"},
        {"fit-rows", "12", "axial elements along the sleeve"},
        {"end-rows", "7", "axial elements of each free shaft end"},
        {"young", "200000", "Young's modulus E (MPa)"},
        {"poisson", "0.3", "Poisson's ratio"}},
       shrink_fit});
}

}  // namespace styk::mesher::detail
