#include "bolted_flange_mesh.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

#include "styk/mesher/block_mesh.hpp"

namespace styk::mesher::detail {
namespace {

using G = FlangeGeometry;
constexpr double kPi = 3.14159265358979323846;

// Block layout of the flange's plan (x-y). Around the half hole an O-grid of two rings, each
// kAroundHole elements around (9 deg each): ring 1 from the hole (rho 9) to the head's edge
// (rho 12 on the top face: the head-bearing annulus), ring 2 from there to a "box" whose sides
// are the arc r = kBoxOuter (6 segments), the radial line theta = kBoxAngle (10) and the arc
// r = R_a (4). Outside the box: the inner region r < R_a under which the gasket lies (4 + 4
// around), the tangential block and the outer ring up to the rim.
constexpr double kBoxAngle = 14.0 * kPi / 180;
constexpr double kBoxOuter = 79;
constexpr int kOuterSide = 6, kTangentialSide = 10, kInnerSide = 4;
static_assert(kOuterSide + kTangentialSide + kInnerSide == kAroundHole, "box sides");
static_assert(kInnerSide + 4 == kGasketAround, "gasket around");
// The plan changes with height (lambda = 0 at the flange's bottom face, 1 at its top): the gasket
// edge r = 54 must be a mesh line at the bottom, the head's edge rho = 12 at the top, and the two
// circles cross. So the box's inner side moves from r = 54 (bottom) to 48 (top) and ring 1's
// outer circle from rho 10 to 12.
constexpr double kBoxInnerTop = 48, kRing1Bottom = 10;

double box_inner(double lambda) {
  return G::kGasketOuter + lambda * (kBoxInnerTop - G::kGasketOuter);
}
double ring1_outer(double lambda) {
  return kRing1Bottom + lambda * (G::kHeadRadius - kRing1Bottom);
}

// A plan patch: (s, t) in [0, 1]^2 at height parameter lambda -> point of the plane.
using PlanMap = std::function<Vec3(double s, double t, double lambda)>;
using Radius = std::function<double(double lambda)>;

Vec3 polar_point(double r, double theta) { return {r * std::cos(theta), r * std::sin(theta), 0}; }

// Angle phi about the bolt axis of the O-grid's segment coordinate t in [0, 1]: 0 points away
// from the pipe axis (+x), pi towards it; counter-clockwise seen from +z.
double hole_angle(double t) { return kPi * t; }
Vec3 about_bolt(double rho, double phi) {
  return {G::kPitchRadius + rho * std::cos(phi), rho * std::sin(phi), 0};
}

PlanMap polar(Radius r0, Radius r1, double theta0, double theta1) {
  return [=](double s, double t, double lambda) {
    const double a = r0(lambda), b = r1(lambda);
    return polar_point(a + s * (b - a), theta0 + t * (theta1 - theta0));
  };
}

Radius constant(double value) {
  return [value](double) { return value; };
}

// A ring about the bolt axis, rho from rho0 to rho1, the half circle 0 .. pi.
PlanMap bolt_ring(Radius rho0, Radius rho1) {
  return [=](double s, double t, double lambda) {
    const double a = rho0(lambda), b = rho1(lambda);
    return about_bolt(a + s * (b - a), hole_angle(t));
  };
}

// The box side at segment coordinate u in [0, kAroundHole].
Vec3 box_side(double u, double lambda) {
  if (u <= kOuterSide) return polar_point(kBoxOuter, kBoxAngle * u / kOuterSide);
  const double inner = box_inner(lambda);
  if (u <= kOuterSide + kTangentialSide)
    return polar_point(kBoxOuter + (inner - kBoxOuter) * (u - kOuterSide) / kTangentialSide,
                       kBoxAngle);
  return polar_point(inner, kBoxAngle * (kAroundHole - u) / kInnerSide);
}

// Ring 2: straight lines from ring 1's outer circle to the box side.
PlanMap ring_to_box() {
  return [](double s, double t, double lambda) {
    const Vec3 c = about_bolt(ring1_outer(lambda), hole_angle(t));
    const Vec3 b = box_side(kAroundHole * t, lambda);
    return Vec3{c[0] + s * (b[0] - c[0]), c[1] + s * (b[1] - c[1]), 0};
  };
}

// The bolt's cross-section inside the shank: a core rectangle [-w, w] x [0, h] about the bolt
// axis (12 x 4 elements) whose corners point at phi = 36 and 144 deg, so its right, top and left
// sides face 4, 12 and 4 of the 20 segments of the circle; ring a joins it to the shank circle.
constexpr int kCoreAlong = 12, kCoreAcross = 4;
static_assert(kCoreAlong + 2 * kCoreAcross == kAroundHole, "core sides");
constexpr double kCoreCorner = 0.7 * G::kShankRadius;  // distance of the core's corners
const double kCoreW = kCoreCorner * std::cos(kPi * kCoreAcross / kAroundHole);
const double kCoreH = kCoreCorner * std::sin(kPi * kCoreAcross / kAroundHole);

PlanMap bolt_core() {
  return [](double s, double t, double) {
    return Vec3{G::kPitchRadius - kCoreW + 2 * kCoreW * s, kCoreH * t, 0};
  };
}

Vec3 core_side(double u) {
  if (u <= kCoreAcross) return {G::kPitchRadius + kCoreW, kCoreH * u / kCoreAcross, 0};
  if (u <= kCoreAcross + kCoreAlong)
    return {G::kPitchRadius + kCoreW - 2 * kCoreW * (u - kCoreAcross) / kCoreAlong, kCoreH, 0};
  return {G::kPitchRadius - kCoreW, kCoreH * (kAroundHole - u) / kCoreAcross, 0};
}

PlanMap core_to_shank() {
  return [](double s, double t, double) {
    const Vec3 c = core_side(kAroundHole * t);
    const Vec3 b = about_bolt(G::kShankRadius, hole_angle(t));
    return Vec3{c[0] + s * (b[0] - c[0]), c[1] + s * (b[1] - c[1]), 0};
  };
}

// A plan patch extruded from z0 to z1; lambda(z) morphs the plan.
BlockMap extruded(const PlanMap& plan, double z0, double z1,
                  const std::function<double(double)>& lambda) {
  return [=](const Vec3& xi) {
    const double z = z0 + (z1 - z0) * 0.5 * (xi[2] + 1);
    Vec3 p = plan(0.5 * (xi[0] + 1), 0.5 * (xi[1] + 1), lambda(z));
    p[2] = z;
    return p;
  };
}

}  // namespace

void mesh_bolted_flange(Mesh& mesh, const std::string& type, const FlangeLayout& m) {
  if (m.neck_rings < 1 || m.neck_rings >= m.gasket_rings)
    throw std::invalid_argument("bolted flange: need 1 <= neck rings < gasket rings");
  if (m.ring_layers < 2)
    throw std::invalid_argument(
        "bolted flange: the ring needs two layers (gasket and head contact layers differ)");
  if (m.gasket_layers < 1 || m.neck_layers < 1 || m.outer_rings < 1 || m.shank_layers < 1 ||
      m.head_layers < 1 || !(m.gasket_half > 0) || !(m.ring_thickness > 0))
    throw std::invalid_argument("bolted flange: counts must be >= 1, the gasket thicker than 0");
  const double z_bottom = m.gasket_half, z_top = z_bottom + m.ring_thickness;
  const double z_neck = z_top + G::kNeckHeight, z_head = z_top + G::kHeadHeight;
  const auto bottom_plan = [](double) { return 0.0; };
  const auto top_plan = [](double) { return 1.0; };
  const auto ring_plan = [=](double z) { return (z - z_bottom) / m.ring_thickness; };

  // Inner region: the neck wall's radial lines (r 25..30 at the top) and the rest up to the box;
  // at the bottom (and in the gasket) the gasket_rings elements are of equal width.
  const double wall_bottom =
      G::kBore + (G::kGasketOuter - G::kBore) * m.neck_rings / m.gasket_rings;
  const Radius wall = [=](double lambda) {
    return wall_bottom + lambda * (G::kNeckOuter - wall_bottom);
  };
  const Radius bore = constant(G::kBore), inner = box_inner;
  const int rest = m.gasket_rings - m.neck_rings;
  struct Part {
    PlanMap plan;
    int n_s, n_t;
  };
  const std::vector<Part> wall_parts = {
      {polar(bore, wall, 0, kBoxAngle), m.neck_rings, kInnerSide},
      {polar(bore, wall, kBoxAngle, G::kSector), m.neck_rings, kGasketAround - kInnerSide}};
  const std::vector<Part> rest_parts = {
      {polar(wall, inner, 0, kBoxAngle), rest, kInnerSide},
      {polar(wall, inner, kBoxAngle, G::kSector), rest, kGasketAround - kInnerSide}};
  const std::vector<Part> bolt_region = {
      {polar(inner, constant(kBoxOuter), kBoxAngle, G::kSector), kTangentialSide,
       kGasketAround - kInnerSide},
      {polar(constant(kBoxOuter), constant(G::kRim), 0, kBoxAngle), m.outer_rings, kOuterSide},
      {polar(constant(kBoxOuter), constant(G::kRim), kBoxAngle, G::kSector), m.outer_rings,
       kGasketAround - kInnerSide},
      {bolt_ring(constant(G::kHoleRadius), ring1_outer), 1, kAroundHole},
      {ring_to_box(), 1, kAroundHole}};

  auto add = [&](const std::vector<Part>& parts, double z0, double z1, int layers,
                 const std::function<double(double)>& lambda, const std::string& elset) {
    for (const Part& part : parts)
      mesh_block(mesh, extruded(part.plan, z0, z1, lambda),
                 {type, {part.n_s, part.n_t, layers}, {1, 1, 1}, elset});
  };
  add(wall_parts, 0, z_bottom, m.gasket_layers, bottom_plan, "GASKET");
  add(rest_parts, 0, z_bottom, m.gasket_layers, bottom_plan, "GASKET");
  add(wall_parts, z_bottom, z_top, m.ring_layers, ring_plan, "FLANGE");
  add(rest_parts, z_bottom, z_top, m.ring_layers, ring_plan, "FLANGE");
  add(bolt_region, z_bottom, z_top, m.ring_layers, ring_plan, "FLANGE");
  add(wall_parts, z_top, z_neck, m.neck_layers, top_plan, "FLANGE");

  const std::vector<Part> shank = {{bolt_core(), kCoreAlong, kCoreAcross},
                                   {core_to_shank(), 1, kAroundHole}};
  const std::vector<Part> head_rings = {
      {bolt_ring(constant(G::kShankRadius), constant(G::kHoleRadius)), 1, kAroundHole},
      {bolt_ring(constant(G::kHoleRadius), constant(G::kHeadRadius)), 1, kAroundHole}};
  add(shank, 0, z_top, m.shank_layers, top_plan, "BOLT");
  add(shank, z_top, z_head, m.head_layers, top_plan, "BOLT");
  add(head_rings, z_top, z_head, m.head_layers, top_plan, "BOLT");
}

}  // namespace styk::mesher::detail
