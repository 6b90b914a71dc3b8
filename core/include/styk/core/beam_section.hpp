// The standard beam cross-sections of *BEAM SECTION (CalculiX/Abaqus RECT, CIRC, PIPE, BOX):
// their section constants, the extreme-fibre points where stresses are reported, the outline the
// renderer extrudes, and the section axes of an element. Geometry only (no element, no Eigen), so
// the solver, the elements, the results reader and the renderer share one definition.
//
// Section coordinates (x1, x2) run along the section axes n1, n2; the beam axis t = n1 x n2 (so
// (t, n1, n2) is right-handed). Dimensions (BeamSection::dimensions, CalculiX meaning):
//   RECT a, b            width a along n1, height b along n2;
//   CIRC d1 [, d2]       axis lengths (diameters) along n1 and n2 (an ellipse; one value: circle);
//   PIPE r, t            outer radius r and wall thickness t (0 < t <= r);
//   BOX  a, b, t1..t4    outer width a along n1 and height b along n2; wall thicknesses t1 at
//                        +x1, t2 at +x2, t3 at -x1, t4 at -x2 (opposite walls equal: t1 = t3,
//                        t2 = t4, so the centroid is the box centre).
// The beam nodes lie on the centroid (no offsets).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk {

using SectionPoint = std::array<double, 2>;  // (x1, x2)

struct BeamSectionProperties {
  double area = 0.0;
  double I11 = 0.0;  // integral of x2^2 dA: bending about axis 1 (moment SM1)
  double I22 = 0.0;  // integral of x1^2 dA: bending about axis 2 (moment SM2)
  double J = 0.0;    // Saint-Venant torsion constant
  // Effective shear areas k A for transverse shear along axis 1 (SF3) and axis 2 (SF2).
  double shear_area1 = 0.0;
  double shear_area2 = 0.0;
  // The extreme fibres where stresses are reported: RECT, BOX the four outer corners (+,+), (-,+),
  // (-,-), (+,-); CIRC, PIPE the four points on the section axes (+r1, 0), (0, +r2), (-r1, 0),
  // (0, -r2).
  std::array<SectionPoint, 4> fibres{};
  // Torsional shear stress (components along n1, n2 on the section face) at each fibre per unit
  // torque: round sections T rho / J tangentially; rectangles 0 at the corners (St. Venant);
  // boxes Bredt's T / (2 A_m t) in the thinner wall meeting at the corner, along that wall.
  std::array<SectionPoint, 4> torsion_shear_per_torque{};
};

// Constants of a section; dimensions must have been checked (check_beam_section).
BeamSectionProperties beam_section_properties(const BeamSection& section);

// "" when the dimensions fit the shape (count, positive, walls thinner than the section, opposite
// BOX walls equal), else what is wrong, for an error at the *BEAM SECTION line.
std::string check_beam_section(const BeamSection& section);

// How many dimensions the first data line of each shape takes: {min, max}.
std::array<int, 2> beam_dimension_count(BeamShape shape);
// "RECT", "CIRC", "PIPE", "BOX".
const char* beam_shape_name(BeamShape shape);

// The closed outline of the section (counter-clockwise, in section coordinates): the outer edge
// and, for PIPE and BOX, the inner edge (`inner` = true; empty for solid sections). Round edges
// get `segments` points.
std::vector<SectionPoint> beam_section_outline(const BeamSection& section, bool inner,
                                               int segments);

// The section axes of an element whose axis points along `tangent` (need not be unit), from the
// approximate first axis `direction`: n2 = t x direction / |...|, n1 = n2 x t (Abaqus). False when
// the direction is (nearly) parallel to the tangent, so no axes follow.
bool beam_section_axes(const Vec3& tangent, const Vec3& direction, Vec3& n1, Vec3& n2);

}  // namespace styk
