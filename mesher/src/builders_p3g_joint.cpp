// Builder of the SPEC §4.5 P3G polygon joint (DIN 32711: D 60, n 3, e 2.25), full model: shaft
// 120 long (z = 0 fixed; round Ø65 up to z = 80, the polygon over the hub), hub z = 80..120 =
// arm Ø80 x 20 + flange Ø155 x 20 at the shaft's end (--flange-at shoulder: the flange next to
// the round part, the arm at the shaft's end); the hub's bore is the polygon, meshed with
// coincident nodes, frictionless; 1000 N m on the flange rim.
//
// Section: a hexagonal core (sides centred on v = 60 k, alternately on the polygon's flats and
// lobes), a ring to the polygon (nodes at equal steps of the profile parameter v, p3g_point),
// and rings outside it: the shaft's round part to Ø65 on the rays through the polygon's nodes,
// the hub to Ø80 half-way from those rays to equal angles, and the flange to Ø155 at equal
// angles (graded with the radius), so the rim carries equal elements.
#include <algorithm>
#include <cmath>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "contact_support.hpp"
#include "joint_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

const std::vector<std::string> kFamilies = {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"};

constexpr double kD = 60, kE = 2.25;
constexpr int kLobes = 3;
constexpr double kRoundRadius = 32.5, kArmRadius = 40, kFlangeRadius = 77.5;
constexpr double kShaftLength = 120, kHubStart = 80, kFlangeStart = 100;

struct P3gMesh {
  int around = 48;        // elements around (multiple of 6: contact elements per row)
  int arm_rows = 3;       // axial, z 80..100
  int flange_rows = 3;    // axial, z 100..120
  int shaft_rows = 4;     // axial, z 0..80
  int shaft_rings = 1;    // hexagon to polygon
  int round_rings = 1;    // polygon to Ø65
  int hub_rings = 10;     // polygon to Ø80
  int flange_rings = 28;  // Ø80 to Ø155
  double core = 25;       // hexagon circumradius
};

// Profile parameter v along hexagon side k (u in [0, 1]).
double parameter(int side, double u) { return (-30.0 + 60.0 * (side + u)) * kPi / 180.0; }

SectionCurve polygon(int side) {
  return [side](double u) { return p3g_point(kD, kLobes, kE, parameter(side, u)); };
}

// Polar angle of the polygon's point at v: v plus the angle between the ray at v and the point
// (zero on the flats and lobes), continuous in v.
double polar_angle(double v) {
  const Vec3 q = p3g_point(kD, kLobes, kE, v);
  return v + std::atan2(q[1] * std::cos(v) - q[0] * std::sin(v),
                        q[0] * std::cos(v) + q[1] * std::sin(v));
}

// The circle of radius r with its n element nodes per hexagon side at the angles
// v + turn (polar_angle(v) - v): turn 1 puts them on the rays through the polygon's nodes, 0 at
// equal angles. Linear in angle within an element, so mid-edge nodes sit at the arcs' middles.
SectionCurve circle(int side, double r, double turn, int n) {
  const auto node_angle = [side, turn, n](int i) {
    const double v = parameter(side, static_cast<double>(i) / n);
    return v + turn * (polar_angle(v) - v);
  };
  return [=](double u) {
    const int i = std::min(n - 1, static_cast<int>(std::floor(u * n)));
    const double t = u * n - i, a = node_angle(i) + t * (node_angle(i + 1) - node_angle(i));
    return Vec3{r * std::cos(a), r * std::sin(a), 0.0};
  };
}

BuildResult p3g_joint(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  P3gMesh m;
  m.around = p.count("around", 6);
  if (m.around % 6 != 0) p.fail("--around must be a multiple of 6 (one hexagon side each)");
  m.arm_rows = p.count("arm-rows");
  m.flange_rows = p.count("flange-rows");
  m.shaft_rows = p.count("shaft-rows");
  m.shaft_rings = p.count("shaft-rings");
  m.round_rings = p.count("round-rings");
  m.hub_rings = p.count("hub-rings");
  m.flange_rings = p.count("flange-rings");
  m.core = p.positive("core");
  if (m.core >= 27) p.fail("--core must stay inside the polygon (< 27)");
  const double torque = p.number("torque");
  const bool sector = sector_requested(p);

  BuildResult r;
  Mesh& mesh = r.mesh;
  const std::string type = base_type(registry, fam);
  const int n = m.around / 6;
  // The flange's place on the hub is in the thesis' lost figure: at the shaft's end (z 100-120,
  // the arm next to the shoulder) or at the shoulder (z 80-100, the arm at the shaft's end).
  const bool flange_at_shoulder = p.choice("flange-at", {"end", "shoulder"}) == "shoulder";
  const double flange_z0 = flange_at_shoulder ? kHubStart : kFlangeStart;
  const double arm_z0 = flange_at_shoulder ? kFlangeStart : kHubStart;
  const double hub_half = kFlangeStart - kHubStart;
  const int first_rows = flange_at_shoulder ? m.flange_rows : m.arm_rows;
  const double row = hub_half / first_rows;
  const AxialSegment round{0, kHubStart, m.shaft_rows,
                           1.0 / continuing_grading(row, kHubStart, m.shaft_rows)};
  const AxialSegment arm{arm_z0, arm_z0 + hub_half, m.arm_rows, 1.0};
  const AxialSegment flange{flange_z0, flange_z0 + hub_half, m.flange_rows, 1.0};
  const double flange_grading = kFlangeRadius / kArmRadius;
  // The faces along the polygon inside the round part, both sides: a C3D28 layer on the
  // contact surface closes through them (docs/mesher.md).
  // (Kept as a mesh surface so that a sector cut renumbers it.)
  const std::string round_polygon = "__ROUND_POLYGON";
  for (const AxialSegment& seg : {round, arm, flange}) {
    const bool hub = seg.z0 >= kHubStart;
    const bool is_flange = hub && seg.z0 == flange_z0;
    mesh_hexagon_core(mesh, type, m.core, n, seg, "SHAFT");
    for (int k = 0; k < 6; ++k) {
      const auto spec = [&](int radial, double grading, const char* elset) {
        return BlockSpec{type, {radial, n, seg.rows}, {grading, 1, seg.grading}, elset};
      };
      const Block ring = mesh_block(mesh, curve_ring(hexagon_side(m.core, k), polygon(k), seg),
                                    spec(m.shaft_rings, 1, "SHAFT"));
      if (!hub) {
        const Block outer =
            mesh_block(mesh, curve_ring(polygon(k), circle(k, kRoundRadius, 1, n), seg),
                       spec(m.round_rings, 1, "SHAFT"));
        mesh.add_to_surface(round_polygon, ring.side_faces(0, +1));
        mesh.add_to_surface(round_polygon, outer.side_faces(0, -1));
        continue;
      }
      mesh_block(mesh, curve_ring(polygon(k), circle(k, kArmRadius, 0.5, n), seg),
                 spec(m.hub_rings, 1, "HUB"));
      if (!is_flange) continue;
      const Block rim = mesh_block(
          mesh, curve_ring(circle(k, kArmRadius, 0.5, n), circle(k, kFlangeRadius, 0, n), seg),
          spec(m.flange_rings, flange_grading, "HUB"));
      mesh.add_to_surface("FLANGE_RIM", rim.side_faces(0, +1));
    }
  }
  merge_coincident_nodes(mesh);
  if (sector) cut_joint_sector(mesh, p);
  // The hub's face at z = 80 rests on the round part's shoulder without shared nodes (their
  // radial divisions differ): touching, not a contact surface (a pure torque loads it not).
  split_bodies(mesh, "HUB", "HUB_BORE", "SHAFT_POLYGON");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("SHAFT"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("HUB"));
  if (fam == "C3D28") {
    convert_contact_layers(mesh, registry, fam, {"HUB_BORE"});
    const std::string work = "__SHAFT_LAYER";
    mesh.surfaces[work] = mesh.surfaces.at("SHAFT_POLYGON");
    mesh.add_to_surface(work, mesh.surfaces.at(round_polygon));
    convert_elements(mesh, registry, fam, work);
    mesh.surfaces.erase(work);
  } else {
    convert_contact_layers(mesh, registry, fam, {"HUB_BORE", "SHAFT_POLYGON"});
  }
  mesh.surfaces.erase(round_polygon);

  const double E = p.positive("young"), nu = p.number("poisson");
  r.model = contact_model(
      mesh,
      "SPEC 4.5 P3G polygon joint (DIN 32711, D 60, n 3, e 2.25), " + fam +
          ": shaft 120 (round D65 to z 80, z 0 fixed), hub z 80-120 = arm D80 x 20 + flange "
          "D155 x 20 (flange at the " +
          std::string(flange_at_shoulder ? "shoulder" : "shaft's end") + "), frictionless bore; " +
          fmt_number(torque) + " N m on the flange rim" +
          (sector ? " (120 deg sector with cyclic symmetry, N = 3: a third of it)" : "") +
          ". Published: max displacement 0.41 mm at the flange rim, max "
          "Mises 141 MPa in the hub, the contact recedes",
      {{"SHAFT", "SHAFT", E, nu, {}}, {"HUB", "HUB", E, nu, {}}});
  add_surfaces(r.model, mesh, {"HUB_BORE", "SHAFT_POLYGON", "FLANGE_RIM"});
  add_contact(r.model, "POLYGON", "HUB_BORE", "SHAFT_POLYGON", std::nullopt);

  if (!sector) {
    add_joint_torque_step(r, registry, fam, torque, flange_z0 + 0.5 * hub_half);
    return r;
  }
  const SectorBoundary boundary = sector_boundary(mesh, kJointSectors, 1e-7 * mesh.size());
  add_cyclic_symmetry(r.model, boundary);
  add_joint_torque_step(r, registry, fam, torque, flange_z0 + 0.5 * hub_half, &boundary);
  return r;
}

}  // namespace

