// Builders of the SPEC §3.2 contact tests: §3.2.1 punch on an elastic foundation, §3.2.2 two
// concentric cylinders, §3.2.3 two cantilevers with friction, §3.2.4 punch on a half-space.
// Each body is meshed in blocks merged into one part, then split at the contact faces into two
// bodies with coincident node pairs (the thesis' zero-thickness interface); the contact layers
// become the chosen family with the contact face as S1 on both sides.
#include <cmath>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "contact_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

const std::vector<std::string> kFamilies = {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"};

bool near(double a, double b, double tol) { return std::abs(a - b) < tol; }

// Block of an axis-aligned box lo..hi with grading (last / first) per direction.
Block box(Mesh& mesh, const std::string& type, const Vec3& lo, const Vec3& hi,
          std::array<int, 3> divisions, std::array<double, 3> grading, const std::string& elset) {
  return mesh_block(mesh, box_map(lo, {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}),
                    {type, divisions, grading, elset});
}

// §3.2.1 --------------------------------------------------------------------------------------

BuildResult punch_on_foundation(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const int n = p.count("n"), rows = p.count("punch-rows"), outer = p.count("outer");
  const int depth_rows = p.count("depth-rows");
  const double grading = p.positive("grading"), width = p.positive("width");
  const double a = 1.0, h = 1.0, b = 2.0, depth = 2.0;  // SPEC stand-in (half model)
  const std::string type = base_type(registry, fam);
  // Contact elements shrink towards the punch edge x = a (first / last = grading); the
  // foundation continues from the smallest one outwards and from the mean one downwards.
  const std::vector<double> t = graded_parameters(n, 1.0 / grading);
  const double smallest = a * (t[n] - t[n - 1]);
  BuildResult r;
  Mesh& mesh = r.mesh;
  box(mesh, type, {0, 0, -depth}, {a, width, 0}, {n, 1, depth_rows},
      {1.0 / grading, 1, 1.0 / continuing_grading(a / n, depth, depth_rows)}, "FOUNDATION");
  box(mesh, type, {a, 0, -depth}, {b, width, 0}, {outer, 1, depth_rows},
      {continuing_grading(smallest, b - a, outer), 1,
       1.0 / continuing_grading(a / n, depth, depth_rows)},
      "FOUNDATION");
  const Block punch = box(mesh, type, {0, 0, 0}, {a, width, h}, {n, 1, rows},
                          {1.0 / grading, 1, continuing_grading(a / n, h, rows)}, "PUNCH");
  mesh.add_to_surface("PUNCH_TOP", punch.side_faces(2, +1));
  merge_coincident_nodes(mesh);
  split_bodies(mesh, "PUNCH", "PUNCH_BOTTOM", "FOUNDATION_TOP");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("PUNCH"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("FOUNDATION"));
  convert_contact_layers(mesh, registry, fam, {"PUNCH_BOTTOM", "FOUNDATION_TOP"});

  const double E = p.positive("young"), nu = p.number("poisson");
  r.model = contact_model(
      mesh,
      "SPEC 3.2.1 elastic punch on an elastic foundation (NAFEMS), plane strain, half model, " +
          fam + ": punch " + fmt_number(a) + " x " + fmt_number(h) + ", foundation " +
          fmt_number(b) + " x " + fmt_number(depth) + ", width " + fmt_number(width) + ", " +
          std::to_string(n) + " + " + std::to_string(n) +
          " contact elements graded towards the punch edge; unit pressure on the punch top. "
          "Published contact pressure about 0.9 at the centre, rising at the edge",
      {{"PUNCH", "PUNCH", E, nu, {}}, {"FOUNDATION", "FOUNDATION", E, nu, {}}});
  add_surfaces(r.model, mesh, {"PUNCH_BOTTOM", "FOUNDATION_TOP", "PUNCH_TOP"});
  add_contact(r.model, "PUNCH_FOUNDATION", "PUNCH_BOTTOM", "FOUNDATION_TOP",
              friction_parameter(p, "mu"));
  const double tol = 1e-7 * mesh.size();
  const auto symmetry = nodes_where(mesh, [&](const Vec3& x) { return x[0] < tol; });
  const auto sides =
      nodes_where(mesh, [&](const Vec3& x) { return x[1] < tol || x[1] > width - tol; });
  const auto bottom = nodes_where(mesh, [&](const Vec3& x) { return x[2] < -depth + tol; });
  add_node_set(r.model, "SYMMETRY", symmetry);
  add_node_set(r.model, "BOTTOM", bottom);
  add_node_set(r.model, "PUNCHBOTTOM", mesh.surface_nodes("PUNCH_BOTTOM"));
  fix(r.model, symmetry, {1});
  fix(r.model, sides, {2});  // plane strain: front and back held out of plane
  fix(r.model, bottom, {1, 2, 3});
  Step step = static_step();
  pressure_on(step, mesh, "PUNCH_TOP", p.number("pressure"));
  step.outputs = {contact_print(fam),
                  print_request(OutputRequest::Kind::NodePrint, "PUNCHBOTTOM", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "BOTTOM", {"RF"}, true)};
  r.model.steps.push_back(step);
  return r;
}

// §3.2.2 --------------------------------------------------------------------------------------

// A quarter ring r1..r2 (xi, radial), 0..90 deg (eta), z 0..length (zeta): right-handed.
Block quarter_ring(Mesh& mesh, const std::string& type, double r1, double r2, double length,
                   std::array<int, 3> divisions, const std::string& elset) {
  const BlockMap map = [=](const Vec3& xi) {
    const double r = r1 + (r2 - r1) * 0.5 * (xi[0] + 1), angle = 0.25 * kPi * (xi[1] + 1);
    return Vec3{r * std::cos(angle), r * std::sin(angle), length * 0.5 * (xi[2] + 1)};
  };
  return mesh_block(mesh, map, {type, divisions, {1, 1, 1}, elset});
}

// Lamé: radial displacement at r of a plane-strain ring a..b under pressures pa (inside) and pb.
double lame_displacement(double r, double a, double b, double pa, double pb, double E, double nu) {
  const double c2 = (pb - pa) / (1 / (b * b) - 1 / (a * a));
  const double c1 = -pa + c2 / (a * a);  // sigma_r = c1 - c2 / r^2
  return (1 + nu) / E * ((1 - 2 * nu) * c1 * r + c2 / r);
}

BuildResult concentric_cylinders(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllHexFamilies);
  const int nr = p.count("nr"), ntheta = p.count("ntheta");
  const double r1 = 1, r2 = 2, r3 = 3, length = 1;
  const double pi = p.number("p-inner"), po = p.number("p-outer");
  const double E1 = 10, nu1 = 0.3, E2 = 20, nu2 = 0.2;  // SPEC §3.2.2
  BuildResult r;
  Mesh& mesh = r.mesh;
  const std::string type = base_type(registry, fam);
  const Block inner = quarter_ring(mesh, type, r1, r2, length, {nr, ntheta, 1}, "INNER");
  const Block outer = quarter_ring(mesh, type, r2, r3, length, {nr, ntheta, 1}, "OUTER");
  mesh.add_to_surface("BORE", inner.side_faces(0, -1));
  mesh.add_to_surface("RIM", outer.side_faces(0, +1));
  merge_coincident_nodes(mesh);
  split_bodies(mesh, "INNER", "INNER_CONTACT", "OUTER_CONTACT");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("INNER"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("OUTER"));
  convert_contact_layers(mesh, registry, fam, {"INNER_CONTACT", "OUTER_CONTACT"});

  // Analytic contact pressure: the interface displacement is affine in the pressure.
  auto mismatch = [&](double q) {
    return lame_displacement(r2, r1, r2, pi, q, E1, nu1) -
           lame_displacement(r2, r2, r3, q, po, E2, nu2);
  };
  const double q = -mismatch(0) / (mismatch(1) - mismatch(0));
  r.model = contact_model(
      mesh,
      "SPEC 3.2.2 two concentric cylinders (Lame), plane strain, quarter model, " + fam +
          ": inner r 1-2 E 10 nu 0.3, outer r 2-3 E 20 nu 0.2, pressures " + fmt_number(pi) +
          " inside, " + fmt_number(po) + " outside; analytic contact pressure " + fmt_number(q),
      {{"INNER", "INNER", E1, nu1, {}}, {"OUTER", "OUTER", E2, nu2, {}}});
  add_surfaces(r.model, mesh, {"INNER_CONTACT", "OUTER_CONTACT", "BORE", "RIM"});
  add_contact(r.model, "CYLINDERS", "INNER_CONTACT", "OUTER_CONTACT", friction_parameter(p, "mu"));
  const double tol = 1e-7 * mesh.size();
  fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol; }), {1});
  fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; }), {2});
  fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return x[2] < tol || x[2] > length - tol; }),
      {3});
  add_node_set(r.model, "INTERFACE", mesh.surface_nodes("INNER_CONTACT"));
  Step step = static_step();
  pressure_on(step, mesh, "BORE", pi);
  pressure_on(step, mesh, "RIM", po);
  step.outputs = {contact_print(fam),
                  print_request(OutputRequest::Kind::NodePrint, "INTERFACE", {"U"}),
                  print_request(OutputRequest::Kind::ElementPrint, "EALL", {"S"})};
  r.model.steps.push_back(step);
  return r;
}

