#include "session/revolve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "session/brick_types.hpp"
#include "session/input_checks.hpp"
#include "styk/core/vec3.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/hex_topology.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::gui {
namespace {

constexpr double kPi = 3.14159265358979323846;
const std::array<std::string, 6> kSides{"INNER", "OUTER", "BOTTOM", "TOP", "CUT0", "CUT1"};

using V3 = Eigen::Vector3d;

bool solid(const RevolveInput& in) { return in.r_inner == 0.0; }
bool closed(const RevolveInput& in) { return std::abs(in.angle - 360.0) < 1e-9; }
int quarters(const RevolveInput& in) { return static_cast<int>(std::lround(in.angle / 90.0)); }

// The cylindrical frame of the revolve: axis a, angle 0 along e1, 90 degrees along e2 = a x e1.
struct Frame {
  V3 origin, a, e1, e2;
  Vec3 point(double r, double theta, double z) const {
    return to_vec3(origin + z * a + r * std::cos(theta) * e1 + r * std::sin(theta) * e2);
  }
  // (r, theta in [0, 2 pi), z) of x
  Vec3 polar(const Vec3& x) const {
    const V3 d = as_eigen(x) - origin;
    const double z = d.dot(a), u = d.dot(e1), v = d.dot(e2);
    double theta = std::atan2(v, u);
    if (theta < 0) theta += 2 * kPi;
    return {std::hypot(u, v), theta, z};
  }
};

Frame frame_of(const RevolveInput& in) {
  Frame f;
  f.origin = as_eigen(in.origin);
  f.a = as_eigen(in.axis).normalized();
  f.e1 = as_eigen(revolve_reference_direction(in.axis));
  f.e2 = f.a.cross(f.e1);
  return f;
}

// The blocks of the solid: per 90 degrees a core square [0, c]^2 (c = r_outer / 2) and two ring
// blocks from the core's edges to the circle (0..45 and 45..90 degrees); xi, eta span the
// section (right-handed with the axis), zeta runs along the axis.
std::vector<mesher::Block> mesh_solid(mesher::Mesh& mesh, const RevolveInput& in, const Frame& f,
                                      const mesher::BlockSpec& base) {
  const int n = in.around / (2 * quarters(in));
  const double R = in.r_outer, c = 0.5 * R, q = 0.25 * kPi;
  std::vector<mesher::Block> blocks;
  for (int k = 0; k < quarters(in); ++k) {
    const double phi = 0.5 * kPi * k;
    const V3 u = std::cos(phi) * f.e1 + std::sin(phi) * f.e2;
    const V3 v = f.a.cross(u);
    const auto at = [&](double x, double y, double zeta) {
      const double z = in.z0 + (in.z1 - in.z0) * 0.5 * (zeta + 1);
      return to_vec3(f.origin + z * f.a + x * u + y * v);
    };
    const auto blend = [](double x0, double y0, double x1, double y1, double s) {
      return std::array<double, 2>{x0 + s * (x1 - x0), y0 + s * (y1 - y0)};
    };
    const mesher::BlockMap core = [=](const Vec3& xi) {
      return at(c * 0.5 * (xi[0] + 1), c * 0.5 * (xi[1] + 1), xi[2]);
    };
    const mesher::BlockMap ring1 = [=](const Vec3& xi) {
      const double s = 0.5 * (xi[0] + 1), t = 0.5 * (xi[1] + 1);
      const auto p = blend(c, c * t, R * std::cos(q * t), R * std::sin(q * t), s);
      return at(p[0], p[1], xi[2]);
    };
    const mesher::BlockMap ring2 = [=](const Vec3& xi) {
      const double s = 0.5 * (xi[0] + 1), t = 0.5 * (xi[1] + 1);
      const auto p = blend(c * (1 - t), c, R * std::cos(q * (1 + t)), R * std::sin(q * (1 + t)), s);
      return at(p[0], p[1], xi[2]);
    };
    mesher::BlockSpec spec = base;
    spec.divisions = {n, n, in.axial};
    spec.grading = {1.0, 1.0, in.axial_grading};
    blocks.push_back(mesher::mesh_block(mesh, core, spec));
    spec.divisions = {in.radial, n, in.axial};
    spec.grading = {in.radial_grading, 1.0, in.axial_grading};
    blocks.push_back(mesher::mesh_block(mesh, ring1, spec));
    blocks.push_back(mesher::mesh_block(mesh, ring2, spec));
  }
  return blocks;
}

// The hollow part: one block of the profile revolved (xi along the axis, eta radial, zeta around).
mesher::Block mesh_ring(mesher::Mesh& mesh, const RevolveInput& in, const Frame& f,
                        const mesher::BlockSpec& base) {
  const mesher::PatchMap profile =
      mesher::quad_map({f.point(in.r_inner, 0, in.z0), f.point(in.r_inner, 0, in.z1),
                        f.point(in.r_outer, 0, in.z1), f.point(in.r_outer, 0, in.z0)});
  mesher::BlockSpec spec = base;
  spec.divisions = {in.axial, in.radial, in.around};
  spec.grading = {in.axial_grading, in.radial_grading, 1.0};
  return mesher::mesh_block(
      mesh, mesher::revolve(profile, to_vec3(f.origin), to_vec3(f.a), 0.0, in.angle * kPi / 180),
      spec);
}

// Which side (index into kSides) the face lies on, -1 for none: every corner on it.
int side_of(const mesher::Mesh& mesh, const mesher::FaceRef& face, const RevolveInput& in,
            const Frame& f, double tol) {
  const mesher::MeshElement& el = mesh.elements[face.element];
  std::array<Vec3, 4> p{};
  const std::vector<int> corners = mesher::face_corner_nodes(face.face);
  for (int i = 0; i < 4; ++i) p[i] = f.polar(mesh.nodes[el.nodes[corners[i]]]);
  const auto all = [&](auto on) { return std::all_of(p.begin(), p.end(), on); };
  if (!solid(in) && all([&](const Vec3& x) { return std::abs(x[0] - in.r_inner) < tol; })) return 0;
  if (all([&](const Vec3& x) { return std::abs(x[0] - in.r_outer) < tol; })) return 1;
  if (all([&](const Vec3& x) { return std::abs(x[2] - in.z0) < tol; })) return 2;
  if (all([&](const Vec3& x) { return std::abs(x[2] - in.z1) < tol; })) return 3;
  if (closed(in)) return -1;
  // A corner on the axis lies on both cut planes; the others decide (arc length within tol).
  const double end = in.angle * kPi / 180;
  const auto on_angle = [&](double angle) {
    return all([&](const Vec3& x) {
      double d = std::abs(x[1] - angle);
      d = std::min(d, 2 * kPi - d);
      return x[0] < tol || x[0] * d < tol;
    });
  };
  if (on_angle(0.0)) return 4;
  if (on_angle(end)) return 5;
  return -1;
}

}  // namespace

