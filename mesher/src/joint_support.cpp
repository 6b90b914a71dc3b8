#include "joint_support.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <Eigen/Core>

#include "builder_support.hpp"
#include "contact_support.hpp"
#include "styk/mesher/block_mesh.hpp"

namespace styk::mesher::detail {
namespace {

double axial(const AxialSegment& s, double zeta) { return s.z0 + (s.z1 - s.z0) * 0.5 * (zeta + 1); }

}  // namespace

Vec3 hexagon_vertex(double a, int i) {
  const double angle = (-30.0 + 60.0 * i) * kPi / 180.0;
  return {a * std::cos(angle), a * std::sin(angle), 0.0};
}

void mesh_hexagon_core(Mesh& mesh, const std::string& type, double a, int n,
                       const AxialSegment& segment, const std::string& elset) {
  // Rhombus j spans O, V(2j), V(2j + 1) = V(2j) + V(2j + 2), V(2j + 2): the parallelogram
  // s V(2j) + t V(2j + 2), right-handed because V(2j + 2) lies 120 degrees further on.
  for (int j = 0; j < 3; ++j) {
    const Vec3 A = hexagon_vertex(a, 2 * j), B = hexagon_vertex(a, 2 * j + 2);
    const BlockMap map = [A, B, segment](const Vec3& xi) {
      const double s = 0.5 * (xi[0] + 1), t = 0.5 * (xi[1] + 1);
      return Vec3{s * A[0] + t * B[0], s * A[1] + t * B[1], axial(segment, xi[2])};
    };
    mesh_block(mesh, map, {type, {n, n, segment.rows}, {1, 1, segment.grading}, elset});
  }
}

SectionCurve hexagon_side(double a, int side) {
  const Vec3 v0 = hexagon_vertex(a, side), v1 = hexagon_vertex(a, side + 1);
  return [v0, v1](double u) {
    return Vec3{v0[0] + u * (v1[0] - v0[0]), v0[1] + u * (v1[1] - v0[1]), 0.0};
  };
}

BlockMap curve_ring(const SectionCurve& inner, const SectionCurve& outer,
                    const AxialSegment& segment) {
  return [inner, outer, segment](const Vec3& xi) {
    const double s = 0.5 * (xi[0] + 1), u = 0.5 * (xi[1] + 1);
    const Vec3 a = inner(u), b = outer(u);
    return Vec3{a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), axial(segment, xi[2])};
  };
}

BlockMap polar_block(double rho0, double rho1, const std::function<double(double)>& lo,
                     const std::function<double(double)>& hi, const AxialSegment& segment) {
  return [=](const Vec3& xi) {
    const double rho = rho0 + (rho1 - rho0) * 0.5 * (xi[0] + 1);
    const double a0 = lo(rho), a1 = hi(rho);
    const double angle = a0 + (a1 - a0) * 0.5 * (xi[1] + 1);
    return Vec3{rho * std::cos(angle), rho * std::sin(angle), axial(segment, xi[2])};
  };
}

BlockMap coons_block(const SectionCurve& inner, const SectionCurve& outer, const SectionCurve& left,
                     const SectionCurve& right, const AxialSegment& segment) {
  const Vec3 i0 = inner(0), i1 = inner(1), o0 = outer(0), o1 = outer(1);
  return [=](const Vec3& xi) {
    const double s = 0.5 * (xi[0] + 1), u = 0.5 * (xi[1] + 1);
    const Vec3 a = inner(u), b = outer(u), l = left(s), r = right(s);
    Vec3 p{0, 0, axial(segment, xi[2])};
    for (int d = 0; d < 2; ++d)
      p[d] =
          (1 - s) * a[d] + s * b[d] + (1 - u) * l[d] + u * r[d] -
          ((1 - s) * (1 - u) * i0[d] + (1 - s) * u * i1[d] + s * (1 - u) * o0[d] + s * u * o1[d]);
    return p;
  };
}

