// Builder of the SPEC §4.3 conical fit (pin in a tapered sleeve), quarter model, with the SPEC
// stand-in geometry: taper 1:10 on the diameter, engagement 30 long from Ø18.5 (bottom, z = 0)
// to Ø21.5, the pin continuing 10 above the sleeve with the same taper; sleeve outer Ø40,
// bottom face fixed; 20 MPa on the pin's top face. The pin is an O-grid.
#include <cmath>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "contact_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

const std::vector<std::string> kFamilies = {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"};

constexpr double kBottomRadius = 9.25, kTaper = 0.05;  // radius grows 1:20 (diameter 1:10)
constexpr double kEngagement = 30, kPinLength = 40, kSleeveRadius = 20;

double pin_radius(double z) { return kBottomRadius + kTaper * z; }

BuildResult conical_fit(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const int around = p.count("around", 2);
  if (around % 2 != 0) p.fail("--around must be even (two O-grid blocks per quarter)");
  const int n = around / 2, rings = p.count("pin-rings"), sleeve_rings = p.count("sleeve-rings");
  const int rows = p.count("fit-rows"), top_rows = p.count("top-rows");
  BuildResult r;
  Mesh& mesh = r.mesh;
  const std::string type = base_type(registry, fam);
  const std::vector<SectionPatch> o_grid = quarter_o_grid(0.5);
  const double z[3] = {0, kEngagement, kPinLength};
  const int layers[2] = {rows, top_rows};
  for (int k = 0; k < 2; ++k)
    for (int part = 0; part < 3; ++part) {
      const Block b = mesh_block(mesh, prism(o_grid[part], z[k], z[k + 1], pin_radius),
                                 {type, {part == 0 ? n : rings, n, layers[k]}, {1, 1, 1}, "PIN"});
      if (k == 1) mesh.add_to_surface("PIN_TOP", b.side_faces(2, +1));
    }
  // Sleeve: xi radial from the cone to the outer cylinder, eta 0..90 deg, zeta axial.
  const BlockMap sleeve = [](const Vec3& xi) {
    const double zz = kEngagement * 0.5 * (xi[2] + 1), a = 0.25 * kPi * (xi[1] + 1);
    const double rr = pin_radius(zz) + (kSleeveRadius - pin_radius(zz)) * 0.5 * (xi[0] + 1);
    return Vec3{rr * std::cos(a), rr * std::sin(a), zz};
  };
  mesh_block(mesh, sleeve, {type, {sleeve_rings, around, rows}, {1, 1, 1}, "SLEEVE"});
  merge_coincident_nodes(mesh);
  split_bodies(mesh, "SLEEVE", "SLEEVE_BORE", "PIN_CONE");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("PIN"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("SLEEVE"));
  convert_contact_layers(mesh, registry, fam, {"SLEEVE_BORE", "PIN_CONE"});

  const double E = p.positive("young"), nu = p.number("poisson"), q = p.number("pressure");
  r.model = contact_model(
      mesh,
      "SPEC 4.3 conical fit stand-in, quarter model, " + fam +
          ": pin taper 1:10, D18.5 -> D21.5 over the engagement 30, 10 above the sleeve; sleeve "
          "D40, bottom fixed; " +
          fmt_number(q) + " MPa on the pin top, mu = " + p.text("mu") +
          ". Published max Mises 58 (mu 0), 42 (0.2), 35 MPa (0.4), low in the pin",
      {{"PIN", "PIN", E, nu, {}}, {"SLEEVE", "SLEEVE", E, nu, {}}});
  add_surfaces(r.model, mesh, {"SLEEVE_BORE", "PIN_CONE", "PIN_TOP"});
  add_contact(r.model, "CONE", "SLEEVE_BORE", "PIN_CONE", friction_parameter(p, "mu"));
  const double tol = 1e-7 * mesh.size();
  fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[0]) < tol; }), {1});
  fix(r.model, nodes_where(mesh, [&](const Vec3& x) { return std::abs(x[1]) < tol; }), {2});
  // The sleeve's bottom only: the pin's bottom face lies in the same plane and is free.
  std::vector<int> base;
  for (int e : mesh.element_sets.at("SLEEVE"))
    for (int node : mesh.elements[e].nodes)
      if (mesh.nodes[node][2] < tol) base.push_back(node);
  add_node_set(r.model, "SLEEVE_BASE", base);
  fix(r.model, r.model.nsets.at("SLEEVE_BASE").nodes, {1, 2, 3});
  add_node_set(r.model, "PINTOP", mesh.surface_nodes("PIN_TOP"));
  Step step = static_step();
  pressure_on(step, mesh, "PIN_TOP", q);
  step.outputs = {contact_print(fam),
                  print_request(OutputRequest::Kind::NodePrint, "PINTOP", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "SLEEVE_BASE", {"RF"}, true),
                  print_request(OutputRequest::Kind::ElementPrint, "PIN", {"S"})};
  r.model.steps.push_back(step);
  return r;
}

}  // namespace

void add_conical_fit_builder(std::vector<BuilderInfo>& all) {
  all.push_back({"conical-fit",
                 "§4.3",
                 "Conical fit: pin in a tapered sleeve (stand-in geometry), quarter",
                 {family_param("C3D21", kFamilies),
                  {"around", "8", "elements around the quarter (even; contact elements per row)"},
                  {"fit-rows", "12", "axial elements along the engagement (contact rows)"},
                  {"top-rows", "2", "axial elements of the pin above the sleeve"},
                  {"pin-rings", "1", "radial elements of the pin's outer O-grid ring"},
                  {"sleeve-rings", "2", "radial elements of the sleeve"},
                  {"pressure", "20", "pressure on the pin's top face (MPa)"},
                  {"mu", "0", "friction coefficient (0, 0.2, 0.4; 'rough')"},
                  {"young", "200000", "Young's modulus E (MPa)"},
                  {"poisson", "0.3", "Poisson's ratio"}},
                 conical_fit});
}

}  // namespace styk::mesher::detail
