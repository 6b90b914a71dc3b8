// Builders of SPEC §2.4 single element, §3.1.5 thick plate, §3.1.6 hemisphere stand-in,
// §3.1.7 thick cylinder, §3.1.8 patch test and the §6.2 cylinder wall.
#include <cmath>
#include <cstdio>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

const std::vector<std::string> kFamilies = {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"};
// The brick families and the tetrahedra and wedges split from bricks (mesher/split.hpp).
const std::vector<std::string> kAllFamilies = {"C3D8",  "C3D20", "C3D14",  "C3D21", "C3D28",
                                               "C3D8R", "C3D8I", "C3D20R", "C3D27", "C3D4",
                                               "C3D10", "C3D6",  "C3D15"};

bool near(double a, double b, double tol) { return std::abs(a - b) < tol; }

BuildResult single_element(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const std::string loads = p.choice("loads", {"thesis", "consistent"});
  BuildResult r;
  const Block b = mesh_block(r.mesh, box_map({-1, -1, -1}, {2, 2, 2}),
                             {base_type(registry, fam), {1, 1, 1}, {1, 1, 1}, "EALL"});
  r.mesh.add_to_surface("CONTACT", b.side_faces(2, -1));
  apply_family(r.mesh, registry, fam, "CONTACT");
  r.model = finish_model(r.mesh,
                         "SPEC 2.4 single " + fam +
                             " on the reference cube [-1,1]^3, top "
                             "face loaded (" +
                             loads +
                             " loads of a unit pressure), bottom "
                             "supported in z; bottom reactions must all be positive and sum to 4",
                         p.positive("young"), p.number("poisson"));
  const auto bottom = nodes_where(r.mesh, [](const Vec3& x) { return x[2] < -1 + 1e-9; });
  const auto top = nodes_where(r.mesh, [](const Vec3& x) { return x[2] > 1 - 1e-9; });
  add_node_set(r.model, "BOTTOM", bottom);
  add_node_set(r.model, "TOP", top);
  fix(r.model, bottom, {3});
  // Minimal in-plane rigid-body removal: node at (-1,-1,-1) in x and y, node at (1,-1,-1) in y.
  for (int n : bottom) {
    const Vec3& x = r.mesh.nodes[n];
    if (near(x[0], -1, 1e-9) && near(x[1], -1, 1e-9)) fix(r.model, {n}, {1, 2});
    if (near(x[0], 1, 1e-9) && near(x[1], -1, 1e-9)) fix(r.model, {n}, {2});
  }
  Step step = static_step();
  if (fam == "C3D14" && loads == "thesis") {
    // Tab 2.6: corners -1/3, top face centre -8/3 (not the consistent -5/9, -16/9).
    for (int n : top) {
      const Vec3& x = r.mesh.nodes[n];
      const bool centre = near(x[0], 0, 1e-9) && near(x[1], 0, 1e-9);
      step.cloads.push_back({n, 3, centre ? -8.0 / 3.0 : -1.0 / 3.0, {}});
    }
  } else {
    // Tab 2.7/2.8 top loads are the consistent loads of the (serendipity) top face: P2 = 1.
    step.dloads.push_back({0, 2, 1.0, {}});
  }
  step.outputs = {print_request(OutputRequest::Kind::NodePrint, "BOTTOM", {"RF"}, true),
                  print_request(OutputRequest::Kind::NodePrint, "TOP", {"U"})};
  r.model.steps.push_back(step);
  return r;
}

BuildResult thick_plate(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllFamilies);
  const int n = p.count("n"), nz = p.count("nz");
  if (n % 2 != 0) p.fail("--n must be even: the load sits on the plate's centre node");
  const double a = 400, t = 40;
  BuildResult r;
  const Block b = mesh_block(r.mesh, box_map({0, 0, 0}, {a, a, t}),
                             {base_type(registry, fam), {n, n, nz}, {1, 1, 1}, "EALL"});
  r.mesh.add_to_surface("CONTACT", b.side_faces(2, -1));
  apply_family(r.mesh, registry, fam, "CONTACT");
  const double tol = 1e-6 * r.mesh.size();
  r.model = finish_model(r.mesh,
                         "SPEC 3.1.5 thick plate 400 x 400 x 40 (full), " + fam + " " +
                             std::to_string(n) + "x" + std::to_string(n) +
                             ", edges clamped, P = 16 at the top centre; bottom-centre "
                             "deflection, published theory 0.003322",
                         p.positive("young"), p.number("poisson"));
  const auto edges = nodes_where(r.mesh, [&](const Vec3& x) {
    return x[0] < tol || x[1] < tol || x[0] > a - tol || x[1] > a - tol;
  });
  add_node_set(r.model, "EDGES", edges);
  fix(r.model, edges, {1, 2, 3});
  const auto top_centre = nodes_where(r.mesh, [&](const Vec3& x) {
    return near(x[0], a / 2, tol) && near(x[1], a / 2, tol) && x[2] > t - tol;
  });
  const auto bottom_centre = nodes_where(r.mesh, [&](const Vec3& x) {
    return near(x[0], a / 2, tol) && near(x[1], a / 2, tol) && x[2] < tol;
  });
  add_node_set(r.model, "LOADED", top_centre);
  add_node_set(r.model, "BOTCENTRE", bottom_centre);
  Step step = static_step();
  step.cloads.push_back({top_centre.at(0), 3, -p.number("force"), {}});
  step.outputs = {print_request(OutputRequest::Kind::NodePrint, "BOTCENTRE", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "EDGES", {"RF"}, true)};
  r.model.steps.push_back(step);
  return r;
}

