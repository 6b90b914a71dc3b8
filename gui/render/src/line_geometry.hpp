// Private: the vertex arrays of line elements (trusses). A line element has no faces, so it has
// no skin; it is drawn as the polyline through its nodes in their order along the element, placed
// and coloured exactly like the faces' grid points (same deformation, same field values), so a
// bar meets the faces of the solid it is attached to.
#pragma once

#include <vector>

#include "styk/render/geometry.hpp"

namespace styk::render {

// Appends the line elements of `layer` (LayerSkin::lines) to `bars` as line pairs: positions
// relative to `origin`, deformed by request.displacement x request.scale; coloured by the
// request's field (t per node; a discrete field splits each segment at its middle so no colour
// between two categories is drawn) or by the layer colour. A field with values at some nodes only
// colours the elements it covers entirely; the others are neutral grey or, with
// request.hide_undefined_faces, left out.
void add_line_elements(const SkinModel& skin, const SkinModel::LayerSkin& layer,
                       const GeometryRequest& request, const Vec3& origin,
                       std::vector<Vertex>& bars);

}  // namespace styk::render
