#include "session/block_input.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "session/brick_types.hpp"
#include "session/input_checks.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/quality.hpp"

namespace styk::gui {
namespace {

const std::array<std::string, 6> kSides{"XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX"};

// Corner pairs of the C3D20 mid-edge nodes 9-20 (0-based corner indices).
constexpr int kEdgeCorners[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                     {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

std::string point_name(int i) {
  return i < 8
             ? "corner " + std::to_string(i + 1)
             : "mid-edge point " + std::to_string(i - 7) + " (node " + std::to_string(i + 1) + ")";
}

// Curved edges: 12 finite points, and no two of the 20 control points at the same place (a
// collapsed edge makes a degenerate map whose Jacobian vanishes along it).
void check_mid_edges(const BlockInput& in) {
  if (in.mid_edges.empty()) return;
  if (in.mid_edges.size() != 12)
    refuse("curved edges: give 12 mid-edge points (C3D20 nodes 9-20), not " +
           std::to_string(in.mid_edges.size()));
  for (const Vec3& p : in.mid_edges)
    for (double x : p) check_finite(x, "mid-edge point coordinate");
  std::vector<Vec3> points;
  for (const Vec3& c : block_corners(in)) points.push_back(c);
  points.insert(points.end(), in.mid_edges.begin(), in.mid_edges.end());
  double extent = 0.0;
  for (const Vec3& p : points)
    for (const Vec3& q : points)
      extent = std::max(extent, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  const double tolerance = 1e-9 * extent;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const Vec3& p = points[i];
      const Vec3& q = points[j];
      if (std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) <= tolerance)
        refuse("curved edges: " + point_name(static_cast<int>(j)) + " coincides with " +
               point_name(static_cast<int>(i)));
    }
}

// A curved map can fold inside although its first element is right-handed (all mesh_block
// checks): every generated element must have a positive Jacobian at its integration points and
// nodes (mesher::assess_quality).
void check_not_folded(const mesher::Mesh& mesh, const ElementRegistry& registry) {
  const Model part = mesher::to_model(mesh);
  mesher::QualityReport report;
  try {
    report = mesher::assess_quality(part, registry);
  } catch (const InputError& e) {
    refuse("the curved edges fold the block: " + e.message() +
           " (element numbers count within the block); move the mid-edge points closer to the "
           "straight midpoints");
  }
  for (const mesher::ElementQuality& q : report.elements)
    if (!(q.jacobian_ratio > 0))
      refuse(
          "the curved edges fold the block: element " +
          std::to_string(part.elements[q.element].id) +
          " of the block has a negative Jacobian at a node; move the mid-edge points closer to the "
          "straight midpoints");
}

}  // namespace

std::array<Vec3, 8> block_corners(const BlockInput& in) {
  if (in.use_corners) return in.corners;
  const Vec3& o = in.origin;
  const Vec3 e{o[0] + in.size[0], o[1] + in.size[1], o[2] + in.size[2]};
  return {{{o[0], o[1], o[2]},
           {e[0], o[1], o[2]},
           {e[0], e[1], o[2]},
           {o[0], e[1], o[2]},
           {o[0], o[1], e[2]},
           {e[0], o[1], e[2]},
           {e[0], e[1], e[2]},
           {o[0], e[1], e[2]}}};
}

std::vector<Vec3> straight_mid_edges(const BlockInput& in) {
  const std::array<Vec3, 8> c = block_corners(in);
  std::vector<Vec3> mids;
  for (const auto& edge : kEdgeCorners) {
    const Vec3& a = c[edge[0]];
    const Vec3& b = c[edge[1]];
    mids.push_back({0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])});
  }
  return mids;
}

