// Builder of the SPEC §4.4 spline joint: 6 straight-sided splines (tip Ø67, root Ø61.18, width
// 12.48), full model, with the SPEC stand-in lengths: shaft 120 (z = 0 fixed; round Ø61.18 up to
// z = 80, splined over the hub), hub z = 80..120 = arm Ø80 x 20 + flange Ø155 x 20 at the shaft's
// end. The hub's bore is the shaft profile grown by the radial clearance (0.1) at the tips and
// roots; the flanks coincide and carry the torque (1000 N m on the flange rim), frictionless.
//
// Section (per 60 degree pitch, the spline centred on its pitch): a hexagonal core (one hexagon
// side per pitch), one ring to the root circle, then polar blocks whose angular limits are the
// flank lines asin(w / 2 rho): the spline (a 0.1 strip where the hub's tooth tip leaves the
// flank free, then the contact rows), the hub's tooth in the groove (contact rows, then the strip
// beyond the spline tip), the hub ring to Ø80 and the flange to Ø155.
//
// C3D28 (docs/mesher.md, "Joints"): a C3D28 layer can only end on free faces or on C3D28 faces
// that carry the same GLL nodes. The concave corner at a spline's root has three elements around
// it (the strip, the element under the spline, the groove's), and the middle one has no free
// face; so the C3D28 shaft section puts two elements there (a transition: the strip element and
// the groove element meet along an edge slanting into the core), and its 0.1 root strip runs on to
// the shaft's end (a 0.1 ridge on the round part), because the transition elements straddle the
// root circle. The hub's corners (strip over the spline tip / ring) are closed by converting both
// sides of every sector line of the hub ring and flange, which run to the free surfaces at Ø80
// and Ø155.
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

constexpr int kSplines = 6;
constexpr double kTipRadius = 33.5, kRootRadius = 30.59, kWidth = 12.48;
constexpr double kShaftLength = 120, kHubStart = 80, kFlangeStart = 100;
constexpr double kArmRadius = 40, kFlangeRadius = 77.5;
constexpr double kPitch = 2 * kPi / kSplines;
// Working surface: both sides of the hub's sector lines (C3D28 only).
const char* const kHubSectors = "__HUB_SECTORS";

struct SplineMesh {
  int tooth = 4;           // elements across a spline
  int groove = 6;          // elements across a groove (even: half on each hexagon side)
  int flank_rows = 2;      // radial contact rows along a flank
  int core_rings = 1;      // hexagon to root circle
  int hub_rings = 2;       // hub tooth root to Ø80
  int flange_rings = 7;    // Ø80 to Ø155
  int arm_rows = 4;        // axial, z 80..100
  int flange_rows = 4;     // axial, z 100..120
  int shaft_rows = 14;     // axial, z 0..80
  double core = 26;        // hexagon circumradius
  double clearance = 0.1;  // radial, at tips and roots
};

// Half angle of the flank lines (distance w / 2 from the spline's centre line) at radius rho.
double flank(double rho) { return std::asin(0.5 * kWidth / rho); }

Vec3 polar(double r, double angle) { return {r * std::cos(angle), r * std::sin(angle), 0.0}; }

// The outer edge of the core ring of pitch k on the root circle: half a groove, the spline's
// root, half a groove; piecewise linear in angle so that its nodes meet the spline's.
SectionCurve root_arc(int k, const SplineMesh& m) {
  const double b = 0.5 * m.groove / (m.tooth + m.groove), phi = flank(kRootRadius);
  const double centre = k * kPitch, half = 0.5 * kPitch;
  return [=](double u) {
    double a;
    if (u <= b)
      a = -half + (u / b) * (half - phi);
    else if (u >= 1 - b)
      a = phi + ((u - (1 - b)) / b) * (half - phi);
    else
      a = -phi + (u - b) / (1 - 2 * b) * 2 * phi;
    return polar(kRootRadius, centre + a);
  };
}

// The polar arc of radius r from angle a0 to a1, linear in angle.
SectionCurve arc(double r, double a0, double a1) {
  return [=](double u) { return polar(r, a0 + u * (a1 - a0)); };
}

SectionCurve line(const Vec3& a, const Vec3& b) { return polyline({a, b}); }