// §3.2.3 --------------------------------------------------------------------------------------

BuildResult two_cantilevers(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const int n = p.count("n"), rows = p.count("rows");
  const double L = 1.0, h = 0.1, width = p.positive("width");  // SPEC §3.2.3
  BuildResult r;
  Mesh& mesh = r.mesh;
  const std::string type = base_type(registry, fam);
  box(mesh, type, {0, 0, 0}, {L, width, h}, {n, 1, rows}, {1, 1, 1}, "LOWER");
  const Block upper =
      box(mesh, type, {0, 0, h}, {L, width, 2 * h}, {n, 1, rows}, {1, 1, 1}, "UPPER");
  mesh.add_to_surface("UPPER_TOP", upper.side_faces(2, +1));
  merge_coincident_nodes(mesh);
  split_bodies(mesh, "UPPER", "UPPER_BOTTOM", "LOWER_TOP");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("UPPER"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("LOWER"));
  convert_contact_layers(mesh, registry, fam, {"UPPER_BOTTOM", "LOWER_TOP"});

  const double E = p.positive("young"), q = p.number("pressure");
  const std::optional<Friction> friction = friction_parameter(p, "mu");
  r.model = contact_model(
      mesh,
      "SPEC 3.2.3 two cantilevers in contact (Zhong 1993), " + fam + ", each 1.0 x " +
          fmt_number(h) + ", " + std::to_string(n) + " x " + std::to_string(rows) +
          " elements, E = " + fmt_number(E) + ", nu = 0, pressure " + fmt_number(q) +
          " on the top, left ends clamped, mu = " + p.text("mu") +
          "; upper tip deflection: frictionless -7.56e-3 (CalculiX C3D20), tied -1.935e-3",
      {{"UPPER", "UPPER", E, 0.0, {}}, {"LOWER", "LOWER", E, 0.0, {}}});
  add_surfaces(r.model, mesh, {"UPPER_BOTTOM", "LOWER_TOP", "UPPER_TOP"});
  add_contact(r.model, "BEAMS", "UPPER_BOTTOM", "LOWER_TOP", friction);
  const double tol = 1e-7 * mesh.size();
  const auto root = nodes_where(mesh, [&](const Vec3& x) { return x[0] < tol; });
  add_node_set(r.model, "ROOT", root);
  fix(r.model, root, {1, 2, 3});
  // Tip of the upper beam: the nodes at x = L above the interface (the upper body's own).
  std::vector<int> tip;
  for (int e : mesh.element_sets.at("UPPER"))
    for (int node : mesh.elements[e].nodes)
      if (mesh.nodes[node][0] > L - tol) tip.push_back(node);
  add_node_set(r.model, "TIP", tip);
  Step step = static_step();
  pressure_on(step, mesh, "UPPER_TOP", q);
  step.outputs = {contact_print(fam), print_request(OutputRequest::Kind::NodePrint, "TIP", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "ROOT", {"RF"}, true)};
  r.model.steps.push_back(step);
  return r;
}

