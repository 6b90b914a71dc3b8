// "Revolve" geometry object (SPEC §5 volumes): the r-z rectangle [r_inner, r_outer] x [z0, z1]
// of a half-plane through an axis, revolved about that axis by an angle and meshed with
// hexahedra (C3D8, C3D20, or C3D20 with a C3D21/C3D28 contact layer on one side). With
// r_inner = 0 the rectangle touches the axis: the solid is meshed as an O-grid (a square core
// and two ring blocks per 90 degrees), which needs an angle of 90, 180, 270 or 360 degrees.
//
// Created names (NAME upper-case): element set NAME, node set NAME (every node), and surfaces
// plus node sets NAME_INNER (r = r_inner, absent for a solid), NAME_OUTER (r = r_outer),
// NAME_BOTTOM (z = z0), NAME_TOP (z = z1), NAME_CUT0 (the half-plane at angle 0) and NAME_CUT1
// (at the end angle); no cuts for 360 degrees. Nodes are never merged with the model's: two
// revolves sharing a cylinder (a shaft's outer = a sleeve's inner radius, the same divisions
// around and matching axial nodes) get coincident, separate nodes there — the zero-thickness
// interface a contact pair of NAME_OUTER and the other's NAME_INNER pairs node to node.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "session/commands.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct RevolveInput {
  std::string name = "PART";
  Vec3 origin{0, 0, 0};  // a point of the axis
  Vec3 axis{0, 0, 1};    // its direction (z measured along it from `origin`)
  double r_inner = 0.0;
  double r_outer = 10.0;
  double z0 = 0.0;
  double z1 = 10.0;
  double angle = 90.0;  // degrees, right-handed about the axis, from the reference half-plane
  // Elements radially (the O-grid's ring blocks for a solid), axially, and around the angle.
  int radial = 2;
  int axial = 4;
  int around = 6;
  double radial_grading = 1.0;  // last / first element length (outwards; upwards)
  double axial_grading = 1.0;
  std::string type = "C3D20";        // C3D8, C3D20, C3D21, C3D28
  std::string layer_side = "OUTER";  // C3D21/C3D28: INNER, OUTER, BOTTOM, TOP, CUT0, CUT1
  std::string material;              // non-empty: a solid section of NAME with this material
};

// The half-plane at angle 0 contains this direction (perpendicular to the axis): for the global
// axes z -> x, x -> y, y -> z; otherwise the global axis least aligned with the axis, projected.
Vec3 revolve_reference_direction(const Vec3& axis);

void check_revolve(const RevolveInput& input, const Model& model, const ElementRegistry& registry);
Model model_with_revolve(const Model& model, const RevolveInput& input,
                         const ElementRegistry& registry);
std::unique_ptr<Command> revolve_command(const Model& model, const RevolveInput& input,
                                         const ElementRegistry& registry);

}  // namespace styk::gui
