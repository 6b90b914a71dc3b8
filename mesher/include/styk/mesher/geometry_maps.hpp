// Isoparametric geometry: a line is graded parameters on [0, 1], a patch maps (u, v) in [-1, 1]^2
// to space, a block maps (xi, eta, zeta) in [-1, 1]^3 to space. The mesher samples these maps at
// the (graded) node positions, so curved geometry (revolve, sweep, exact circles) is placed exactly
// at every node, mid-edge nodes included.
#pragma once

#include <functional>
#include <vector>

#include "styk/core/model.hpp"

namespace styk::mesher {

using PatchMap = std::function<Vec3(double u, double v)>;
using BlockMap = std::function<Vec3(const Vec3& xi)>;
using PathMap = std::function<Vec3(double t)>;  // t in [0, 1]

// n + 1 parameters 0 = t0 < ... < tn = 1 whose interval lengths grow geometrically so that
// last / first = ratio (ratio 4 = the 4:1 grading of SPEC §3.1.7; 1 = uniform; < 1 shrinks).
// Throws std::invalid_argument for n < 1 or ratio <= 0.
std::vector<double> graded_parameters(int n, double ratio = 1.0);

// Points of a straight line a -> b divided into n graded intervals.
std::vector<Vec3> mesh_line(const Vec3& a, const Vec3& b, int n, double ratio = 1.0);

// Patch maps from 4 (bilinear), 8 (serendipity) or 9 (Lagrange) control points in the
// quadrilateral numbering: corners counter-clockwise from (-1,-1), then mid-edges from the edge
// v = -1 on, then the centre. Throws std::invalid_argument for another count.
PatchMap quad_map(const std::vector<Vec3>& control);

// Block maps from 8 (trilinear), 20 (serendipity) or 27 (Lagrange) control points: nodes 1-20 in
// the C3D20 numbering; for 27 then the face centres S1..S6 (zeta-, zeta+, eta-, xi+, eta+, xi-)
// and the body centre.
BlockMap hex_map(const std::vector<Vec3>& control);

// A profile patch (u, v) revolved about the axis through `origin` along `axis`: zeta in [-1, 1]
// runs from angle0 to angle1 (radians, right-handed about the axis). The profile's own
// orientation decides the block's handedness; mesh_block() checks it.
BlockMap revolve(const PatchMap& profile, const Vec3& origin, const Vec3& axis, double angle0,
                 double angle1);

// A cross-section patch given in local coordinates (x, y of the returned point; z ignored) swept
// along a path: zeta runs from t = 0 to t = 1. The section plane is normal to the path tangent,
// with the local x axis the component of `up` normal to the tangent; `twist(t)` rotates the
// section about the tangent (radians; nullptr = none).
BlockMap sweep(const PatchMap& section, const PathMap& path, const Vec3& up,
               const std::function<double(double)>& twist = nullptr);

// A patch extruded along `direction` (zeta = -1 on the patch, +1 at patch + direction).
BlockMap extrude(const PatchMap& patch, const Vec3& direction);

// SPEC §4.5 (DIN 32711 P3G): the polygon profile point at angle v,
// x = (D/2 - e cos nv) cos v - n e sin nv sin v, y = (D/2 - e cos nv) sin v + n e sin nv cos v.
Vec3 p3g_point(double D, int n, double e, double v);

// SPEC §4.4: a straight-sided spline shaft outline (N splines, tip diameter D, root diameter d,
// spline width w; flanks parallel to the spline's centre line) as its polar radius at angle v.
double spline_radius(double D, double d, double w, int N, double v);

}  // namespace styk::mesher