BuildResult hemisphere(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllFamilies);
  const int n = p.count("n");
  const double R = 10, t = 0.04, hole = 18.0 * kPi / 180;
  // xi: radius, eta: azimuth 0..90 deg, zeta: latitude 0..72 deg -> (e_r, e_theta, e_phi)
  // right-handed.
  const BlockMap map = [=](const Vec3& xi) {
    const double r = R + t / 2 * xi[0];
    const double theta = 0.25 * kPi * (xi[1] + 1), phi = (0.5 * kPi - hole) * 0.5 * (xi[2] + 1);
    return Vec3{r * std::cos(phi) * std::cos(theta), r * std::cos(phi) * std::sin(theta),
                r * std::sin(phi)};
  };
  BuildResult r;
  const Block b =
      mesh_block(r.mesh, map, {base_type(registry, fam), {p.count("nt"), n, n}, {1, 1, 1}, "EALL"});
  r.mesh.add_to_surface("CONTACT", b.side_faces(0, -1));  // inner surface
  apply_family(r.mesh, registry, fam, "CONTACT");
  const double tol = 1e-7 * R;
  r.model = finish_model(r.mesh,
                         "SPEC 3.1.6 stand-in: MacNeal-Harder hemisphere R = 10, t = 0.04, "
                         "18 deg hole, quarter model, " +
                             fam + "; radial load-point displacement, theory 0.094",
                         p.positive("young"), p.number("poisson"));
  const auto sym_y = nodes_where(r.mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; });
  const auto sym_x = nodes_where(r.mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol; });
  fix(r.model, sym_y, {2});
  fix(r.model, sym_x, {1});
  // The equator is free; one node fixed in z removes the vertical rigid-body motion.
  const auto equator_a = nodes_where(
      r.mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol && std::abs(x[2]) < tol; });
  const auto equator_b = nodes_where(
      r.mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol && std::abs(x[2]) < tol; });
  fix(r.model, {equator_a.at(0)}, {3});
  // Quarter model: each load point lies on a symmetry plane, so it carries half of F = 2.
  const double F = p.number("force") / 2;
  std::vector<int> loaded_a, loaded_b;
  Step step = static_step();
  step.cloads = point_force(r.mesh, equator_a, {R, 0, 0}, {F, 0, 0}, &loaded_a);
  const auto more = point_force(r.mesh, equator_b, {0, R, 0}, {0, -F, 0}, &loaded_b);
  step.cloads.insert(step.cloads.end(), more.begin(), more.end());
  add_node_set(r.model, "LOADA", loaded_a);
  add_node_set(r.model, "LOADB", loaded_b);
  step.outputs = {print_request(OutputRequest::Kind::NodePrint, "LOADA", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "LOADB", {"U"})};
  r.model.steps.push_back(step);
  return r;
}

// A ring sector r1..r2, angle 0..sweep, z 0..length: xi radius (graded), eta angle, zeta axial.
Block ring(Mesh& mesh, const std::string& type, double r1, double r2, double sweep_angle,
           double length, std::array<int, 3> divisions, double grading) {
  const BlockMap map = [=](const Vec3& xi) {
    const double r = r1 + (r2 - r1) * 0.5 * (xi[0] + 1), a = sweep_angle * 0.5 * (xi[1] + 1);
    return Vec3{r * std::cos(a), r * std::sin(a), length * 0.5 * (xi[2] + 1)};
  };
  return mesh_block(mesh, map, {type, divisions, {grading, 1, 1}, "EALL"});
}