// §3.2.4 --------------------------------------------------------------------------------------

BuildResult punch_on_half_space(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const int n = to_upper(p.text("n")) == "AUTO" ? (fam == "C3D28" ? 3 : 4) : p.count("n");
  const int outer = p.count("outer"), depth_rows = p.count("depth-rows");
  const double a = 10, b = 50, depth = 50;  // SPEC §3.2.4 quarter model
  const double grading = p.positive("grading"), depth_grading = p.positive("depth-grading");
  BuildResult r;
  Mesh& mesh = r.mesh;
  const std::string type = base_type(registry, fam);
  const double spans[2][2] = {{0, a}, {a, b}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      box(mesh, type, {spans[i][0], spans[j][0], -depth}, {spans[i][1], spans[j][1], 0},
          {i == 0 ? n : outer, j == 0 ? n : outer, depth_rows},
          {i == 0 ? 1.0 : grading, j == 0 ? 1.0 : grading, 1.0 / depth_grading}, "HALFSPACE");
  box(mesh, type, {0, 0, 0}, {a, a, a}, {n, n, n}, {1, 1, 1}, "PUNCH");
  merge_coincident_nodes(mesh);
  split_bodies(mesh, "PUNCH", "PUNCH_BOTTOM", "HALFSPACE_TOP");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("PUNCH"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("HALFSPACE"));
  convert_contact_layers(mesh, registry, fam, {"PUNCH_BOTTOM", "HALFSPACE_TOP"});

  const double E = p.positive("young"), nu = p.number("poisson"), P = p.number("force");
  std::optional<Friction> friction = friction_parameter(p, "mu");
  const bool anisotropic = to_upper(p.text("mu2")) != "NONE";
  std::string law = "mu = " + p.text("mu");
  if (anisotropic) {
    if (!friction || friction->kind != Friction::Kind::Isotropic)
      p.fail("--mu2 needs a positive --mu (mu1 along x)");
    const double mu2 = p.number("mu2");
    if (!(mu2 > 0)) p.fail("--mu2 must be positive or 'none', not " + p.text("mu2"));
    friction->kind = Friction::Kind::Anisotropic;
    friction->mu2 = mu2;
    friction->orientation = "FRICTION_AXES";
    law = "mu1 = " + p.text("mu") + " along x, mu2 = " + p.text("mu2") + " along y";
  }
  r.model = contact_model(
      mesh,
      "SPEC 3.2.4 elastic punch on an elastic half-space with friction (Klarbring), quarter "
      "model, " +
          fam + ": punch 10 x 10 x 10 (" + std::to_string(n) + " x " + std::to_string(n) +
          " contact elements), half-space 50 x 50 x 50, P = " + fmt_number(P) +
          " down at the punch's top corner on the axis, " + law +
          "; thesis corner slip -4.03e-4 (C3D21, mu = 0.04)",
      {{"PUNCH", "PUNCH", E, nu, {}}, {"HALFSPACE", "HALFSPACE", E, nu, {}}});
  if (anisotropic) {
    Orientation o;  // local 1 = x, 2 = y
    o.name = "FRICTION_AXES";
    o.axes.system = CoordinateSystem::Rectangular;
    o.axes.a = {1, 0, 0};
    o.axes.b = {0, 1, 0};
    r.model.orientations[o.name] = o;
  }
  add_surfaces(r.model, mesh, {"PUNCH_BOTTOM", "HALFSPACE_TOP"});
  add_contact(r.model, "PAD", "PUNCH_BOTTOM", "HALFSPACE_TOP", friction);
  const double tol = 1e-7 * mesh.size();
  fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return x[0] < tol; }), {1});
  fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return x[1] < tol; }), {2});
  const auto bottom = nodes_where(mesh, [&](const Vec3& x) { return x[2] < -depth + tol; });
  add_node_set(r.model, "BOTTOM", bottom);
  fix(r.model, bottom, {1, 2, 3});
  const auto loaded = nodes_where(
      mesh, [&](const Vec3& x) { return x[0] < tol && x[1] < tol && near(x[2], a, tol); });
  add_node_set(r.model, "LOADED", loaded);
  add_node_set(r.model, "PUNCHBOTTOM", mesh.surface_nodes("PUNCH_BOTTOM"));
  Step step = static_step();
  step.cloads.push_back({loaded.at(0), 3, -P, {}});
  step.outputs = {contact_print(fam),
                  print_request(OutputRequest::Kind::NodePrint, "PUNCHBOTTOM", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "BOTTOM", {"RF"}, true)};
  r.model.steps.push_back(step);
  return r;
}

}  // namespace

