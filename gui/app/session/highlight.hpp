// How the selection is shown: markers drawn over the model as overlay triangles (the renderer's
// 2D layer, drawn after the model without depth test), so the renderer needs no change and the
// selection stays visible in every display mode. The depth test is done here instead, with the
// picker's face-id buffer of the same frame: a node is marked only when it lies on a front-most
// face, an outline only along the stretches of its edges that a front-most face holding the
// edge covers, so nothing selected behind the front surface shows through. Nodes are squares with
// a dark rim; faces and elements are outlined along the corners of their skin faces.
#pragma once

#include <vector>

#include "session/selection.hpp"
#include "styk/render/overlay.hpp"

namespace styk::gui {

class Scene;

// Magenta: not a hue of the contour rainbow (blue .. red) nor of the muted layer palette.
constexpr render::Rgb kHighlight{1.0f, 0.0f, 1.0f};

// Appends the markers of `selection` for the scene's last frame() to `triangles`. Indices the
// model does not hold (a selection older than an edit) are skipped.
void append_highlight(const Scene& scene, const Selection& selection,
                      std::vector<render::OverlayVertex>& triangles);

// The corner nodes (model node indices) of face `face` (0-based) of element `element`, in order
// around the face.
std::vector<int> face_corner_nodes(const Scene& scene, int element, int face);

}  // namespace styk::gui