void pressure_on(Step& step, const Mesh& mesh, const std::string& surface, double p) {
  for (const FaceRef& f : mesh.surfaces.at(surface))
    step.dloads.push_back({f.element, f.face + 1, p, {}});
}

// The face of the C3D21/C3D28 layer of the ring builders: the inner wall (`inner`, the thesis'
// contact face) or the z = 0 face (`bottom`: with one element along the axis, every element).
std::vector<FaceRef> layer_faces(const BuilderParams& p, const Block& b) {
  return p.choice("layer", {"inner", "bottom"}) == "inner" ? b.side_faces(0, -1)
                                                           : b.side_faces(2, -1);
}

BuildResult thick_cylinder(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllFamilies);
  const double r1 = 3, r2 = 9, nu = p.number("poisson"), E = p.positive("young");
  BuildResult r;
  const Block b = ring(r.mesh, base_type(registry, fam), r1, r2, 0.5 * kPi, 1.0,
                       {p.count("nr"), p.count("ntheta"), 1}, p.positive("grading"));
  r.mesh.add_to_surface("INNERFACE", b.side_faces(0, -1));
  r.mesh.add_to_surface("LAYER", layer_faces(p, b));
  apply_family(r.mesh, registry, fam, "LAYER");
  const double u =
      (1 + nu) * r1 * r1 / (E * (r2 * r2 - r1 * r1)) * (r2 * r2 / r1 + (1 - 2 * nu) * r1);
  char theory[64];
  std::snprintf(theory, sizeof theory, "%.5g", u);
  r.model = finish_model(r.mesh,
                         "SPEC 3.1.7 thick-walled cylinder R1 = 3, R2 = 9, plane strain, " + fam +
                             ", nu = " + p.text("poisson") +
                             ", unit internal pressure; u(R1) theory " + theory +
                             ". Quarter model (symmetry planes x = 0, y = 0) in place of "
                             "the thesis' 10 deg sector: oblique symmetry needs *EQUATION",
                         E, nu);
  const double tol = 1e-7 * r2;
  fix(r.model, nodes_where(r.mesh, [&](const Vec3& x) { return x[2] < tol || x[2] > 1 - tol; }),
      {3});
  fix(r.model, nodes_where(r.mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; }), {2});
  fix(r.model, nodes_where(r.mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol; }), {1});
  const auto inner = nodes_where(
      r.mesh, [&](const Vec3& x) { return std::abs(std::hypot(x[0], x[1]) - r1) < tol; });
  add_node_set(r.model, "INNER", inner);
  Step step = static_step();
  pressure_on(step, r.mesh, "INNERFACE", 1.0);
  step.outputs = {print_request(OutputRequest::Kind::NodePrint, "INNER", {"U"})};
  r.model.steps.push_back(step);
  return r;
}

