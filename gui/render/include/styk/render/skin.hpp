// Skin extraction: the faces of a set of elements that no second element of the set shares.
// Only these are drawn (DESIGN "Headless and desktop rendering"). Face definitions come from each
// element's TElement::faces() (corners first), so plug-in elements need nothing here; a planar
// element is drawn as its own area (drawn_faces).
#pragma once

#include <cstdint>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::render {

struct SkinFace {
  int element = 0;  // element index
  int face = 0;     // 0-based face of the element (0 = S1)
};

// The formulation of every element of the model, looked up once. An element type the registry
// does not know is an InputError naming it, the element and the types that are known.
std::vector<const TElement*> element_formulations(const Model& model,
                                                  const ElementRegistry& registry);

// The faces of `elements` (indices into the model) not shared by two of them. Two faces are the
// same face when their sorted corner node indices agree (so a C3D20 face meets a C3D21 face).
// Linear time: faces are bucketed by their smallest corner node (a counting sort over the nodes,
// a perfect hash on the first key component) and matched within their bucket, whose size is
// bounded by the valence of one node. The result is ordered by bucket, so it is deterministic.
std::vector<SkinFace> extract_skin(const Model& model,
                                   const std::vector<const TElement*>& formulations,
                                   const std::vector<int>& elements);

// Number of corners (3 or 4) of a face definition: a 4th listed node inside the triangle of the
// first three (in natural coordinates) is a mid-edge node of a triangle, not a corner.
int face_corner_count(const TElement& element, const FaceDef& face);

// Whether a formulation is drawn as a planar area (CPS4, CPE8, CAX8, ...): its form
// (TElement::form()) is Planar or Axisymmetric, so its faces are its edges.
bool is_planar_element(const TElement& element);

// The faces the renderer draws, indexed as SkinFace::face: TElement::faces(), or for a planar
// element empty placeholders for its edges (never drawn) followed by the element's own area (all
// its nodes, corners first) at index faces().size(), so a plane mesh shows as a filled surface.
std::vector<FaceDef> drawn_faces(const TElement& element);

// Whether a formulation is a line element (a truss such as T3D2): its form is Line. It has no
// skin; the renderer draws it as segments through its nodes instead.
bool is_line_element(const TElement& element);

// The local nodes of a line element in their order along the line (ascending natural xi), e.g.
// {0, 2, 1} for a 3-node line listing its middle node last.
std::vector<int> line_node_order(const TElement& element);

}  // namespace styk::render
