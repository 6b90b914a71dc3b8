// Builder of SPEC §2.4, thesis Tab 2.9-2.11: two elements of one family stacked on the reference
// cubes [-1,1]^2 x [-1,1] (lower) and [-1,1]^2 x [1,3] (upper), separated by a zero-thickness
// frictionless contact interface (coincident nodes: node-to-node pairs). The layout of
// tests/verification/spec_2_4_contact_test.cpp: lower bottom supported in z, the in-plane rigid
// motions removed on both elements (node at x = y = -1: ux, uy; node at x = 1, y = -1: uy), the
// thesis' point loads on the upper top face; the upper element is held in z by the contact only.
// C3D21/C3D28: both contact faces are S1 (the lower element turned upside down).
#include <cmath>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "contact_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

const std::vector<std::string> kFamilies = {"C3D14", "C3D21", "C3D28", "C3D20", "C3D8"};

bool near(double a, double b) { return std::abs(a - b) < 1e-9; }

BuildResult stacked_elements(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  BuildResult r;
  Mesh& mesh = r.mesh;
  mesh_block(mesh, box_map({-1, -1, -1}, {2, 2, 2}),
             {base_type(registry, fam), {1, 1, 1}, {1, 1, 1}, "LOWER"});
  mesh_block(mesh, box_map({-1, -1, 1}, {2, 2, 2}),
             {base_type(registry, fam), {1, 1, 1}, {1, 1, 1}, "UPPER"});
  merge_coincident_nodes(mesh);
  split_bodies(mesh, "LOWER", "LOWER_TOP", "UPPER_BOTTOM");
  convert_contact_layers(mesh, registry, fam, {"UPPER_BOTTOM", "LOWER_TOP"});
  const double E = p.positive("young"), nu = p.number("poisson");
  const bool c3d14 = fam == "C3D14", c3d8 = fam == "C3D8";
  r.model = contact_model(
      mesh,
      "SPEC 2.4 two stacked " + fam +
          " on the reference cubes, frictionless zero-thickness interface, thesis top loads (" +
          (c3d14  ? "corners -1/3, centre -8/3"
           : c3d8 ? "corners -1, the consistent loads"
                  : "corners +1/3, mid-edges -4/3") +
          "); pair forces " +
          (fam == "C3D14"   ? "0.5935 (corners), 1.626 (centre), Tab 2.9"
           : fam == "C3D21" ? "1/9, 4/9, 16/9, Tab 2.10"
           : fam == "C3D28" ? "1/36, 5/36, 25/36, Tab 2.11"
           : c3d8           ? "1 at each corner"
                            : "corner pairs would have to pull (A_i = -1/3): they open") +
          ", sum 4",
      {{"LOWER", "LOWER", E, nu, {}}, {"UPPER", "UPPER", E, nu, {}}});
  add_surfaces(r.model, mesh, {"UPPER_BOTTOM", "LOWER_TOP"});
  add_contact(r.model, "SMOOTH", "UPPER_BOTTOM", "LOWER_TOP", std::nullopt);

  const auto bottom = nodes_where(mesh, [](const Vec3& x) { return near(x[2], -1); });
  const auto top = nodes_where(mesh, [](const Vec3& x) { return near(x[2], 3); });
  add_node_set(r.model, "BOTTOM", bottom);
  add_node_set(r.model, "TOP", top);
  fix(r.model, bottom, {3});
  for (double z : {-1.0, 3.0}) {
    fix(r.model,
        nodes_where(
            mesh, [z](const Vec3& x) { return near(x[0], -1) && near(x[1], -1) && near(x[2], z); }),
        {1, 2});
    fix(r.model,
        nodes_where(
            mesh, [z](const Vec3& x) { return near(x[0], 1) && near(x[1], -1) && near(x[2], z); }),
        {2});
  }
  Step step = static_step();
  for (int n : top) {
    const Vec3& x = mesh.nodes[n];
    const bool corner = near(std::abs(x[0]), 1) && near(std::abs(x[1]), 1);
    const bool centre = near(x[0], 0) && near(x[1], 0);
    // Tab 2.9: C3D14's top corners -1/3 and face centre -8/3 (not its consistent loads); Tab
    // 2.10/2.11 (and C3D20): the consistent loads of the serendipity top face, +1/3 and -4/3;
    // C3D8 (not tabulated; SPEC: it passes the physical contact condition): -1 per corner.
    double cf3 = corner ? 1.0 / 3 : -4.0 / 3;
    if (c3d14) cf3 = corner ? -1.0 / 3 : (centre ? -8.0 / 3 : 0.0);
    if (c3d8) cf3 = -1.0;
    if (cf3 != 0.0) step.cloads.push_back({n, 3, cf3, {}});
  }
  step.outputs = {contact_print(fam),
                  print_request(OutputRequest::Kind::NodePrint, "BOTTOM", {"RF"}, true),
                  print_request(OutputRequest::Kind::NodePrint, "TOP", {"U"})};
  r.model.steps.push_back(step);
  return r;
}

}  // namespace

void add_stacked_elements_builder(std::vector<BuilderInfo>& all) {
  all.push_back({"stacked-elements",
                 "§2.4",
                 "Two stacked elements with a zero-thickness contact interface (Tab 2.9-2.11)",
                 {family_param("C3D21", kFamilies),
                  {"young", "210000", "Young's modulus E (the pair forces do not depend on it)"},
                  {"poisson", "0.3", "Poisson's ratio"}},
                 stacked_elements});
}

}  // namespace styk::mesher::detail
