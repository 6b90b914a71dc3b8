// What the status bar and the properties panel say about the selection: ids, coordinates, types
// and the value of the contour field shown (node value; element value; face = element + S1..Sn).
#pragma once

#include <string>
#include <vector>

#include "session/scene.hpp"
#include "session/selection.hpp"

namespace styk::gui {

// One line per selected entity, at most `limit` lines plus "... and N more". Node: "node 12
// (1, 0.5, 2)  S.mises = 1.2346E+02"; element: "element 5 C3D20, centroid (1, 0.5, 0.5)
// S.mises = ..." (an element field's own value, else the mean over the element's nodes); face:
// "element 5 C3D20 face S3".
std::vector<std::string> describe_selection(const Scene& scene, const Selection& selection,
                                            std::size_t limit = 20);

// A one-line summary for the status bar: "3 nodes selected" / "node 12 (...) ...".
std::string selection_summary(const Scene& scene, const Selection& selection);

// The integration-point values of one element (the probe of the integration-point display):
// "element 5 C3D20: S.mises at 27 integration points, 1.234E+02 .. 2.345E+02" ...
std::string element_probe_summary(const ElementProbe& probe);
// ... and one line per point: "point 1 (-0.7746, -0.7746, -0.7746) at (x, y, z): 1.2346E+02".
std::vector<std::string> describe_element_probe(const ElementProbe& probe);

}  // namespace styk::gui
