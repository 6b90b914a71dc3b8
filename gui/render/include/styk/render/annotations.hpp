// What is drawn on top of the model's skin: node and element numbers (scene labels, shown where
// their anchor is seen) and the integration points coloured by their values.
#pragma once

#include <array>
#include <vector>

#include "styk/render/camera.hpp"
#include "styk/render/color_scale.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/overlay.hpp"
#include "styk/render/point_field.hpp"

namespace styk::render {

struct LabelRequest {
  bool nodes = false;     // node numbers (ids as in the deck)
  bool elements = false;  // element numbers
  // Non-empty: label only these (node / element indices, sorted), e.g. the selection.
  std::vector<int> only_nodes;
  std::vector<int> only_elements;
};

// The label colours: nodes in ink with a marker at the node, elements in dark red.
Rgb node_label_color();
Rgb element_label_color();

// Candidate labels of the drawn skin, placed as `request` places the geometry (deformed, relative
// to the skin's centre): a node label at each node of a drawn face or line element, an element
// label at the centre of the element's drawn face that turns most towards the eye (elements
// without a face towards the eye get none; a line element's at its middle). With
// `request.hide_undefined_faces` only the faces the field colours count. The renderer shows those
// whose anchor is not hidden (GlRenderer), elements first.
std::vector<SceneLabel> scene_labels(const SkinModel& skin, const GeometryRequest& request,
                                     const Camera& camera, const LabelRequest& labels);

// The integration points of the visible elements, as round points coloured by `field` on
// `colors`, placed like the faces of `request`; appended to geometry.ip_points.
void add_integration_points(const SkinModel& skin, const PointField& field,
                            const ColorScale& colors, const GeometryRequest& request,
                            FrameGeometry& geometry);

// How many integration points the visible elements have.
std::size_t visible_point_count(const SkinModel& skin, const PointField& field);
// Minimum and maximum of a point field over the visible elements ({0, 0} when none).
std::array<double, 2> point_field_range(const SkinModel& skin, const PointField& field);

}  // namespace styk::render
