#include "section_extent.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace styk::solver_detail {

std::vector<double> section_extents(const Model& model) {
  constexpr double kHuge = std::numeric_limits<double>::max();
  std::vector<std::array<double, 6>> box(model.sections.size(),
                                         {kHuge, kHuge, kHuge, -kHuge, -kHuge, -kHuge});
  for (int e = 0; e < model.element_count(); ++e) {
    const int s = model.elements[e].section;
    if (s < 0 || s >= static_cast<int>(box.size())) continue;
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k)
      for (int d = 0; d < 3; ++d) {
        box[s][d] = std::min(box[s][d], model.coords[nodes[k]][d]);
        box[s][3 + d] = std::max(box[s][3 + d], model.coords[nodes[k]][d]);
      }
  }
  std::vector<double> extent(box.size(), 0.0);
  for (std::size_t s = 0; s < box.size(); ++s)
    for (int d = 0; d < 3; ++d)
      if (box[s][3 + d] >= box[s][d]) extent[s] = std::max(extent[s], box[s][3 + d] - box[s][d]);
  return extent;
}

}  // namespace styk::solver_detail
