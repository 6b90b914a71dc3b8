// Plane and line geometry objects (SPEC §5 "geometry objects (lines, planes, volumes) meshed
// isoparametrically"; the volumes are Mesh block and Revolve).
//
// Plane: a patch of 4 corner points (counter-clockwise seen from +z), optionally with 4 mid-side
// points (side 1-2, 2-3, 3-4, 4-1) for curved sides, in the x-y plane (z = 0: the plane elements'
// plane), meshed by mesher::mesh_patch into CPS4/CPE4 or CPS8/CPE8 with divisions and grading
// along side 1-2 (u) and side 1-4 (v). With a material it gets a section of the given thickness.
// A plane of shells (S4, S4R, S8, S8R, S9, S9R: a type whose form is Shell) may lie anywhere in
// space; it is meshed by mesher::mesh_shell_patch (node sets NAME_SIDE1..4 too: sides 1-2, 2-3,
// 3-4, 4-1), its normal the right-hand normal of the corner order, and its section is a *SHELL
// SECTION (thickness, OFFSET).
// Line: a straight line a -> b divided into graded T3D2 trusses (mesher::mesh_line); with a
// material it gets a section whose first data value is the cross-section area. A line of beams
// (B31, B31R: 2 nodes; B32, B32R: 3 nodes, the middle one at mid-length) gets a *BEAM SECTION
// (RECT, CIRC, PIPE or BOX with its dimensions, and the approximate first section axis).
//
// Created names (NAME upper-case): element set NAME and node set NAME (every node). Nodes are
// never merged with the model's (a separate body, like the other parts).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "session/commands.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct PlaneInput {
  std::string name = "PLATE";
  std::vector<Vec3> points;  // 4 corners, or 4 corners + 4 mid-side points
  int divisions_u = 4;       // along side 1-2
  int divisions_v = 4;       // along side 1-4
  double grading_u = 1.0;    // last / first element length
  double grading_v = 1.0;
  std::string type = "CPS4";  // CPS4, CPE4 (4-node), CPS8, CPE8 (8-node) or a shell type
  std::string material;       // non-empty: a section of NAME with this material
  double thickness = 1.0;     // the section's thickness
  double offset = 0.0;        // shells: the reference surface's offset, -0.5..0.5 (OFFSET=)
};

struct LineInput {
  std::string name = "BAR";
  Vec3 a{0, 0, 0};
  Vec3 b{1, 0, 0};
  int divisions = 4;
  double grading = 1.0;            // last / first element length (from a to b)
  std::string material;            // non-empty: a section of NAME with this material
  double area = 1.0;               // the section's cross-section area (trusses)
  std::string type = "T3D2";       // T3D2, or a beam: B31, B31R, B32, B32R
  std::string shape = "RECT";      // beams: RECT, CIRC, PIPE, BOX
  std::vector<double> dimensions;  // beams: the *BEAM SECTION's first data line
  Vec3 direction{0.0, 0.0, -1.0};  // beams: the approximate first section axis
};

void check_plane(const PlaneInput& input, const Model& model, const ElementRegistry& registry);
Model model_with_plane(const Model& model, const PlaneInput& input,
                       const ElementRegistry& registry);
std::unique_ptr<Command> plane_command(const Model& model, const PlaneInput& input,
                                       const ElementRegistry& registry);

void check_line(const LineInput& input, const Model& model, const ElementRegistry& registry);
Model model_with_line(const Model& model, const LineInput& input, const ElementRegistry& registry);
std::unique_ptr<Command> line_command(const Model& model, const LineInput& input,
                                      const ElementRegistry& registry);

}  // namespace styk::gui
