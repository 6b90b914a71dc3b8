#include "session/geometry_objects.hpp"

#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "session/input_checks.hpp"
#include "session/object_support.hpp"
#include "styk/core/beam_section.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"
#include "styk/mesher/shell_mesh.hpp"

namespace styk::gui {
namespace {

using namespace objects;

bool is_plane_type(const std::string& type) {
  return type == "CPS4" || type == "CPE4" || type == "CPS8" || type == "CPE8";
}
int plane_order(const std::string& type) { return type == "CPS8" || type == "CPE8" ? 2 : 1; }

// A 3D beam type of the registry with 2 or 3 nodes (B31, B31R, B32, B32R).
bool is_space_beam_type(const std::string& type, const ElementRegistry& registry) {
  const TElement* f = registry.find(type);
  return f != nullptr && f->section_measure() == SectionMeasure::Beam && f->active_dofs()[2] &&
         (f->node_count() == 2 || f->node_count() == 3);
}

const char* const kSides[] = {"_SIDE1", "_SIDE2", "_SIDE3", "_SIDE4"};

std::optional<BeamShape> beam_shape_of(const std::string& name) {
  for (const BeamShape shape : {BeamShape::Rect, BeamShape::Circ, BeamShape::Pipe, BeamShape::Box})
    if (to_upper(name) == beam_shape_name(shape)) return shape;
  return std::nullopt;
}

BeamSection beam_section_of(const LineInput& in) {
  BeamSection section;
  section.shape = beam_shape_of(in.shape).value_or(BeamShape::Rect);
  section.dimensions = in.dimensions;
  section.direction = in.direction;
  section.direction_given = true;
  return section;
}

// Twice the signed area of the corner polygon in the x-y plane (positive: counter-clockwise).
double twice_area(const mesher::PatchMesh& mesh, const std::vector<int>& quad) {
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Vec3& p = mesh.nodes[quad[k]];
    const Vec3& q = mesh.nodes[quad[(k + 1) % 4]];
    sum += p[0] * q[1] - q[0] * p[1];
  }
  return sum;
}

}  // namespace

void check_plane(const PlaneInput& in, const Model& model, const ElementRegistry& registry) {
  check_object_names(model, in.name, "the plane's element set");
  if (in.points.size() != 4 && in.points.size() != 8)
    refuse("a plane takes 4 corner points, or 4 corners and 4 mid-side points, not " +
           std::to_string(in.points.size()));
  const std::string type = to_upper(in.type);
  const bool shells = is_shell_type(type, registry);
  for (const Vec3& p : in.points) {
    for (double c : p) check_finite(c, "every coordinate");
    if (p[2] != 0.0 && !shells)
      refuse(
          "plane elements lie in the x-y plane: every point needs z = 0 (shells may lie "
          "anywhere)");
  }
  check_divisions(in.divisions_u, "side 1-2", 1000);
  check_divisions(in.divisions_v, "side 1-4", 1000);
  check_grading(in.grading_u, "side 1-2");
  check_grading(in.grading_v, "side 1-4");
  if (!is_plane_type(type) && !shells)
    refuse("element type " + in.type +
           " cannot be meshed here; use CPS4, CPE4, CPS8, CPE8 or a shell: S4, S4R, S8, S8R, S9, "
           "S9R");
  if (!registry.find(type)) refuse("element type " + type + " is not available");
  check_section(model, in.material, in.thickness, "the thickness");
  if (!shells) return;
  check_finite(in.offset, "the offset");
  if (!(std::abs(in.offset) <= 0.5))
    refuse("the offset must lie within -0.5 .. 0.5 (thicknesses from the mid-surface)");
  for (const char* side : kSides) check_set_names_free(model, to_upper(in.name) + side);
}

