// Curved shell objects (docs/gui.md "Shell surfaces"): a cylindrical panel or a hemisphere with a
// hole at its pole, meshed by mesher/shell_mesh.hpp into a shell type of the registry (S4 ...
// S9R), with a *SHELL SECTION when a material is given. These are the surfaces of the shell
// obstacle course (the Scordelis-Lo roof, the pinched cylinder, the pinched hemisphere), which a
// Plane object (4 points, straight or singly curved sides) cannot describe.
//
// Panel: radius R about the y axis, `length` along y from y = 0, spanning `angle` degrees
// symmetrically about +z (x = R sin(phi), z = R cos(phi)); 360 is the closed cylinder. u runs
// round the arc, v along y. Hemisphere: radius R about the origin, pole on +z, a hole of `hole`
// degrees about the pole, over `sweep` degrees of longitude from +x (90: the benchmark's quarter;
// 360 closes it); u runs round the longitude, v from the equator to the hole. Normals point
// outward. Created names (NAME upper-case): element set and node set NAME, node sets
// NAME_SIDE1 (v = -1: the panel's edge y = 0, the hemisphere's equator), NAME_SIDE2 (u = 1),
// NAME_SIDE3 (v = 1: the panel's edge y = length, the hole's rim) and NAME_SIDE4 (u = -1); a
// closed surface has no SIDE2 / SIDE4 (its seam is shared).
#pragma once

#include <memory>
#include <string>

#include "session/commands.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

enum class ShellSurfaceKind { CylindricalPanel, Hemisphere };

struct ShellSurfaceInput {
  std::string name = "SHELL";
  ShellSurfaceKind kind = ShellSurfaceKind::CylindricalPanel;
  double radius = 25.0;
  double length = 50.0;  // panel: along y
  double angle = 80.0;   // panel: degrees of arc, 0 < angle <= 360
  double hole = 18.0;    // hemisphere: degrees about the pole, 0 < hole < 90
  double sweep = 90.0;   // hemisphere: degrees of longitude, 0 < sweep <= 360
  int divisions_u = 8;   // round the arc / the longitude
  int divisions_v = 8;   // along the panel / from the equator to the hole
  double grading_u = 1.0;
  double grading_v = 1.0;
  std::string type = "S8R";  // a shell type with 4, 8 or 9 nodes
  std::string material;      // non-empty: a *SHELL SECTION of NAME with this material
  double thickness = 0.25;
  double offset = 0.0;  // the reference surface's offset, -0.5 .. 0.5 thicknesses
};

// The name of a kind as the dialog shows it ("Cylindrical panel", "Hemisphere") and back
// (refuses any other text).
std::string shell_surface_kind_name(ShellSurfaceKind kind);
ShellSurfaceKind shell_surface_kind_of(const std::string& name);

void check_shell_surface(const ShellSurfaceInput& input, const Model& model,
                         const ElementRegistry& registry);
Model model_with_shell_surface(const Model& model, const ShellSurfaceInput& input,
                               const ElementRegistry& registry);
std::unique_ptr<Command> shell_surface_command(const Model& model, const ShellSurfaceInput& input,
                                               const ElementRegistry& registry);

}  // namespace styk::gui