// The C3D28 shaft section of pitch k from hexagon side k (around - 2 elements) to the root circle
// and the 0.1 strip of spline k (to root + clearance), in every axial segment. The strip's first
// and last elements reach down along a slanted edge to the points Y, Y' under the spline, so that
// the concave corner A (root circle x flank) has two elements: the strip element (free flank face)
// and the groove element (free groove bottom), and the C3D28 layer turns from the flank into the
// groove bottom. Blocks: the strip (1 x tooth, bottom A -> Y -> arc -> Y' -> A'), the groove
// rings left and right (core-rings + 1 radial x groove / 2, one side bent at Y), and the ring
// under the spline (core-rings x tooth - 2, between the hexagon and the arc through Y, Y').
void mesh_shaft_c3d28(Mesh& mesh, const std::string& type, const SplineMesh& m, int k,
                      const AxialSegment& seg) {
  const double centre = k * kPitch, half = 0.5 * kPitch, c = m.clearance;
  const double root = kRootRadius, top = kRootRadius + c;
  const int q = m.core_rings + 1, half_groove = m.groove / 2, inner = m.tooth - 2;
  const SectionCurve side = hexagon_side(m.core, k);
  const double u_d = static_cast<double>(half_groove) / (m.tooth + m.groove - 2);
  const Vec3 V0 = side(0), D = side(u_d), D1 = side(1 - u_d), V1 = side(1);
  const double a = centre - flank(root), a1 = centre + flank(root);
  const double step = 2 * flank(top) / m.tooth;
  const double y = centre - flank(top) + step, y1 = centre + flank(top) - step;
  // Depth of Y below the root circle: the strip element tapers from its 0.1 flank to its side
  // B2 Y, and the groove element's angle at A opens towards 180 degrees as Y rises. Three
  // clearances balance the two (min det J ratio of the coarse test mesh 0.25 at the strip element,
  // 0.09 at a depth of 1, 0.02 with a 45 degree diagonal). At most half-way to the hexagon.
  const double hexagon_at_y = m.core * std::cos(kPi / 6) / std::cos(y - centre);
  const double depth = std::min(3 * c, 0.5 * (root - hexagon_at_y));
  const Vec3 A = polar(root, a), A1 = polar(root, a1);
  const Vec3 Y = polar(root - depth, y), Y1 = polar(root - depth, y1);
  const auto bent_side = [q](const Vec3& from, const Vec3& bend, const Vec3& to) {
    std::vector<Vec3> points;
    for (int i = 0; i < q; ++i) {
      const double t = static_cast<double>(i) / (q - 1);
      points.push_back({from[0] + t * (bend[0] - from[0]), from[1] + t * (bend[1] - from[1]), 0});
    }
    points.push_back(to);
    return polyline(points);
  };
  const auto spec = [&](int radial, int across) {
    return BlockSpec{type, {radial, across, seg.rows}, {1, 1, seg.grading}, "SHAFT"};
  };
  mesh_block(mesh,
             coons_block([=](double u) { return side(u * u_d); }, arc(root, centre - half, a),
                         line(V0, polar(root, centre - half)), bent_side(D, Y, A), seg),
             spec(q, half_groove));
  mesh_block(
      mesh,
      coons_block([=](double u) { return side(1 - u_d + u * u_d); }, arc(root, a1, centre + half),
                  bent_side(D1, Y1, A1), line(V1, polar(root, centre + half)), seg),
      spec(q, half_groove));
  if (inner > 0)
    mesh_block(mesh,
               curve_ring([=](double u) { return side(u_d + u * (1 - 2 * u_d)); },
                          arc(root - depth, y, y1), seg),
               spec(q - 1, inner));
  const double first = 1.0 / m.tooth;
  const SectionCurve bottom = [=](double u) {
    if (u <= first) return line(A, Y)(u / first);
    if (u >= 1 - first) return line(Y1, A1)((u - (1 - first)) / first);
    return arc(root - depth, y, y1)((u - first) / (1 - 2 * first));
  };
  mesh_block(mesh, curve_ring(bottom, arc(top, centre - flank(top), centre + flank(top)), seg),
             spec(1, m.tooth));
}

