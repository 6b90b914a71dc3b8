// Whether the faces that carry a surface field (contact output) can be seen in a view, or lie
// hidden under other faces (the slave surface of a fit under its master body). The frame's
// triangles are rasterised on the CPU with a depth buffer at a coarse resolution, back faces of a
// closed skin culled as the GL does.
#pragma once

#include "styk/render/camera.hpp"
#include "styk/render/geometry.hpp"

namespace styk::render {

// Below this fraction of their pixels seen, the faces that carry a surface field count as hidden
// (RenderOptions / DisplaySettings FieldFaces::Auto then draws them alone).
constexpr double kHiddenFieldFaces = 0.05;

// Of the pixels the field's triangles (vertices with t >= 0) cover when drawn alone, the fraction
// where one of them is also the front-most triangle of the whole picture; 0 when they cover none.
// `aspect` = width / height of the model area; the raster is `columns` pixels wide.
double field_faces_seen(const FrameGeometry& geometry, const Camera& camera, double aspect,
                        int columns = 240);

}  // namespace styk::render