void add_p3g_joint_builder(std::vector<BuilderInfo>& all) {
  all.push_back(
      {"p3g-joint",
       "§4.5",
       "P3G polygon joint (DIN 32711, D 60, e 2.25): shaft + hub with flange, torque, full",
       {family_param("C3D21", kFamilies),
        {"around", "48", "elements around (multiple of 6; contact elements per row)"},
        {"arm-rows", "3", "axial elements of the hub's arm (z 80-100)"},
        {"flange-rows", "3", "axial elements of the flange (z 100-120)"},
        {"shaft-rows", "4", "axial elements of the round shaft part (z 0-80)"},
        {"shaft-rings", "1", "radial elements from the hexagonal core to the polygon"},
        {"round-rings", "1", "radial elements of the round part outside the polygon (to Ø65)"},
        {"hub-rings", "10", "radial elements of the hub from the bore to Ø80"},
        {"flange-rings", "28", "radial elements of the flange, Ø80 to Ø155 (graded)"},
        {"core", "25", "circumradius of the shaft's hexagonal core"},
        {"flange-at", "end",
         "where the flange sits on the hub (lost figure): end (z 100-120, the shaft's end) or "
         "shoulder (z 80-100, next to the round part)"},
        {"torque", "1000", "torque on the flange rim (N m)"},
        sector_param(kJointSectors),
        {"young", "200000", "Young's modulus E (MPa)"},
        {"poisson", "0.3", "Poisson's ratio"}},
       p3g_joint});
}

}  // namespace styk::mesher::detail
