#include "session/geometry_objects.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "session/input_checks.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::gui {
namespace {

bool is_plane_type(const std::string& type) {
  return type == "CPS4" || type == "CPE4" || type == "CPS8" || type == "CPE8";
}
int plane_order(const std::string& type) { return type == "CPS8" || type == "CPE8" ? 2 : 1; }

void check_divisions(int d, const std::string& what, int most) {
  if (d < 1) refuse(what + " divisions must be at least 1, not " + std::to_string(d));
  if (d > most) refuse(what + " divisions must be at most " + std::to_string(most));
}

void check_grading(double g, const std::string& what) {
  check_finite(g, what + " grading");
  if (!(g > 0)) refuse(what + " grading must be > 0 (last / first element length; 1 = uniform)");
}

void check_object_names(const Model& model, const std::string& name, const std::string& what) {
  check_name(name, what);
  const std::string upper = to_upper(name);
  if (model.find_elset(upper) || model.find_nset(upper))
    refuse("a set " + upper + " exists already; choose another name");
  check_set_names_free(model, upper);
}

void check_section(const Model& model, const std::string& material, double value,
                   const std::string& what) {
  if (material.empty()) return;
  if (model.material_index(to_upper(material)) < 0)
    refuse("no material " + to_upper(material) + " in the model");
  check_finite(value, what);
  if (!(value > 0)) refuse(what + " must be > 0");
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

// The mesh as a new part of `model` (element set and node set `name`), with a section when a
// material is given (`value`: thickness or area).
Model append_object(const Model& model, mesher::Mesh& mesh, const std::string& name,
                    const std::string& material, double value) {
  std::vector<int> all(mesh.nodes.size());
  std::iota(all.begin(), all.end(), 0);
  mesh.add_to_node_set(name, all);
  Model result = model;
  append_part(result, mesher::to_model(mesh));
  if (!material.empty()) {
    Section section;
    section.elset = name;
    section.material = to_upper(material);
    section.material_index = result.material_index(section.material);
    section.thickness = value;
    const int index = static_cast<int>(result.sections.size());
    result.sections.push_back(section);
    for (int e : result.elsets.at(name).elements) result.elements[e].section = index;
  }
  return result;
}

}  // namespace

void check_plane(const PlaneInput& in, const Model& model, const ElementRegistry& registry) {
  check_object_names(model, in.name, "the plane's element set");
  if (in.points.size() != 4 && in.points.size() != 8)
    refuse("a plane takes 4 corner points, or 4 corners and 4 mid-side points, not " +
           std::to_string(in.points.size()));
  for (const Vec3& p : in.points) {
    for (double c : p) check_finite(c, "every coordinate");
    if (p[2] != 0.0) refuse("plane elements lie in the x-y plane: every point needs z = 0");
  }
  check_divisions(in.divisions_u, "side 1-2", 1000);
  check_divisions(in.divisions_v, "side 1-4", 1000);
  check_grading(in.grading_u, "side 1-2");
  check_grading(in.grading_v, "side 1-4");
  const std::string type = to_upper(in.type);
  if (!is_plane_type(type))
    refuse("element type " + in.type + " cannot be meshed here; use CPS4, CPE4, CPS8 or CPE8");
  if (!registry.find(type)) refuse("element type " + type + " is not available");
  check_section(model, in.material, in.thickness, "the thickness");
}

Model model_with_plane(const Model& model, const PlaneInput& in, const ElementRegistry& registry) {
  check_plane(in, model, registry);
  const std::string name = to_upper(in.name);
  const std::string type = to_upper(in.type);
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
  if (!registry.find("T3D2")) refuse("element type T3D2 is not available");
  check_section(model, in.material, in.area, "the cross-section area");
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
  std::vector<int> elements;
  for (int k = 0; k < in.divisions; ++k) elements.push_back(mesh.add_element("T3D2", {k, k + 1}));
  mesh.add_to_element_set(name, elements);
  return append_object(model, mesh, name, in.material, in.area);
}

std::unique_ptr<Command> line_command(const Model& model, const LineInput& input,
                                      const ElementRegistry& registry) {
  Model after = model_with_line(model, input, registry);
  return make_replace_model("Line " + to_upper(input.name), model, std::move(after));
}

}  // namespace styk::gui