void mesh_pitch(Mesh& mesh, const std::string& type, const SplineMesh& m, int k,
                const AxialSegment& seg, bool flange, bool c3d28) {
  const double centre = k * kPitch, c = m.clearance;
  const double tip = kTipRadius, root = kRootRadius;
  const auto spline_lo = [centre](double rho) { return centre - flank(rho); };
  const auto spline_hi = [centre](double rho) { return centre + flank(rho); };
  const auto groove_lo = spline_hi;
  const auto groove_hi = [centre](double rho) { return centre + kPitch - flank(rho); };
  const auto block = [&](const BlockMap& map, int radial, int across, const char* elset) {
    return mesh_block(mesh, map, {type, {radial, across, seg.rows}, {1, 1, 1}, elset});
  };
  // The spline: the strip facing the gap under the hub's tooth tip (C3D28: mesh_shaft_c3d28),
  // then the contact rows.
  if (!c3d28) block(polar_block(root, root + c, spline_lo, spline_hi, seg), 1, m.tooth, "SHAFT");
  block(polar_block(root + c, tip, spline_lo, spline_hi, seg), m.flank_rows, m.tooth, "SHAFT");
  // The hub's tooth in the groove: contact rows, then the strip beyond the spline tip.
  block(polar_block(root + c, tip, groove_lo, groove_hi, seg), m.flank_rows, m.groove, "HUB");
  block(polar_block(tip, tip + c, groove_lo, groove_hi, seg), 1, m.groove, "HUB");
  // Hub ring: the sector lines turn from the flanks to equal element angles at Ø80.
  const double inner = tip + c, even = kPitch * 0.5 * m.tooth / (m.tooth + m.groove);
  const auto sector = [=](double rho) {
    if (rho >= kArmRadius) return even;
    return flank(inner) + (rho - inner) / (kArmRadius - inner) * (even - flank(inner));
  };
  const auto ring_lo = [=](double rho) { return centre - sector(rho); };
  const auto ring_hi = [=](double rho) { return centre + sector(rho); };
  const auto ring_end = [=](double rho) { return centre + kPitch - sector(rho); };
  // Both sides of every sector line (C3D28: the hub's layer closes through them).
  const auto sectors = [&](const Block& over_spline, const Block& over_groove) {
    if (!c3d28) return;
    for (const Block* b : {&over_spline, &over_groove})
      for (int end : {-1, +1}) mesh.add_to_surface(kHubSectors, b->side_faces(1, end));
  };
  const Block over_spline =
      block(polar_block(inner, kArmRadius, ring_lo, ring_hi, seg), m.hub_rings, m.tooth, "HUB");
  const Block over_groove =
      block(polar_block(inner, kArmRadius, ring_hi, ring_end, seg), m.hub_rings, m.groove, "HUB");
  sectors(over_spline, over_groove);
  if (!flange) return;
  const Block a = block(polar_block(kArmRadius, kFlangeRadius, ring_lo, ring_hi, seg),
                        m.flange_rings, m.tooth, "HUB");
  const Block b = block(polar_block(kArmRadius, kFlangeRadius, ring_hi, ring_end, seg),
                        m.flange_rings, m.groove, "HUB");
  sectors(a, b);
  mesh.add_to_surface("FLANGE_RIM", a.side_faces(0, +1));
  mesh.add_to_surface("FLANGE_RIM", b.side_faces(0, +1));
}