Vec3 revolve_reference_direction(const Vec3& axis) {
  const V3 a = as_eigen(axis).normalized();
  // Along a global axis: the next one (z -> x, x -> y, y -> z); otherwise the global axis least
  // aligned with a, made perpendicular to it.
  int pick = 0;
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(a[k]) - 1.0) < 1e-12) pick = (k + 1) % 3;
  if (std::abs(std::abs(a[0]) - 1.0) >= 1e-12 && std::abs(std::abs(a[1]) - 1.0) >= 1e-12 &&
      std::abs(std::abs(a[2]) - 1.0) >= 1e-12)
    for (int k = 1; k < 3; ++k)
      if (std::abs(a[k]) < std::abs(a[pick])) pick = k;
  const V3 g = V3::Unit(pick);
  return to_vec3((g - g.dot(a) * a).normalized());
}

void check_revolve(const RevolveInput& in, const Model& model, const ElementRegistry& registry) {
  check_name(in.name, "the revolve's element set");
  const std::string name = to_upper(in.name);
  if (model.find_elset(name) || model.find_nset(name))
    refuse("a set " + name + " exists already; choose another name");
  for (const std::string& side : kSides) check_set_names_free(model, name + "_" + side);
  for (int k = 0; k < 3; ++k) {
    check_finite(in.origin[k], "axis point");
    check_finite(in.axis[k], "axis direction");
  }
  if (as_eigen(in.axis).squaredNorm() < 1e-24) refuse("the axis direction must not be zero");
  for (double v :
       {in.r_inner, in.r_outer, in.z0, in.z1, in.angle, in.radial_grading, in.axial_grading})
    check_finite(v, "every number");
  if (in.r_inner < 0) refuse("inner radius must be >= 0 (0: a solid)");
  if (!(in.r_outer > in.r_inner)) refuse("outer radius must be above the inner radius");
  if (!(in.z1 > in.z0)) refuse("z to must be above z from");
  if (!(in.angle > 0 && in.angle <= 360 + 1e-9)) refuse("angle must lie in (0, 360] degrees");
  const std::pair<int, const char*> divisions[] = {
      {in.radial, "radial"}, {in.axial, "axial"}, {in.around, "around"}};
  for (const auto& [d, what] : divisions) {
    if (d < 1)
      refuse(std::string(what) + " divisions must be at least 1, not " + std::to_string(d));
    if (d > 1000) refuse(std::string(what) + " divisions must be at most 1000");
  }
  if (!(in.radial_grading > 0) || !(in.axial_grading > 0))
    refuse("grading must be > 0 (last / first element length; 1 = uniform)");
  if (solid(in)) {
    const double q = in.angle / 90.0;
    if (std::abs(q - std::round(q)) > 1e-9)
      refuse(
          "a solid (inner radius 0) is meshed as an O-grid and needs an angle of 90, 180, "
          "270 or 360 degrees");
    if (in.around % (2 * quarters(in)) != 0)
      refuse("a solid (inner radius 0) needs an even number of divisions around per 90 degrees: " +
             std::to_string(in.around) + " around " + std::to_string(quarters(in) * 90) +
             " degrees is not a multiple of " + std::to_string(2 * quarters(in)));
  }
  // Elements: a ring radial x axial x around; a solid per 90 degrees n x n + 2 radial x n rows.
  const long long n = solid(in) ? in.around / (2 * std::max(1, quarters(in))) : 0;
  const long long count = solid(in) ? quarters(in) * (n * n + 2LL * in.radial * n) * in.axial
                                    : 1LL * in.radial * in.axial * in.around;
  if (count > 2000000)
    refuse("the revolve would have " + std::to_string(count) + " elements; at most 2,000,000");
  const std::string type = to_upper(in.type);
  const std::vector<std::string> types = brick_types(registry);
  if (std::find(types.begin(), types.end(), type) == types.end())
    refuse("element type " + in.type + " cannot be meshed here; use " + brick_type_list(registry));
  if (needs_layer_side(registry, type)) {
    const std::string side = to_upper(in.layer_side);
    if (std::find(kSides.begin(), kSides.end(), side) == kSides.end())
      refuse("layer side must be one of INNER, OUTER, BOTTOM, TOP, CUT0, CUT1");
    if (side == "INNER" && solid(in)) refuse("a solid (inner radius 0) has no INNER side");
    if ((side == "CUT0" || side == "CUT1") && closed(in))
      refuse("a full 360 degree revolve has no cut planes");
  }
  if (!in.material.empty() && model.material_index(to_upper(in.material)) < 0)
    refuse("no material " + to_upper(in.material) + " in the model");
}

