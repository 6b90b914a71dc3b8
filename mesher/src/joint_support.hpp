// Shared pieces of the shaft-hub joint builders (SPEC §4.4 spline, §4.5 P3G polygon; private to
// the mesher): the hexagonal core of a shaft section, polar blocks whose angular limits vary with
// the radius (exact straight flanks), blends from the hexagon to an outer profile, and the torque
// on a hub rim as tangential nodal forces.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sector_support.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher::detail {

// One axial stretch of a joint: z from z0 to z1 in `rows` elements (grading last / first).
struct AxialSegment {
  double z0 = 0.0;
  double z1 = 0.0;
  int rows = 1;
  double grading = 1.0;
};

// A point of the section plane (z ignored) as a function of a parameter in [0, 1].
using SectionCurve = std::function<Vec3(double u)>;

// Vertex i of the regular hexagon of circumradius `a` whose vertices sit at -30 + 60 i degrees,
// so side k (vertex k to k + 1) is centred on the angle 60 k degrees.
Vec3 hexagon_vertex(double a, int i);

// The hexagonal core of a shaft section: three rhombi of n x n elements; each hexagon side has n
// element edges of equal length.
void mesh_hexagon_core(Mesh& mesh, const std::string& type, double a, int n,
                       const AxialSegment& segment, const std::string& elset);

// Hexagon side k (vertex k -> k + 1) as a straight section curve.
SectionCurve hexagon_side(double a, int side);

// The block between two section curves: xi blends linearly from inner(u) to outer(u), eta is u,
// zeta runs along z. Two curves through points at the same angle give radial lines.
BlockMap curve_ring(const SectionCurve& inner, const SectionCurve& outer,
                    const AxialSegment& segment);

// A block in polar coordinates: xi is the radius rho0 -> rho1, eta the angle from lo(rho) to
// hi(rho) (radians, linear in between), zeta along z. Lines of constant xi are arcs; a limit
// asin(w / 2 rho) is a straight line at distance w / 2 from the centre (a spline flank).
BlockMap polar_block(double rho0, double rho1, const std::function<double(double)>& lo,
                     const std::function<double(double)>& hi, const AxialSegment& segment);

// The block bounded by four section curves (transfinite / Coons interpolation): xi runs from
// inner(u) to outer(u), eta is u, the sides u = 0 and u = 1 are left(s) and right(s) (s = 0 on
// inner, 1 on outer); zeta along z. Unlike curve_ring, the sides may be bent (a polyline with a
// corner at an element node), which the C3D28 spline-root transition needs.
BlockMap coons_block(const SectionCurve& inner, const SectionCurve& outer, const SectionCurve& left,
                     const SectionCurve& right, const AxialSegment& segment);

// The polyline through `points` with point i at parameter i / (points - 1), linear in between.
SectionCurve polyline(std::vector<Vec3> points);

// Tangential nodal forces of a uniform shear traction on the faces of a rim (a cylinder about the
// z axis): node i gets k A_i along e_theta (A_i = TElement::nodal_areas, summed over the faces),
// with k chosen so that the moment about z, sum (x F_y - y F_x) = sum k A_i r_i, equals `torque`
// to round-off.
std::vector<ConcentratedLoad> rim_torque_loads(const Model& model, const ElementRegistry& registry,
                                               const std::vector<FaceRef>& faces, double torque);

// The supports, loads and step shared by the joint decks: every node at z = 0 (the shaft's end)
// fixed (node set SHAFT_END); the nodes of mesh surface FLANGE_RIM as node set FLANGE_RIM; the
// rim node nearest the +x axis at height `hold_z` held axially (HUB_HOLD: frictionless contact
// cannot hold the hub along the axis; no force reaches that node under a torque); step TORQUE
// with `torque_nm` N m on the rim (rim_torque_loads, mm units) and the contact, rim U and
// SHAFT_END RF prints.
// A sector model (`sector` not null) carries torque_nm / N on its part of the rim, and its
// supports skip what the cyclic tie holds (fix_in_sector).
void add_joint_torque_step(BuildResult& result, const ElementRegistry& registry,
                           const std::string& family, double torque_nm, double hold_z,
                           const SectorBoundary* sector = nullptr);

// The --sector parameter of the joint builders ("no" or "yes") and what it means.
ParamDecl sector_param(int sectors);
bool sector_requested(const BuilderParams& params);
// Cuts the 120 deg sector -30 .. 90 deg (N = 3: the hexagonal core's rhombus edges and the
// pitch boundaries lie on those planes) out of a full joint mesh; a builder error otherwise.
void cut_joint_sector(Mesh& mesh, const BuilderParams& params);
constexpr int kJointSectors = 3;
constexpr double kJointSectorStart = -30.0;  // degrees

}  // namespace styk::mesher::detail
