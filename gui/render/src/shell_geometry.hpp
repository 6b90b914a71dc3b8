// Private: shells drawn as surfaces with their thickness. A shell element (TElement::form() ==
// Shell: S4 ... S9R) has no faces; it is drawn as the body its section describes, with the
// geometry the solver uses (docs/elements.md "Shells"): x(xi, eta, zeta) = sum N_a [X_a + z V_a],
// z = t (zeta / 2 - offset), V_a the solver's unit nodal normal at node a (averaged over the
// elements sharing a smooth node, *NORMAL where given: styk/core/shell_normals.hpp; else the
// element's own normal there). The bottom (zeta = -1)
// and top (zeta = +1) faces are lit grids over the element, the free edges of the layer's shells
// (used by one shell of the layer) get side walls between them. Deformed: the nodes move by the
// scaled translations and the directors V_a turn by the scaled nodal rotations (UR), so bending
// shows as the faces moving apart along the fibres. Colours: a nodal or element field is
// interpolated over the surface (the same on both faces); a stress or strain field is taken from
// the tensors the solver stored at the surface Gauss points on the chosen fibre
// (ScalarField::shell_fibre), extrapolated over the element by Lagrange interpolation through
// those points (exact for a tensor linear (2x2 rule) or quadratic (3x3) in xi and eta), then
// evaluated, and drawn on every face of the shell.
#pragma once

#include <array>
#include <vector>

#include "styk/render/geometry.hpp"

namespace styk::render {

// Whether element e is drawn as a shell (its form is Shell).
bool is_drawn_shell(const TElement& formulation);

// Appends the layer's shells (LayerSkin::shells) to g: faces and walls to g.face_vertices /
// g.triangles, element edges on both faces to g.edges, the free edges and the walls' corners to
// g.edges and g.features, relative to g.origin.
void add_shell_elements(const SkinModel& skin, const SkinModel::LayerSkin& layer,
                        const GeometryRequest& request, FrameGeometry& g);

// The largest distance of a shell face from the shells' nodes (t (1/2 + |offset|)), for bounds.
double largest_shell_reach(const Model& model, const std::vector<int>& shells);

// The range of a field over the drawn points of the given shells (on the field's shell fibre for
// a field with point tensors); {+inf, -inf} when there are none.
std::array<double, 2> shell_field_range(const SkinModel& skin, const std::vector<int>& shells,
                                        const ScalarField& field);

}  // namespace styk::render