namespace {

// A plane of shells: mesher::mesh_shell_patch on the points' map; refused when an element folds
// (its corners' normal vanishes or turns against the first element's).
Model model_with_shell_plane(const Model& model, const PlaneInput& in,
                             const ElementRegistry& registry) {
  const mesher::ShellMeshSpec spec = shell_mesh_spec(in);
  mesher::Mesh mesh;
  try {
    mesh = mesher::mesh_shell_patch(mesher::quad_map(in.points), spec, registry);
  } catch (const std::invalid_argument& e) {
    refuse(std::string("the mesher refuses the plane: ") + e.what());
  }
  double size = 0.0;
  for (const Vec3& p : in.points)
    size = std::max({size, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  const auto corner_normal = [&](const mesher::MeshElement& e) {
    const auto& x = mesh.nodes;
    const Vec3& a = x[e.nodes[0]];
    const Vec3& b = x[e.nodes[1]];
    const Vec3& c = x[e.nodes[2]];
    const Vec3& d = x[e.nodes[3]];
    const Vec3 p{c[0] - a[0], c[1] - a[1], c[2] - a[2]}, q{d[0] - b[0], d[1] - b[1], d[2] - b[2]};
    return Vec3{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
  };
  const Vec3 first = corner_normal(mesh.elements.front());
  for (const mesher::MeshElement& e : mesh.elements) {
    const Vec3 n = corner_normal(e);
    const double along = n[0] * first[0] + n[1] * first[1] + n[2] * first[2];
    if (!(std::hypot(n[0], n[1], n[2]) > 1e-12 * size * size) || !(along > 0))
      refuse(
          "the plane folds: give the corners in order round the patch and mid-side points "
          "that keep the sides apart");
  }
  return append_object(model, mesh, spec.elset, in.material, in.thickness, in.offset);
}

}  // namespace

Model model_with_plane(const Model& model, const PlaneInput& in, const ElementRegistry& registry) {
  check_plane(in, model, registry);
  const std::string name = to_upper(in.name);
  const std::string type = to_upper(in.type);
  if (is_shell_type(type, registry)) return model_with_shell_plane(model, in, registry);
  mesher::PatchMesh patch;
  try {
    patch = mesher::mesh_patch(mesher::quad_map(in.points), in.divisions_u, in.divisions_v,
                               in.grading_u, in.grading_v, plane_order(type));
  } catch (const std::invalid_argument& e) {
    refuse(std::string("the mesher refuses the plane: ") + e.what());
  }
  double size = 0.0;
  for (const Vec3& p : in.points) size = std::max({size, std::abs(p[0]), std::abs(p[1])});
  const double tiny = 1e-12 * size * size;
  for (const std::vector<int>& quad : patch.quads)
    if (!(twice_area(patch, quad) > tiny))
      refuse(
          "the plane folds or runs clockwise: give the corners counter-clockwise seen from +z, "
          "and mid-side points that keep the sides apart");
  mesher::Mesh mesh;
  mesh.nodes = patch.nodes;
  std::vector<int> elements;
  for (const std::vector<int>& quad : patch.quads) elements.push_back(mesh.add_element(type, quad));
  mesh.add_to_element_set(name, elements);
  return append_object(model, mesh, name, in.material, in.thickness);
}

std::unique_ptr<Command> plane_command(const Model& model, const PlaneInput& input,
                                       const ElementRegistry& registry) {
  Model after = model_with_plane(model, input, registry);
  return make_replace_model("Plane " + to_upper(input.name), model, std::move(after));
}

void check_line(const LineInput& in, const Model& model, const ElementRegistry& registry) {
  check_object_names(model, in.name, "the line's element set");
  for (int k = 0; k < 3; ++k) {
    check_finite(in.a[k], "start point");
    check_finite(in.b[k], "end point");
  }
  const double length = std::hypot(in.b[0] - in.a[0], in.b[1] - in.a[1], in.b[2] - in.a[2]);
  if (!(length > 0)) refuse("the line's end points coincide");
  check_divisions(in.divisions, "line", 100000);
  check_grading(in.grading, "line");
  const std::string type = to_upper(in.type);
  if (type != "T3D2" && !is_space_beam_type(type, registry))
    refuse("element type " + in.type +
           " cannot be meshed on a line; use T3D2, B31, B31R, B32 or B32R");
  if (!registry.find(type)) refuse("element type " + type + " is not available");
  if (type == "T3D2") {
    check_section(model, in.material, in.area, "the cross-section area");
    return;
  }
  check_section(model, in.material, 1.0, "the section");
  if (!beam_shape_of(in.shape))
    refuse("beam section " + in.shape + " is not RECT, CIRC, PIPE or BOX");
  for (double v : in.dimensions) check_finite(v, "every section dimension");
  for (double v : in.direction) check_finite(v, "the first section axis");
  const BeamSection section = beam_section_of(in);
  if (const std::string why = check_beam_section(section); !why.empty()) refuse(why);
  Vec3 n1, n2;
  if (!beam_section_axes({in.b[0] - in.a[0], in.b[1] - in.a[1], in.b[2] - in.a[2]}, in.direction,
                         n1, n2))
    refuse("the first section axis runs along the line: give a direction across it");
}

Model model_with_line(const Model& model, const LineInput& in, const ElementRegistry& registry) {
  check_line(in, model, registry);
  const std::string name = to_upper(in.name);
  mesher::Mesh mesh;
  try {
    mesh.nodes = mesher::mesh_line(in.a, in.b, in.divisions, in.grading);
  } catch (const std::invalid_argument& e) {
    refuse(std::string("the mesher refuses the line: ") + e.what());
  }
  const std::string type = to_upper(in.type);
  const int per_element = registry.find(type)->node_count();
  std::vector<int> elements;
  for (int k = 0; k < in.divisions; ++k) {
    if (per_element == 2) {
      elements.push_back(mesh.add_element(type, {k, k + 1}));
      continue;
    }
    const Vec3& p = mesh.nodes[k];
    const Vec3& q = mesh.nodes[k + 1];
    const int middle =
        mesh.add_node({0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])});
    elements.push_back(mesh.add_element(type, {k, middle, k + 1}));  // B32: the middle node 2nd
  }
  mesh.add_to_element_set(name, elements);
  if (type == "T3D2") return append_object(model, mesh, name, in.material, in.area);
  return append_object(model, mesh, name, in.material, 0.0, std::nullopt, beam_section_of(in));
}

std::unique_ptr<Command> line_command(const Model& model, const LineInput& input,
                                      const ElementRegistry& registry) {
  Model after = model_with_line(model, input, registry);
  return make_replace_model("Line " + to_upper(input.name), model, std::move(after));
}

}  // namespace styk::gui
