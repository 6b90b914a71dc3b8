#include "session/shell_surfaces.hpp"

#include <cmath>
#include <exception>
#include <sstream>

#include "session/input_checks.hpp"
#include "session/object_support.hpp"
#include "styk/mesher/shell_mesh.hpp"

namespace styk::gui {
namespace {

using namespace objects;

const char* const kSides[] = {"_SIDE1", "_SIDE2", "_SIDE3", "_SIDE4"};

// Refuses an angle `value` (named `what`, in degrees) unless low < value <= high (or < high).
void check_angle(double value, double low, double high, bool high_included,
                 const std::string& what) {
  check_finite(value, what);
  const bool fits = value > low && (high_included ? value <= high : value < high);
  if (fits) return;
  std::ostringstream message;
  message << what << " must be > " << low << (high_included ? " and <= " : " and < ") << high
          << " degrees, not " << value;
  refuse(message.str());
}

void check_positive(double value, const std::string& what) {
  check_finite(value, what);
  if (!(value > 0)) refuse(what + " must be > 0");
}

// The shell type's node count fits the surface mesher (4, 8 or 9 nodes: quadrilaterals).
void check_shell_type(const std::string& type, const ElementRegistry& registry) {
  if (!is_shell_type(type, registry))
    refuse("element type " + type + " is no shell type; use S4, S4R, S8, S8R, S9 or S9R");
  const int nodes = registry.find(type)->node_count();
  if (nodes != 4 && nodes != 8 && nodes != 9)
    refuse("curved surfaces are meshed with quadrilateral shells (S4, S4R, S8, S8R, S9, S9R); " +
           type + " has " + std::to_string(nodes) + " nodes");
}

}  // namespace

std::string shell_surface_kind_name(ShellSurfaceKind kind) {
  return kind == ShellSurfaceKind::Hemisphere ? "Hemisphere" : "Cylindrical panel";
}

ShellSurfaceKind shell_surface_kind_of(const std::string& name) {
  for (const ShellSurfaceKind kind :
       {ShellSurfaceKind::CylindricalPanel, ShellSurfaceKind::Hemisphere})
    if (name == shell_surface_kind_name(kind)) return kind;
  refuse("unknown shell surface '" + name + "'; use Cylindrical panel or Hemisphere");
}

void check_shell_surface(const ShellSurfaceInput& in, const Model& model,
                         const ElementRegistry& registry) {
  check_object_names(model, in.name, "the surface's element set");
  check_positive(in.radius, "the radius");
  if (in.kind == ShellSurfaceKind::CylindricalPanel) {
    check_positive(in.length, "the length");
    check_angle(in.angle, 0, 360, true, "the angle");
  } else {
    check_angle(in.hole, 0, 90, false, "the hole");
    check_angle(in.sweep, 0, 360, true, "the sweep");
  }
  check_divisions(in.divisions_u, "u (round)", 1000);
  check_divisions(in.divisions_v, "v (along)", 1000);
  check_grading(in.grading_u, "u");
  check_grading(in.grading_v, "v");
  check_shell_type(to_upper(in.type), registry);
  check_section(model, in.material, in.thickness, "the thickness");
  check_finite(in.offset, "the offset");
  if (!(std::abs(in.offset) <= 0.5))
    refuse("the offset must lie within -0.5 .. 0.5 (thicknesses from the mid-surface)");
  for (const char* side : kSides) check_set_names_free(model, to_upper(in.name) + side);
}

Model model_with_shell_surface(const Model& model, const ShellSurfaceInput& in,
                               const ElementRegistry& registry) {
  check_shell_surface(in, model, registry);
  const mesher::ShellMeshSpec spec = shell_mesh_spec(in);
  mesher::Mesh mesh;
  try {
    mesh = in.kind == ShellSurfaceKind::CylindricalPanel
               ? mesher::shell_cylindrical_panel(in.radius, in.length, in.angle, spec, registry)
               : mesher::shell_hemisphere(in.radius, in.hole, in.sweep, spec, registry);
  } catch (const std::exception& e) {
    refuse(std::string("the mesher refuses the surface: ") + e.what());
  }
  return append_object(model, mesh, spec.elset, in.material, in.thickness, in.offset);
}

std::unique_ptr<Command> shell_surface_command(const Model& model, const ShellSurfaceInput& input,
                                               const ElementRegistry& registry) {
  Model after = model_with_shell_surface(model, input, registry);
  return make_replace_model(shell_surface_kind_name(input.kind) + " " + to_upper(input.name), model,
                            std::move(after));
}

}  // namespace styk::gui