SectionCurve polyline(std::vector<Vec3> points) {
  return [points = std::move(points)](double u) {
    const int n = static_cast<int>(points.size()) - 1;
    const int i = std::min(n - 1, std::max(0, static_cast<int>(std::floor(u * n))));
    const double t = u * n - i;
    const Vec3 &a = points[i], &b = points[i + 1];
    return Vec3{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), 0.0};
  };
}

std::vector<ConcentratedLoad> rim_torque_loads(const Model& model, const ElementRegistry& registry,
                                               const std::vector<FaceRef>& faces, double torque) {
  // C3D20 corners carry negative areas, and so negative shares of the torque.
  const std::map<int, double> area = equivalent_nodal_areas(model, registry, faces).area;
  double lever = 0.0;  // sum A_i r_i
  for (const auto& [node, a] : area)
    lever += a * std::hypot(model.coords[node][0], model.coords[node][1]);
  const double k = torque / lever;
  std::vector<ConcentratedLoad> loads;
  for (const auto& [node, a] : area) {
    const Vec3& x = model.coords[node];
    const double r = std::hypot(x[0], x[1]);
    // F = k A (-y, x) / r: moment x F_y - y F_x = k A r.
    const double fx = -k * a * x[1] / r, fy = k * a * x[0] / r;
    if (fx != 0.0) loads.push_back({node, 1, fx, {}});
    if (fy != 0.0) loads.push_back({node, 2, fy, {}});
  }
  return loads;
}

ParamDecl sector_param(int sectors) {
  return {"sector", "no",
          "yes: a " + std::to_string(360 / sectors) +
              " deg sector (N = " + std::to_string(sectors) +
              ") with *TIE, CYCLIC SYMMETRY instead of the full model (same mesh density)"};
}

bool sector_requested(const BuilderParams& params) {
  return params.choice("sector", {"no", "yes"}) == "yes";
}

void cut_joint_sector(Mesh& mesh, const BuilderParams& params) {
  try {
    cut_sector(mesh, kJointSectors, kJointSectorStart * kPi / 180.0);
  } catch (const std::invalid_argument& e) {
    params.fail(std::string("--sector yes: ") + e.what());
  }
}

void add_joint_torque_step(BuildResult& result, const ElementRegistry& registry,
                           const std::string& family, double torque_nm, double hold_z,
                           const SectorBoundary* sector) {
  const Mesh& mesh = result.mesh;
  Model& model = result.model;
  const double tol = 1e-7 * mesh.size();
  const auto end = nodes_where(mesh, [&](const Vec3& x) { return x[2] < tol; });
  add_node_set(model, "SHAFT_END", end);
  if (sector != nullptr) {
    fix_in_sector(model, *sector, end, {1, 2, 3});
    torque_nm /= sector->sectors;
  } else {
    fix(model, end, {1, 2, 3});
  }
  const std::vector<int> rim = mesh.surface_nodes("FLANGE_RIM");
  add_node_set(model, "FLANGE_RIM", rim);
  const auto off = [&](int node) {
    const Vec3& x = mesh.nodes[node];
    return std::abs(x[1]) + std::abs(x[2] - hold_z) + (x[0] > 0 ? 0.0 : 2 * mesh.size());
  };
  int hold = rim.at(0);
  for (int node : rim)
    if (off(node) < off(hold)) hold = node;
  add_node_set(model, "HUB_HOLD", {hold});
  fix(model, {hold}, {3});

  Step step = static_step();
  step.name = "TORQUE";
  step.cloads = rim_torque_loads(model, registry, mesh.surfaces.at("FLANGE_RIM"), torque_nm * 1e3);
  step.outputs = {contact_print(family),
                  print_request(OutputRequest::Kind::NodePrint, "FLANGE_RIM", {"U"}),
                  print_request(OutputRequest::Kind::NodePrint, "SHAFT_END", {"RF"}, true)};
  model.steps.push_back(step);
}

}  // namespace styk::mesher::detail
