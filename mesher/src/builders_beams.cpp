// Builders of the beam models: SPEC §2.1 cantilever, §3.1.1 straight beam, §3.1.2 regular and
// distorted 10 x 2 x 2 beam, §3.1.3 curved beam (MacNeal-Harder stand-in), §3.1.4 twisted beam.
// Contact faces (S1 of C3D21/C3D28) go on the beam's lower face (the lower row for §3.1.4).
#include <cmath>
#include <cstdio>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "styk/mesher/block_mesh.hpp"

namespace styk::mesher::detail {
namespace {

// The brick families and the tetrahedra and wedges split from bricks (mesher/split.hpp).
const std::vector<std::string> kFamilies = {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28",
                                            "C3D4", "C3D10", "C3D6",  "C3D15"};

std::string fmt_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A box beam along x: size (L, width y, height z), TIPFACE = x = L, CONTACT = the face of the
// C3D21/C3D28 layer: the z = 0 face (bottom), or the y = 0 side face (side: with one element
// across the width every element has a face there, so the whole beam is of the family).
Mesh box_beam(const ElementRegistry& registry, const std::string& family, const Vec3& size,
              const std::array<int, 3>& divisions,
              const std::function<void(Mesh&)>& distort = nullptr, bool side_layer = false) {
  Mesh mesh;
  const Block b = mesh_block(mesh, box_map({0, 0, 0}, size),
                             {base_type(registry, family), divisions, {1, 1, 1}, "EALL"});
  mesh.add_to_surface("ROOTFACE", b.side_faces(0, -1));
  mesh.add_to_surface("TIPFACE", b.side_faces(0, +1));
  mesh.add_to_surface("CONTACT", side_layer ? b.side_faces(1, -1) : b.side_faces(2, -1));
  if (distort) distort(mesh);
  apply_family(mesh, registry, family, "CONTACT");
  return mesh;
}

// The cantilever's element distortion in the bending plane x-z (MacNeal-Harder's element shape
// tests): the grid line x_i through the height turns by `angle` about the beam's mid-height,
// x += s(x) (z - h/2) tan(angle). parallelogram: s = 1 everywhere (the end faces turn too);
// trapezoid: s = -1, +1, -1, ... on the interior lines, 0 on the end faces, linear in between
// (mid-edge nodes stay at the middle of straight edges).
std::function<void(Mesh&)> cantilever_distortion(const BuilderParams& p, double L, double h,
                                                 int nx) {
  const std::string kind = p.choice("distortion", {"none", "parallelogram", "trapezoid"});
  const double angle = p.number("angle");
  if (kind == "none") return nullptr;
  if (!(std::abs(angle) < 89.0))
    p.fail("--angle must lie within +-89 degrees, not " + p.text("angle"));
  const double t = std::tan(angle * kPi / 180), dx = L / nx;
  // A trapezoid's narrow side is dx - h tan(angle): it must stay positive.
  if (kind == "trapezoid" && !(h * std::abs(t) < dx))
    p.fail("--angle " + p.text("angle") + " inverts the trapezoids: with elements " +
           fmt_number(dx) + " long and a beam " + fmt_number(h) +
           " high the angle must stay below " + fmt_number(std::atan(dx / h) * 180 / kPi) +
           " degrees");
  const bool trapezoid = kind == "trapezoid";
  return [=](Mesh& mesh) {
    auto line_sign = [&](int i) {
      if (!trapezoid) return 1.0;
      return i == 0 || i == nx ? 0.0 : (i % 2 ? 1.0 : -1.0);
    };
    for (Vec3& x : mesh.nodes) {
      const double u = x[0] / dx;
      const int i = std::min(nx - 1, std::max(0, static_cast<int>(std::floor(u))));
      const double f = u - i, s = (1 - f) * line_sign(i) + f * line_sign(i + 1);
      x[0] += s * (x[2] - h / 2) * t;
    }
  };
}

// Clamps ROOT, writes the step with the loads and the usual prints.
void finish_cantilever(BuildResult& r, const std::vector<int>& root, const std::vector<int>& tip,
                       std::vector<ConcentratedLoad> loads) {
  add_node_set(r.model, "ROOT", root);
  add_node_set(r.model, "TIP", tip);
  fix(r.model, root, {1, 2, 3});
  Step step = static_step();
  step.cloads = std::move(loads);
  step.outputs = {print_request(OutputRequest::Kind::NodePrint, "TIP", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "ROOT", {"RF"}, true)};
  r.model.steps.push_back(step);
}

std::vector<ConcentratedLoad> loaded_point(BuildResult& r, const std::vector<int>& candidates,
                                           const Vec3& target, const Vec3& force) {
  std::vector<int> loaded;
  std::vector<ConcentratedLoad> loads = point_force(r.mesh, candidates, target, force, &loaded);
  add_node_set(r.model, "LOADED", loaded);
  return loads;
}

BuildResult cantilever(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllHexFamilies);
  const std::string mesh_text = p.text("mesh");
  int nx = 0, nz = 0;
  char extra = 0;
  if (std::sscanf(mesh_text.c_str(), "%dx%d%c", &nx, &nz, &extra) != 2 || nx < 1 || nz < 1)
    p.fail("--mesh: expected LENGTHxHEIGHT divisions such as 6x1, 12x2, 12x4, 24x8, not '" +
           mesh_text + "'");
  const double L = p.positive("length"), b = p.positive("width"), h = p.positive("height");
  const double P = p.number("force");
  const bool side_layer = p.choice("layer", {"bottom", "side"}) == "side";
  BuildResult r;
  r.mesh = box_beam(registry, fam, {L, b, h}, {nx, 1, nz}, cantilever_distortion(p, L, h, nx),
                    side_layer);
  const double E = p.positive("young");
  r.model = finish_model(r.mesh,
                         "SPEC 2.1 cantilever " + fam + " " + mesh_text + ": P = " + fmt_number(P) +
                             " as a uniform shear traction on x = L, clamped root; beam theory "
                             "u = P l^3 / (3 E I) = " +
                             fmt_number(P * L * L * L / (3 * E * b * h * h * h / 12)),
                         E, p.number("poisson"));
  // The end faces by their element faces (a parallelogram mesh turns them).
  const std::vector<int> root = r.mesh.surface_nodes("ROOTFACE");
  const std::vector<int> tip = r.mesh.surface_nodes("TIPFACE");
  finish_cantilever(r, root, tip,
                    traction_loads(r.model, registry, r.mesh.surfaces.at("TIPFACE"), {0, 0, P}));
  return r;
}

// SPEC §3.1.1 and §3.1.2 share the set-up: tension = unit traction resultant on the end face,
// bending = a point force along z at the middle of the top edge of the free end.
BuildResult straight_beam(const BuilderParams& p, const ElementRegistry& registry,
                          const std::string& title, const Vec3& size, int n, double bending_force,
                          const std::function<void(Mesh&)>& distort) {
  const std::string fam = family(p, kFamilies);
  const std::string load = p.choice("load", {"tension", "bending"});
  BuildResult r;
  r.mesh = box_beam(registry, fam, size, {n, 1, 1}, distort);
  const double tol = 1e-6 * r.mesh.size();
  r.model =
      finish_model(r.mesh, title + " " + fam + ", " + std::to_string(n) + " elements, " + load,
                   p.positive("young"), p.number("poisson"));
  const auto root = nodes_where(r.mesh, [&](const Vec3& x) { return x[0] < tol; });
  const auto tip = nodes_where(r.mesh, [&](const Vec3& x) { return x[0] > size[0] - tol; });
  std::vector<ConcentratedLoad> loads;
  if (load == "tension") {
    loads = traction_loads(r.model, registry, r.mesh.surfaces.at("TIPFACE"), {1.0, 0, 0});
  } else {
    const auto edge = nodes_where(
        r.mesh, [&](const Vec3& x) { return x[0] > size[0] - tol && x[2] > size[2] - tol; });
    loads = loaded_point(r, edge, {size[0], size[1] / 2, size[2]}, {0, 0, bending_force});
  }
  finish_cantilever(r, root, tip, std::move(loads));
  return r;
}

BuildResult straight_beam_311(const BuilderParams& p, const ElementRegistry& registry) {
  const double L = p.positive("length"), W = p.positive("height"), D = p.positive("width");
  return straight_beam(p, registry,
                       "SPEC 3.1.1 straight cantilever (1a tension u = 3.0e-5, "
                       "1b bending u = 0.108)",
                       {L, D, W}, p.count("n"), 1.0, nullptr);
}

BuildResult beam_312(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string mesh = p.choice("mesh", {"regular", "distorted"});
  const int n = p.count("n");
  std::function<void(Mesh&)> distort;
  if (mesh == "distorted") {
    if (n != 5) p.fail("--mesh distorted is defined for --n 5 (SPEC 3.1.2 stand-in)");
    // SPEC §3.1.2 stand-in: interior cross-sections through x = 1, 3, 6, 8 on the top face and
    // x = 2, 4, 5, 9 on the bottom face; nodes move within each element bilinearly in (x, z).
    distort = [](Mesh& m) {
      const double top[6] = {0, 1, 3, 6, 8, 10}, bottom[6] = {0, 2, 4, 5, 9, 10};
      for (Vec3& x : m.nodes) {
        const int i = std::min(4, static_cast<int>(std::floor(x[0] / 2 + 1e-9)));
        const double t = (x[0] - 2 * i) / 2, s = x[2] / 2;
        const double lo = bottom[i] + (top[i] - bottom[i]) * s;
        const double hi = bottom[i + 1] + (top[i + 1] - bottom[i + 1]) * s;
        x[0] = lo + t * (hi - lo);
      }
    };
  }
  return straight_beam(p, registry,
                       "SPEC 3.1.2 beam 10 x 2 x 2, " + mesh +
                           " mesh (2a tension u = 1.6667e-3, 2b bending P = 0.6 u = 0.1)",
                       {10, 2, 2}, n, 0.6, distort);
}

BuildResult curved_beam(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kAllHexFamilies);
  const std::string load = p.choice("load", {"inplane", "outofplane"});
  const int n = p.count("n"), nr = p.count("nr");
  const double ri = 4.12, ro = 4.32, t = 0.1;
  // xi: thickness (z), eta: radius, zeta: angle 0..90 deg about z -> (z, r, theta) right-handed.
  const BlockMap map = [=](const Vec3& xi) {
    const double z = t * 0.5 * (xi[0] + 1), r = ri + (ro - ri) * 0.5 * (xi[1] + 1);
    const double a = 0.25 * kPi * (xi[2] + 1);
    return Vec3{r * std::cos(a), r * std::sin(a), z};
  };
  BuildResult r;
  const Block b =
      mesh_block(r.mesh, map, {base_type(registry, fam), {1, nr, n}, {1, 1, 1}, "EALL"});
  r.mesh.add_to_surface("ROOTFACE", b.side_faces(2, -1));
  r.mesh.add_to_surface("TIPFACE", b.side_faces(2, +1));
  r.mesh.add_to_surface("CONTACT", b.side_faces(0, -1));
  apply_family(r.mesh, registry, fam, "CONTACT");
  const double tol = 1e-6 * r.mesh.size();
  r.model =
      finish_model(r.mesh,
                   "SPEC 3.1.3 stand-in: MacNeal-Harder curved beam " + fam + ", unit " + load +
                       " tip shear (0.08734 in-plane, 0.5022 "
                       "out-of-plane)",
                   p.positive("young"), p.number("poisson"));
  const auto root = nodes_where(r.mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; });
  const auto tip = nodes_where(r.mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol; });
  // At the tip (theta = 90 deg) the in-plane shear is radial (y), the out-of-plane one along z.
  const Vec3 force = load == "inplane" ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  finish_cantilever(r, root, tip,
                    traction_loads(r.model, registry, r.mesh.surfaces.at("TIPFACE"), force));
  return r;
}