Model model_with_revolve(const Model& model, const RevolveInput& in,
                         const ElementRegistry& registry) {
  check_revolve(in, model, registry);
  const std::string name = to_upper(in.name);
  const std::string type = to_upper(in.type);
  const Frame f = frame_of(in);
  mesher::Mesh mesh;
  mesher::BlockSpec base;
  base.type = brick_of(registry, type);
  base.elset = name;
  try {
    std::vector<mesher::Block> blocks;
    if (solid(in))
      blocks = mesh_solid(mesh, in, f, base);
    else
      blocks.push_back(mesh_ring(mesh, in, f, base));
    mesher::merge_coincident_nodes(mesh);
    const double tol = 1e-7 * std::max(in.r_outer, in.z1 - in.z0);
    std::array<std::vector<mesher::FaceRef>, 6> sides;
    for (const mesher::Block& b : blocks)
      for (int axis = 0; axis < 3; ++axis)
        for (int value : {-1, 1})
          for (const mesher::FaceRef& face : b.side_faces(axis, value))
            if (const int s = side_of(mesh, face, in, f, tol); s >= 0) sides[s].push_back(face);
    for (int s = 0; s < 6; ++s)
      if (!sides[s].empty()) mesh.add_to_surface(name + "_" + kSides[s], sides[s]);
    convert_bricks(mesh, registry, type, name + "_" + to_upper(in.layer_side));
  } catch (const std::invalid_argument& e) {
    refuse(std::string("the mesher refuses the revolve: ") + e.what());
  }
  std::vector<int> all(mesh.nodes.size());
  for (std::size_t n = 0; n < all.size(); ++n) all[n] = static_cast<int>(n);
  mesh.add_to_node_set(name, all);
  for (const auto& [surface, faces] : mesh.surfaces)
    mesh.add_to_node_set(surface, mesh.surface_nodes(surface));

  Model result = model;
  std::vector<std::string> surfaces;
  for (const auto& entry : mesh.surfaces) surfaces.push_back(entry.first);
  append_meshed_part(result, mesh, surfaces, name, in.material);
  return result;
}

std::unique_ptr<Command> revolve_command(const Model& model, const RevolveInput& input,
                                         const ElementRegistry& registry) {
  Model after = model_with_revolve(model, input, registry);
  return make_replace_model("Revolve " + to_upper(input.name), model, std::move(after));
}

}  // namespace styk::gui