BuildResult patch_test(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllFamilies);
  const std::vector<Vec3> cube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  // SPEC §3.1.8 interior nodes (MacNeal-Harder), in the C3D8 corner order of the cube.
  const std::vector<Vec3> inner = {
      {0.249, 0.342, 0.192}, {0.826, 0.288, 0.288}, {0.850, 0.649, 0.263}, {0.273, 0.750, 0.230},
      {0.320, 0.186, 0.643}, {0.677, 0.305, 0.683}, {0.788, 0.693, 0.644}, {0.165, 0.745, 0.702}};
  BuildResult r;
  // The six outer bricks point their axes at different cube faces, so no choice of wedge axis cuts
  // every shared face alike on both sides: a wedge patch would not conform.
  if (splits_bricks(registry, fam) && corner_nodes(*registry.find(fam)).size() == 6)
    throw InputError({"styk mesh", 0},
                     "patch-test: --element " + fam +
                         ": wedges cannot be split conformingly from the 7 bricks of the "
                         "MacNeal-Harder patch (their axes point in different directions)");
  // Tetrahedra and wedges are split from C3D8 bricks, which keeps their edges straight: curved
  // quadratic pieces do not reproduce constant strain under CalculiX's rules (split.hpp).
  const std::string type = splits_bricks(registry, fam) ? "C3D8" : base_type(registry, fam);
  std::vector<FaceRef> outer_faces;
  mesh_block(r.mesh, hex_map(inner), {type, {1, 1, 1}, {1, 1, 1}, "EALL"});
  // One element between each cube face and the matching face of the inner hexahedron: its own
  // face `f` on the cube, the opposite face on the inner hexahedron.
  static constexpr int kAxis[6] = {2, 2, 1, 0, 1, 0};
  static constexpr int kValue[6] = {-1, 1, -1, 1, 1, -1};
  for (int f = 0; f < 6; ++f) {
    std::vector<Vec3> corners(8);
    for (int c = 0; c < 8; ++c) {
      Vec3 nc = {cube[c][0] * 2 - 1, cube[c][1] * 2 - 1, cube[c][2] * 2 - 1};
      const bool outer = static_cast<int>(nc[kAxis[f]]) == kValue[f];
      nc[kAxis[f]] = kValue[f];
      int k = 0;
      for (int q = 0; q < 8; ++q)
        if (cube[q][0] * 2 - 1 == nc[0] && cube[q][1] * 2 - 1 == nc[1] &&
            cube[q][2] * 2 - 1 == nc[2])
          k = q;
      corners[c] = outer ? cube[k] : inner[k];
    }
    const Block b = mesh_block(r.mesh, hex_map(corners), {type, {1, 1, 1}, {1, 1, 1}, "EALL"});
    const std::vector<FaceRef> side = b.side_faces(kAxis[f], kValue[f]);
    outer_faces.insert(outer_faces.end(), side.begin(), side.end());
  }
  merge_coincident_nodes(r.mesh);
  r.mesh.add_to_surface("CONTACT", outer_faces);
  apply_family(r.mesh, registry, fam, "CONTACT");
  r.model = finish_model(r.mesh,
                         "SPEC 3.1.8 patch test, unit cube of 7 elements (" + fam +
                             "), boundary displacements of constant strain 1e-3: "
                             "sigma = 2000, tau = 400 everywhere",
                         p.positive("young"), p.number("poisson"));
  const double tol = 1e-9;
  const auto boundary = nodes_where(r.mesh, [&](const Vec3& x) {
    return x[0] < tol || x[1] < tol || x[2] < tol || x[0] > 1 - tol || x[1] > 1 - tol ||
           x[2] > 1 - tol;
  });
  add_node_set(r.model, "BOUNDARY", boundary);
  for (int n : boundary) {
    const Vec3& x = r.mesh.nodes[n];
    const double u[3] = {1e-3 * (2 * x[0] + x[1] + x[2]) / 2, 1e-3 * (x[0] + 2 * x[1] + x[2]) / 2,
                         1e-3 * (x[0] + x[1] + 2 * x[2]) / 2};
    for (int d = 0; d < 3; ++d) r.model.boundaries.push_back({n, d + 1, u[d], {}});
  }
  Step step = static_step();
  step.outputs = {print_request(OutputRequest::Kind::ElementPrint, "EALL", {"S"}),
                  print_request(OutputRequest::Kind::NodePrint, "", {"U"})};
  r.model.steps.push_back(step);
  return r;
}

BuildResult cylinder_wall(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllFamilies);
  const double r1 = 2, r2 = 3, length = p.positive("length");
  const double t1 = p.number("t1"), t2 = p.number("t2"), k = p.positive("conductivity");
  BuildResult r;
  const Block b = ring(r.mesh, base_type(registry, fam), r1, r2, 2 * kPi, length,
                       {p.count("nr"), p.count("ntheta"), p.count("nz")}, 1.0);
  r.mesh.add_to_surface("INNERFACE", b.side_faces(0, -1));
  r.mesh.add_to_surface("OUTERFACE", b.side_faces(0, +1));
  r.mesh.add_to_surface("LAYER", layer_faces(p, b));
  merge_coincident_nodes(r.mesh);  // close the ring at 0 / 360 deg
  apply_family(r.mesh, registry, fam, "LAYER");
  char theory[160];
  std::snprintf(theory, sizeof theory,
                "T(r) = %g - (%g - %g) ln(r/2)/ln(3/2); heat flow per unit length 2 pi k "
                "(T1 - T2)/ln(3/2) = %.6g",
                t1, t1, t2, 2 * kPi * k * (t1 - t2) / std::log(r2 / r1));
  r.model =
      finish_model(r.mesh,
                   "SPEC 6.2 steady heat through a cylinder wall r1 = 2 (T = " + p.text("t1") +
                       "), r2 = 3 (T = " + p.text("t2") + "), " + fam +
                       ", k = " + p.text("conductivity") + ": " + theory,
                   1.0, 0.0);
  // A heat deck: the material conducts; it needs no elastic constants.
  Material& material = r.model.materials.front();
  material.young.reset();
  material.poisson.reset();
  material.conductivity = std::array<double, 3>{k, k, k};
  // The walls by their faces: the face nodes a C3D21/C3D28 adds there are interpolated on the
  // quadratic face and sit up to ~1e-6 off the circle, and a C3D14's face centre (the mean of
  // the face's corners) lies inside it.
  const std::vector<int> inner = r.mesh.surface_nodes("INNERFACE");
  const std::vector<int> outer = r.mesh.surface_nodes("OUTERFACE");
  add_node_set(r.model, "INNER", inner);
  add_node_set(r.model, "OUTER", outer);
  std::vector<int> all(r.model.node_count());
  for (int n = 0; n < r.model.node_count(); ++n) all[n] = n;
  add_node_set(r.model, "NALL", all);
  Step step;
  step.name = "HEAT";
  step.kind = StepKind::HeatTransfer;
  step.has_procedure = true;
  for (int n : inner) step.boundaries.push_back({n, 11, t1, {}});
  for (int n : outer) step.boundaries.push_back({n, 11, t2, {}});
  step.outputs = {print_request(OutputRequest::Kind::NodePrint, "NALL", {"NT"}),
                  print_request(OutputRequest::Kind::NodePrint, "INNER", {"RFL"}, true),
                  print_request(OutputRequest::Kind::NodePrint, "OUTER", {"RFL"}, true)};
  r.model.steps.push_back(step);
  return r;
}

}  // namespace