BuildResult twisted_beam(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const std::string load = p.choice("load", {"inplane", "outofplane"});
  const int n = p.count("n"), across = p.count("across");
  const double L = 12, W = 1.1, D = 0.32;
  // Sweep of the W x D section along x with a 90 deg twist: root width along y, thickness along
  // z; xi: width, eta: thickness, zeta: length -> (y, z, x) right-handed.
  const PatchMap section = [=](double u, double v) { return Vec3{W / 2 * u, D / 2 * v, 0}; };
  const PathMap path = [=](double s) { return Vec3{L * s, 0, 0}; };
  const BlockMap map = sweep(section, path, {0, 1, 0}, [](double s) { return 0.5 * kPi * s; });
  BuildResult r;
  const Block b =
      mesh_block(r.mesh, map, {base_type(registry, fam), {across, 1, n}, {1, 1, 1}, "EALL"});
  r.mesh.add_to_surface("CONTACT", b.side_faces(0, -1));  // the lower row's outer face
  std::vector<int> lower;
  for (const FaceRef& f : b.side_faces(0, -1)) lower.push_back(f.element);
  r.mesh.add_to_element_set("LOWER", lower);
  apply_family(r.mesh, registry, fam, "CONTACT");
  const double tol = 1e-6 * r.mesh.size();
  r.model =
      finish_model(r.mesh,
                   "SPEC 3.1.4 twisted beam " + fam +
                       (fam == "C3D21" || fam == "C3D28" ? " lower row + C3D20 upper row" : "") +
                       ", unit " + load + " tip shear (in-plane theory 0.005424)",
                   p.positive("young"), p.number("poisson"));
  const auto root = nodes_where(r.mesh, [&](const Vec3& x) { return x[0] < tol; });
  const auto tip = nodes_where(r.mesh, [&](const Vec3& x) { return x[0] > L - tol; });
  // At the tip the width runs along z: the load sits at the middle of the tip's top edge
  // (z = +W/2). In-plane = along the tip's width (z; checked with CalculiX C3D20 12x2:
  // 5.37e-3 against the thesis' Abaqus 4.86e-3 and the theory 5.424e-3), out-of-plane = y
  // (1.78e-3, MacNeal-Harder theory 1.754e-3).
  const auto edge =
      nodes_where(r.mesh, [&](const Vec3& x) { return x[0] > L - tol && x[2] > W / 2 - tol; });
  const Vec3 force = load == "inplane" ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  finish_cantilever(r, root, tip, loaded_point(r, edge, {L, 0, W / 2}, force));
  return r;
}

}  // namespace

