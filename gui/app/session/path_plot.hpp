// The X-Y chart data of the results view: the contour field along the nodes of a node set, in
// the order of their distance along the set's main direction (a straight path of nodes, e.g. a
// beam's top edge).
#pragma once

#include <string>
#include <vector>

#include "session/scene.hpp"

namespace styk::gui {

struct PathPoint {
  double distance = 0.0;  // along the path from its first node (undeformed coordinates)
  double value = 0.0;
  Id node_id = 0;
};

// Throws InputError when the set does not exist, has fewer than 2 nodes, or no field is shown.
// Nodes no visible element uses are left out.
std::vector<PathPoint> field_along_node_set(const Scene& scene, const Model& model,
                                            const std::string& nset);

}  // namespace styk::gui