void add_solid_builders(std::vector<BuilderInfo>& all) {
  all.push_back({"single-element",
                 "§2.4",
                 "Single element on the reference cube, top face loaded",
                 {family_param("C3D21", kFamilies),
                  {"loads", "thesis", "thesis (Tab 2.6-2.8 top loads) or consistent (P2 = 1)"},
                  {"young", "1", "Young's modulus E (drops out of the reactions)"},
                  {"poisson", "0.3", "Poisson's ratio"}},
                 single_element});
  all.push_back({"thick-plate",
                 "§3.1.5",
                 "Thick square plate 400 x 400 x 40, clamped edges, centre load",
                 {family_param("C3D21", kAllFamilies),
                  {"n", "6", "elements per side (6, 10; even)"},
                  {"nz", "1", "elements through the thickness"},
                  {"force", "16", "centre load P"},
                  {"young", "2000", "Young's modulus E"},
                  {"poisson", "0.15", "Poisson's ratio"}},
                 thick_plate});
  all.push_back(
      {"hemisphere",
       "§3.1.6",
       "Hemisphere stand-in: MacNeal-Harder R 10, t 0.04, 18° hole, quarter",
       {family_param("C3D21", kAllFamilies),
        {"n", "9", "elements per direction on the surface (n x n)"},
        {"nt", "1", "elements through the thickness"},
        {"force", "2", "load F of the full hemisphere (half on each symmetry-plane point)"},
        {"young", "6.825e7", "Young's modulus E"},
        {"poisson", "0.3", "Poisson's ratio"}},
       hemisphere});
  all.push_back({"thick-cylinder",
                 "§3.1.7",
                 "Thick-walled cylinder R 3-9, plane strain, 4:1 radial grading",
                 {family_param("C3D21", kAllFamilies),
                  {"nr", "5", "elements through the wall"},
                  {"ntheta", "9", "elements around the quarter (10° each, as the thesis' sector)"},
                  {"grading", "4", "outer / inner element length"},
                  {"poisson", "0.49", "Poisson's ratio (0.49, 0.499, 0.4999)"},
                  {"young", "1000", "Young's modulus E"},
                  {"layer", "inner",
                   "face of the C3D21/C3D28 layer: inner (wall) or bottom (z = 0: every element)"}},
                 thick_cylinder});
  all.push_back({"patch-test",
                 "§3.1.8",
                 "Patch test: unit cube of 7 irregular elements",
                 {family_param("C3D21", kAllFamilies),
                  {"young", "1e6", "Young's modulus E"},
                  {"poisson", "0.25", "Poisson's ratio"}},
                 patch_test});
  all.push_back({"cylinder-wall",
                 "§6.2",
                 "Steady heat through a cylinder wall r 2-3, T 100 inside, 25 outside",
                 {family_param("C3D28", kAllFamilies),
                  {"nr", "1", "elements through the wall"},
                  {"ntheta", "40", "elements around"},
                  {"nz", "5", "elements along the axis"},
                  {"length", "1", "axial length"},
                  {"t1", "100", "temperature on r = 2"},
                  {"t2", "25", "temperature on r = 3"},
                  {"conductivity", "1", "conductivity k"},
                  {"layer", "inner",
                   "face of the C3D21/C3D28 layer: inner (wall) or bottom (z = 0: with --nz 1, "
                   "every element)"}},
                 cylinder_wall});
}

}  // namespace styk::mesher::detail