void add_contact_builders(std::vector<BuilderInfo>& all) {
  all.push_back({"punch-foundation",
                 "§3.2.1",
                 "Punch on an elastic foundation (NAFEMS), plane strain, half model",
                 {family_param("C3D21", kFamilies),
                  {"n", "8", "contact elements per side (graded towards the punch edge)"},
                  {"grading", "4", "largest / smallest contact element"},
                  {"punch-rows", "4", "element rows of the punch"},
                  {"outer", "12", "foundation elements beyond the punch edge"},
                  {"depth-rows", "15", "element rows of the foundation"},
                  {"width", "0.2", "out-of-plane width"},
                  {"pressure", "1", "pressure on the punch top"},
                  {"mu", "0", "friction coefficient (0 = frictionless, 'rough' = no slip)"},
                  {"young", "1", "Young's modulus E"},
                  {"poisson", "0.3", "Poisson's ratio"}},
                 punch_on_foundation});
  all.push_back({"cylinders",
                 "§3.2.2",
                 "Two concentric cylinders (Lamé), plane strain, quarter",
                 {family_param("C3D21", kAllHexFamilies),
                  {"nr", "3", "elements through each wall"},
                  {"ntheta", "16", "elements around the quarter (contact elements per side)"},
                  {"p-inner", "5", "internal pressure"},
                  {"p-outer", "3", "external pressure"},
                  {"mu", "0", "friction coefficient (0 = frictionless, 'rough' = no slip)"}},
                 concentric_cylinders});
  all.push_back({"two-cantilevers",
                 "§3.2.3",
                 "Two stacked cantilevers in contact with friction (Zhong)",
                 {family_param("C3D21", kFamilies),
                  {"n", "40", "elements along each beam"},
                  {"rows", "2", "elements through each beam's height"},
                  {"width", "0.1", "beam width"},
                  {"pressure", "2e6", "pressure on the upper beam's top"},
                  {"mu", "0.2", "friction coefficient (0, 0.2, 0.75, 1, 10, 100; 'rough')"},
                  {"young", "2e11", "Young's modulus E (nu = 0)"}},
                 two_cantilevers});
  all.push_back({"punch-halfspace",
                 "§3.2.4",
                 "Punch on an elastic half-space with friction (Klarbring), quarter",
                 {family_param("C3D21", kFamilies),
                  {"n", "auto", "contact elements per side (auto: 4, C3D28 3)"},
                  {"outer", "5", "half-space elements beyond the punch, per direction"},
                  {"depth-rows", "8", "element rows of the half-space"},
                  {"grading", "4", "outer / inner element length beyond the punch"},
                  {"depth-grading", "6", "bottom / top element height of the half-space"},
                  {"force", "1000", "downward force at the punch's top corner on the axis"},
                  {"mu", "0.04", "friction coefficient (mu1 along x when --mu2 is given)"},
                  {"mu2", "none", "anisotropic friction: mu2 along y (e.g. 0.4)"},
                  {"young", "200000", "Young's modulus E"},
                  {"poisson", "0.3", "Poisson's ratio"}},
                 punch_on_half_space});
}

}  // namespace styk::mesher::detail