void add_beam_builders(std::vector<BuilderInfo>& all) {
  all.push_back(
      {"cantilever",
       "§2.1",
       "Cantilever l = 150, b = 2.5, h = 5 (meshes 6x1, 12x2, 12x4, 24x8)",
       {family_param("C3D8", kAllHexFamilies),
        {"mesh", "6x1", "divisions along the length x height (1 across the width)"},
        {"layer", "bottom",
         "face of the C3D21/C3D28 layer: bottom (z = 0) or side (y = 0: every element)"},
        {"distortion", "none", "element shapes in the x-z plane: none, parallelogram or trapezoid"},
        {"angle", "0", "distortion angle of the element sides, degrees"},
        {"length", "150", "beam length l"},
        {"width", "2.5", "width b"},
        {"height", "5", "height h (load direction)"},
        {"young", "70000", "Young's modulus E"},
        {"poisson", "0", "Poisson's ratio"},
        {"force", "5", "tip force P (uniform shear traction on the end face)"}},
       cantilever});
  all.push_back({"straight-beam",
                 "§3.1.1",
                 "Straight cantilever 6 x 0.2 x 0.1 (1a tension, 1b bending)",
                 {family_param("C3D21", kFamilies),
                  {"n", "6", "elements along the length (6, 12, 24)"},
                  {"load", "tension", "tension (1a) or bending (1b)"},
                  {"length", "6", "length L"},
                  {"height", "0.2", "height W (bending direction)"},
                  {"width", "0.1", "width D"},
                  {"young", "1e7", "Young's modulus E"},
                  {"poisson", "0.3", "Poisson's ratio"}},
                 straight_beam_311});
  all.push_back({"beam-10x2x2",
                 "§3.1.2",
                 "Cantilever 10 x 2 x 2, regular or distorted mesh (2a, 2b)",
                 {family_param("C3D21", kFamilies),
                  {"n", "5", "elements along the length"},
                  {"mesh", "regular", "regular or distorted (stand-in of SPEC §3.1.2)"},
                  {"load", "tension", "tension (2a) or bending (2b, P = 0.6)"},
                  {"young", "1500", "Young's modulus E"},
                  {"poisson", "0.3", "Poisson's ratio"}},
                 beam_312});
  all.push_back({"curved-beam",
                 "§3.1.3",
                 "Curved beam stand-in: MacNeal-Harder 90° arc r 4.12-4.32, t 0.1",
                 {family_param("C3D21", kAllHexFamilies),
                  {"n", "6", "elements along the arc"},
                  {"nr", "1", "elements across the radial depth"},
                  {"load", "inplane", "inplane (0.08734) or outofplane (0.5022) unit tip shear"},
                  {"young", "1e7", "Young's modulus E"},
                  {"poisson", "0.25", "Poisson's ratio"}},
                 curved_beam});
  all.push_back({"twisted-beam",
                 "§3.1.4",
                 "Twisted beam 12 x 1.1 x 0.32, 90° twist (C3D21/C3D28 lower row + C3D20)",
                 {family_param("C3D21", kFamilies),
                  {"n", "12", "elements along the length (12, 24)"},
                  {"across", "2", "elements across the width (rows)"},
                  {"load", "inplane", "inplane (theory 0.005424) or outofplane unit tip shear"},
                  {"young", "29e6", "Young's modulus E"},
                  {"poisson", "0.22", "Poisson's ratio"}},
                 twisted_beam});
}

}  // namespace styk::mesher::detail