void check_block(const BlockInput& in, const Model& model, const ElementRegistry& registry) {
  check_name(in.name, "the block's element set");
  const std::string name = to_upper(in.name);
  if (model.find_elset(name))
    refuse("element set " + name + " exists already; choose another name");
  for (const std::string& side : kSides)
    if (model.find_nset(name + "_" + side) || model.surfaces.count(name + "_" + side))
      refuse("node set or surface " + name + "_" + side + " exists already; choose another name");
  const char* axes = "xyz";
  long long count = 1;
  for (int k = 0; k < 3; ++k) {
    const std::string a(1, axes[k]);
    if (in.divisions[k] < 1)
      refuse("divisions along " + a + " must be at least 1, not " +
             std::to_string(in.divisions[k]));
    if (in.divisions[k] > 1000) refuse("divisions along " + a + " must be at most 1000");
    count *= in.divisions[k];
    check_finite(in.grading[k], "grading along " + a);
    if (!(in.grading[k] > 0)) refuse("grading along " + a + " must be > 0 (1 = uniform)");
    if (!in.use_corners) {
      check_finite(in.size[k], "size along " + a);
      check_finite(in.origin[k], "origin " + a);
      if (!(in.size[k] > 0)) refuse("size along " + a + " must be > 0");
    }
  }
  if (in.use_corners)
    for (const Vec3& c : in.corners)
      for (double x : c) check_finite(x, "corner coordinate");
  check_mid_edges(in);
  if (count > 2000000)
    refuse("the block would have " + std::to_string(count) + " elements; at most 2,000,000");
  const std::string type = to_upper(in.type);
  const std::vector<std::string> types = brick_types(registry);
  if (std::find(types.begin(), types.end(), type) == types.end())
    refuse("element type " + in.type + " cannot be meshed here; use " + brick_type_list(registry));
  if (needs_layer_side(registry, type) &&
      std::find(kSides.begin(), kSides.end(), to_upper(in.layer_side)) == kSides.end())
    refuse("layer side must be one of XMIN, XMAX, YMIN, YMAX, ZMIN, ZMAX");
  if (!in.material.empty() && model.material_index(to_upper(in.material)) < 0)
    refuse("no material " + to_upper(in.material) + " in the model");
}

Model model_with_block(const Model& model, const BlockInput& in, const ElementRegistry& registry) {
  check_block(in, model, registry);
  const std::string name = to_upper(in.name);
  const std::string type = to_upper(in.type);
  const std::array<Vec3, 8> corners = block_corners(in);
  std::vector<Vec3> control(corners.begin(), corners.end());
  control.insert(control.end(), in.mid_edges.begin(), in.mid_edges.end());
  mesher::Mesh mesh;
  mesher::BlockSpec spec;
  spec.type = brick_of(registry, type);
  spec.divisions = in.divisions;
  spec.grading = in.grading;
  spec.elset = name;
  try {
    const mesher::Block block = mesher::mesh_block(mesh, mesher::hex_map(control), spec);
    if (!in.mid_edges.empty()) check_not_folded(mesh, registry);
    for (int s = 0; s < 6; ++s)
      mesh.add_to_surface(name + "_" + kSides[s], block.side_faces(s / 2, s % 2 == 0 ? -1 : 1));
    convert_bricks(mesh, registry, type, name + "_" + to_upper(in.layer_side));
  } catch (const std::invalid_argument& e) {
    refuse(std::string("the mesher refuses the block: ") + e.what());
  }
  for (const std::string& side : kSides)
    mesh.add_to_node_set(name + "_" + side, mesh.surface_nodes(name + "_" + side));

  Model result = model;
  std::vector<std::string> surfaces;
  for (const std::string& side : kSides) surfaces.push_back(name + "_" + side);
  append_meshed_part(result, mesh, surfaces, name, in.material);
  return result;
}

std::unique_ptr<Command> block_command(const Model& model, const BlockInput& input,
                                       const ElementRegistry& registry) {
  Model after = model_with_block(model, input, registry);
  return make_replace_model("Mesh block " + to_upper(input.name), model, std::move(after));
}

}  // namespace styk::gui
