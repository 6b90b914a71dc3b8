// Builder of the SPEC §4.2 shrink fit: shaft L 60, Ø20, sleeve L 20, Ø20/Ø30, centred; model A
// (quarter, symmetry planes x = 0 and y = 0) and model B (full). The shaft's cross-section is an
// O-grid (a square core and two ring blocks per quarter); the full model is four quarters merged.
// Step 1 heats the shaft by dT (alpha = 2e-5: interference 0.02 on the radius); the next steps push
// the sleeve axially (load case axial) or twist it (load case torque), one step per load level.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "contact_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

const std::vector<std::string> kFamilies = {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"};

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

// One quarter of the shaft and the sleeve (angles angle .. angle + 90 deg).
void mesh_quarter(Mesh& mesh, const std::string& type, const FitMesh& m, double angle) {
  const int n = m.around / 2;
  const auto shaft = [](double) { return kShaftRadius; };
  const std::vector<SectionPatch> o_grid = quarter_o_grid(m.core);
  const double z[4] = {0, kFitStart, kFitEnd, kShaftLength};
  const int rows[3] = {m.end_rows, m.fit_rows, m.end_rows};
  for (int k = 0; k < 3; ++k)
    for (int part = 0; part < 3; ++part)
      mesh_block(mesh, prism(o_grid[part], z[k], z[k + 1], shaft, angle),
                 {type, {part == 0 ? n : m.shaft_rings, n, rows[k]}, {1, 1, 1}, "SHAFT"});
  // The sleeve in units of its inner radius: s from 1 to R_o / R_i.
  const double outer = kSleeveRadius / kShaftRadius;
  const SectionPatch sleeve = [outer](double s, double t) {
    const double r = 1 + s * (outer - 1), a = 0.5 * kPi * t;
    return Vec3{r * std::cos(a), r * std::sin(a), 0};
  };
  const Block b = mesh_block(mesh, prism(sleeve, kFitStart, kFitEnd, shaft, angle),
                             {type, {m.sleeve_rings, m.around, m.fit_rows}, {1, 1, 1}, "SLEEVE"});
  mesh.add_to_surface("SLEEVE_TOP", b.side_faces(2, +1));
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

// Tangential nodal forces on the ring of nodes at radius r, height z (a closed circle or a
// quarter): a uniform line load of total moment `torque` about z, distributed as the consistent
// loads of the element edges (linear edges: halves; quadratic: 1/6, 2/3, 1/6).
std::vector<ConcentratedLoad> torque_loads(const Mesh& mesh, const std::vector<int>& ring, double r,
                                           double torque, bool quadratic) {
  std::vector<std::pair<double, int>> by_angle;
  for (int node : ring) {
    double a = std::atan2(mesh.nodes[node][1], mesh.nodes[node][0]);
    if (a < -1e-9) a += 2 * kPi;
    by_angle.push_back({a, node});
  }
  std::sort(by_angle.begin(), by_angle.end());
  const int count = static_cast<int>(by_angle.size());
  const int step = quadratic ? 2 : 1;
  const int edges = count / step;  // closed circle: every node starts one edge piece
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

BuildResult shrink_fit(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const std::string model_name = to_upper(p.choice("model", {"A", "B"}));
  const bool full = model_name == "B";
  std::string load_case = p.choice("load-case", {"auto", "axial", "torque"});
  if (load_case == "auto") load_case = full ? "torque" : "axial";
  if (load_case == "torque" && !full)
    p.fail(
        "--load-case torque needs --model B: a quarter model cannot carry a torque "
        "without cyclic symmetry");
  const std::string fit = p.choice("fit", {"thermal", "clearance"});
  FitMesh m;
  m.around = p.count("around", 2);
  if (m.around % 2 != 0) p.fail("--around must be even (two O-grid blocks per quarter)");
  m.shaft_rings = p.count("shaft-rings");
  m.sleeve_rings = p.count("sleeve-rings");
  m.fit_rows = p.count("fit-rows");
  m.end_rows = p.count("end-rows");
  const double alpha = p.positive("alpha"), dT = p.number("dT");
  std::string mu_text = p.text("mu");
  if (to_upper(mu_text) == "AUTO") mu_text = load_case == "torque" ? "0.4" : "0.2";
  const std::optional<Friction> friction = friction_value(p, "mu", mu_text);

  BuildResult r;
  Mesh& mesh = r.mesh;
  const std::string type = base_type(registry, fam);
  for (int quarter = 0; quarter < (full ? 4 : 1); ++quarter)
    mesh_quarter(mesh, type, m, quarter * 0.5 * kPi);
  merge_coincident_nodes(mesh);
  split_bodies(mesh, "SLEEVE", "SLEEVE_BORE", "SHAFT_FIT");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("SHAFT"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("SLEEVE"));
  convert_contact_layers(mesh, registry, fam, {"SLEEVE_BORE", "SHAFT_FIT"});

  const double E = p.positive("young"), nu = p.number("poisson");
  const double interference = alpha * dT * kShaftRadius;
  r.model = contact_model(
      mesh,
      "SPEC 4.2 shrink fit, model " + model_name + (full ? " (full)" : " (quarter)") + ", " + fam +
          ": shaft 60 x D20, sleeve 20 x D20/D30 centred, E = " + fmt_number(E) +
          ", nu = " + fmt_number(nu) + ", mu = " + mu_text + "; step 1 " +
          (fit == "thermal"
               ? "heats the shaft by " + fmt_number(dT) + " (alpha " + fmt_number(alpha) + ")"
               : "closes a radial interference " + fmt_number(interference)) +
          ", then " +
          (load_case == "axial" ? "axial pressure on the sleeve top" : "torque on the sleeve") +
          ". Tab 4.1 shaft end (thermal): elongation 0.1268 (C3D21), diametral growth 0.0401",
      {{"SHAFT", "SHAFT", E, nu, fit == "thermal" ? std::optional<double>(alpha) : std::nullopt},
       {"SLEEVE", "SLEEVE", E, nu, {}}});
  add_surfaces(r.model, mesh, {"SLEEVE_BORE", "SHAFT_FIT", "SLEEVE_TOP"});
  add_contact(r.model, "FIT", "SLEEVE_BORE", "SHAFT_FIT", friction,
              fit == "clearance" ? std::optional<double>(-interference) : std::nullopt);

  const double tol = 1e-7 * mesh.size();
  const auto base = nodes_where(mesh, [&](const Vec3& x) { return x[2] < tol; });
  const auto end = nodes_where(mesh, [&](const Vec3& x) { return x[2] > kShaftLength - tol; });
  add_node_set(r.model, "SHAFT_BASE", base);
  add_node_set(r.model, "SHAFT_END", end);
  fix(r.model, base, {3});
  if (!full) {
    fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol; }), {1});
    fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; }), {2});
  } else {
    // The base's centre holds x, y; every other base node is held tangentially (a cylindrical
    // *TRANSFORM), which carries the torque and leaves the thermal growth free.
    std::vector<int> centre, ring;
    for (int node : base)
      (std::hypot(mesh.nodes[node][0], mesh.nodes[node][1]) < tol ? centre : ring).push_back(node);
    fix(r.model, centre, {1, 2});
    add_node_set(r.model, "SHAFT_BASE_RING", ring);
    Transform t;
    t.nset = "SHAFT_BASE_RING";
    t.axes.system = CoordinateSystem::Cylindrical;
    t.axes.a = {0, 0, 0};
    t.axes.b = {0, 0, 1};
    r.model.transforms.push_back(t);
    fix(r.model, ring, {2});
  }
  if (!friction) {
    // Frictionless: nothing holds the sleeve along (and, in model B, about) the axis. One node
    // on its outer mid-plane is held there; with mu = 0 no force can reach it.
    const auto hold = nodes_where(mesh, [&](const Vec3& x) {
      return std::abs(x[0] - kSleeveRadius) < tol && std::abs(x[1]) < tol &&
             std::abs(x[2] - 0.5 * (kFitStart + kFitEnd)) <
                 0.5 * (kFitEnd - kFitStart) / m.fit_rows + tol;
    });
    add_node_set(r.model, "SLEEVE_HOLD", {hold.at(0)});
    if (full)
      fix(r.model, {hold.at(0)}, {2, 3});
    else
      fix(r.model, {hold.at(0)}, {3});
  }

  Step heat = static_step();
  heat.name = "FIT";
  heat.procedure.initial_increment = 0.25;
  if (fit == "thermal") {
    for (int node = 0; node < r.model.node_count(); ++node)
      r.model.initial_temperatures.push_back({node, 0.0, {}});
    for (int e : mesh.element_sets.at("SHAFT"))
      for (int node : mesh.elements[e].nodes) heat.temperatures.push_back({node, dT, {}});
    std::sort(heat.temperatures.begin(), heat.temperatures.end(),
              [](const NodalTemperature& a, const NodalTemperature& b) { return a.node < b.node; });
    heat.temperatures.erase(std::unique(heat.temperatures.begin(), heat.temperatures.end(),
                                        [](const NodalTemperature& a, const NodalTemperature& b) {
                                          return a.node == b.node;
                                        }),
                            heat.temperatures.end());
  }
  const std::vector<OutputRequest> outputs = {
      contact_print(fam), print_request(OutputRequest::Kind::NodePrint, "SHAFT_END", {"U"}),
      print_request(OutputRequest::Kind::NodePrint, "SHAFT_BASE", {"RF"}, true)};
  heat.outputs = outputs;
  r.model.steps.push_back(heat);

  const bool quadratic = type == "C3D20";
  int index = 1;
  if (load_case == "axial") {
    for (double pressure : number_list(p, "pressures")) {
      Step push = static_step();
      push.name = "PUSH" + std::to_string(index++);
      push.procedure.initial_increment = 0.25;
      pressure_on(push, mesh, "SLEEVE_TOP", pressure);
      push.outputs = outputs;
      r.model.steps.push_back(push);
    }
  } else {
    const auto rim = nodes_where(mesh, [&](const Vec3& x) {
      return std::abs(std::hypot(x[0], x[1]) - kSleeveRadius) < tol &&
             std::abs(x[2] - kFitStart) < tol;
    });
    add_node_set(r.model, "SLEEVE_RIM", rim);
    for (double torque : number_list(p, "torques")) {
      Step twist = static_step();
      twist.name = "TORQUE" + std::to_string(index++);
      twist.procedure.initial_increment = 0.25;
      twist.cloads = torque_loads(mesh, rim, kSleeveRadius, torque * 1000.0, quadratic);
      twist.outputs = outputs;
      r.model.steps.push_back(twist);
    }
  }
  return r;
}

}  // namespace

void add_shrink_fit_builder(std::vector<BuilderInfo>& all) {
  all.push_back(
      {"shrink-fit",
       "§4.2",
       "Shrink fit: shaft 60 x Ø20, sleeve 20 x Ø20/Ø30; model A quarter, model B full",
       {family_param("C3D21", kFamilies),
        {"model", "A", "A: quarter (3072 elements, 144 contact pairs), B: full (12288)"},
        {"load-case", "auto",
         "axial (step 2A, pressure on the sleeve top) or torque (2B, model "
         "B); auto: A axial, B torque"},
        {"fit", "thermal", "thermal (heat the shaft by dT) or clearance (*CLEARANCE -alpha dT r)"},
        {"mu", "auto", "friction coefficient (auto: 0.2 axial, 0.4 torque; 'rough')"},
        {"pressures", "52.5,72", "axial pressures on the sleeve's top annulus, one step each"},
        {"torques", "300,850", "torques on the sleeve in Nm, one step each (1000: capacity lost)"},
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