BuildResult spline_joint(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kFamilies);
  const bool c3d28 = fam == "C3D28";
  SplineMesh m;
  m.tooth = p.count("tooth", 2);
  m.groove = p.count("groove", 2);
  if (m.groove % 2 != 0) p.fail("--groove must be even (half a groove on each side of a pitch)");
  m.flank_rows = p.count("flank-rows");
  m.core_rings = p.count("core-rings");
  m.hub_rings = p.count("hub-rings");
  m.flange_rings = p.count("flange-rings");
  m.arm_rows = p.count("arm-rows");
  m.flange_rows = p.count("flange-rows");
  m.shaft_rows = p.count("shaft-rows");
  m.core = p.positive("core");
  if (m.core >= kRootRadius - 2) p.fail("--core must stay inside the root circle (< 28.5)");
  m.clearance = p.positive("clearance");
  if (m.clearance >= kTipRadius - kRootRadius - 0.5)
    p.fail("--clearance must leave a flank to touch (< 2.4)");
  const double torque = p.number("torque");
  const bool sector = sector_requested(p);

  BuildResult r;
  Mesh& mesh = r.mesh;
  const std::string type = base_type(registry, fam);
  const int around = m.tooth + m.groove;
  // The shaft outside the hub continues the hub's axial element length towards the fixed end.
  const double row = (kFlangeStart - kHubStart) / m.arm_rows;
  const AxialSegment shaft_seg{0, kHubStart, m.shaft_rows,
                               1.0 / continuing_grading(row, kHubStart, m.shaft_rows)};
  const AxialSegment arm{kHubStart, kFlangeStart, m.arm_rows, 1.0};
  const AxialSegment flange{kFlangeStart, kShaftLength, m.flange_rows, 1.0};
  for (const AxialSegment& seg : {shaft_seg, arm, flange}) {
    mesh_hexagon_core(mesh, type, m.core, c3d28 ? around - 2 : around, seg, "SHAFT");
    for (int k = 0; k < kSplines; ++k) {
      if (c3d28)
        mesh_shaft_c3d28(mesh, type, m, k, seg);
      else
        mesh_block(mesh, curve_ring(hexagon_side(m.core, k), root_arc(k, m), seg),
                   {type, {m.core_rings, around, seg.rows}, {1, 1, seg.grading}, "SHAFT"});
      if (seg.z0 >= kHubStart) mesh_pitch(mesh, type, m, k, seg, seg.z0 >= kFlangeStart, c3d28);
    }
  }
  merge_coincident_nodes(mesh);
  if (sector) cut_joint_sector(mesh, p);
  split_bodies(mesh, "HUB", "HUB_FLANKS", "SHAFT_FLANKS");
  mesh.add_to_element_set("EALL", mesh.element_sets.at("SHAFT"));
  mesh.add_to_element_set("EALL", mesh.element_sets.at("HUB"));
  if (c3d28) {
    // The shaft's layer closes by itself (flanks, root strips, groove bottoms); the hub's through
    // the sector lines, converted on both sides with the shared face as S1.
    convert_contact_layers(mesh, registry, fam, {"SHAFT_FLANKS"});
    const std::string work = "__HUB_LAYER";
    mesh.surfaces[work] = mesh.surfaces.at("HUB_FLANKS");
    mesh.add_to_surface(work, mesh.surfaces.at(kHubSectors));
    mesh.surfaces.erase(kHubSectors);
    convert_elements(mesh, registry, fam, work);
    mesh.surfaces.erase(work);
  } else {
    convert_contact_layers(mesh, registry, fam, {"HUB_FLANKS", "SHAFT_FLANKS"});
  }

  const double E = p.positive("young"), nu = p.number("poisson");
  r.model = contact_model(
      mesh,
      "SPEC 4.4 spline joint, " + fam +
          ": 6 splines D67/d61.18, w 12.48; shaft 120 (round D61.18 to z 80, z 0 fixed), hub "
          "z 80-120 = arm D80 x 20 + flange D155 x 20, radial clearance " +
          fmt_number(m.clearance) + " at tips and roots, frictionless flanks; " +
          fmt_number(torque) + " N m on the flange rim" +
          (sector ? " (120 deg sector with cyclic symmetry, N = 3: a third of it)" : "") +
          ". Published: max Mises about 35 MPa, flank pressure 0-166 MPa",
      {{"SHAFT", "SHAFT", E, nu, {}}, {"HUB", "HUB", E, nu, {}}});
  add_surfaces(r.model, mesh, {"HUB_FLANKS", "SHAFT_FLANKS", "FLANGE_RIM"});
  add_contact(r.model, "FLANKS", "HUB_FLANKS", "SHAFT_FLANKS", std::nullopt);

  if (!sector) {
    add_joint_torque_step(r, registry, fam, torque, 0.5 * (kFlangeStart + kShaftLength));
    return r;
  }
  const SectorBoundary boundary = sector_boundary(mesh, kJointSectors, 1e-7 * mesh.size());
  add_cyclic_symmetry(r.model, boundary);
  add_joint_torque_step(r, registry, fam, torque, 0.5 * (kFlangeStart + kShaftLength), &boundary);
  return r;
}

}  // namespace

void add_spline_joint_builder(std::vector<BuilderInfo>& all) {
  all.push_back(
      {"spline-joint",
       "§4.4",
       "Spline joint: 6 splines D67/d61.18, shaft + hub with flange, torque on the rim, full",
       {family_param("C3D21", kFamilies),
        {"tooth", "4", "elements across a spline"},
        {"groove", "6", "elements across a groove (even)"},
        {"flank-rows", "2", "radial elements along a flank's contact band"},
        {"arm-rows", "4", "axial elements of the hub's arm (z 80-100)"},
        {"flange-rows", "4", "axial elements of the flange (z 100-120)"},
        {"shaft-rows", "14", "axial elements of the shaft outside the hub"},
        {"core-rings", "1", "radial elements from the hexagonal core to the root circle"},
        {"hub-rings", "2", "radial elements from the hub's groove bottom to Ø80"},
        {"flange-rings", "7", "radial elements of the flange, Ø80 to Ø155"},
        {"core", "26", "circumradius of the shaft's hexagonal core"},
        {"clearance", "0.1", "radial clearance at the spline tips and roots"},
        {"torque", "1000", "torque on the flange rim (N m)"},
        sector_param(kJointSectors),
        {"young", "200000", "Young's modulus E (MPa)"},
        {"poisson", "0.3", "Poisson's ratio"}},
       spline_joint});
}

}  // namespace styk::mesher::detail
