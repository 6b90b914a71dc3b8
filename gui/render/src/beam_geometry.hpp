// Private: beams drawn as their cross-sections extruded along the deformed axis. A beam element
// (TElement::section_measure() == Beam) with a *BEAM SECTION in the model has no faces; it is
// drawn as a lit tube: rings of the section outline (RECT, BOX: flat sides; CIRC, PIPE: smooth)
// at points along the axis, placed like the faces' nodes (same deformation and scale), turned by
// the interpolated nodal rotations times the scale when the increment holds them, and closed by
// end caps (annular for PIPE and BOX). Colours: nodal and element fields are interpolated along
// the axis; stress and strain fields use the fibre tensors the field carries
// (ScalarField::point_tensors), interpolated over the section (bilinear between the corners of
// RECT and BOX, a first Fourier term around CIRC and PIPE: both exact for a stress linear in the
// section coordinates) and along the axis (Lagrange through the stations), then evaluated, so a
// bent beam shows tension on one side and compression on the other.
#pragma once

#include <vector>

#include "styk/render/geometry.hpp"

namespace styk::render {

// Whether element e is drawn as an extruded section: a beam formulation whose model section is a
// *BEAM SECTION.
bool is_drawn_beam(const Model& model, const TElement& formulation, int e);

// Appends the tubes of the layer's beams (LayerSkin::beams) to g.face_vertices / g.triangles and
// their end rings and long edges to g.edges, relative to g.origin.
void add_beam_elements(const SkinModel& skin, const SkinModel::LayerSkin& layer,
                       const GeometryRequest& request, FrameGeometry& g);

// The undeformed axes of the layer's beams as line pairs (the outline of the deformed view).
void add_beam_axes(const SkinModel& skin, const SkinModel::LayerSkin& layer, const Vec3& origin,
                   std::vector<Vertex>& lines);

// The largest distance of a section point from the axis of any beam (for bounding boxes).
double largest_beam_section_radius(const Model& model, const std::vector<int>& beams);

// The range of a field with fibre tensors over the section points of the given beams (interpolated
// tensors at the drawn outline points); {+inf, -inf} when there are none.
std::array<double, 2> beam_field_range(const SkinModel& skin, const std::vector<int>& beams,
                                       const ScalarField& field);

}  // namespace styk::render
