// Mesh quality report: per element the Jacobian ratio (min/max det J over the integration points
// and the nodes; negative when a corner is inverted although the integration points are not), the
// aspect ratio (longest/shortest corner edge) and the face warping (largest angle between the two
// triangle normals of a face's corners, degrees).
#pragma once

#include <vector>

#include "styk/core/element.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::mesher {

struct ElementQuality {
  int element = 0;              // element index
  double jacobian_ratio = 1.0;  // min det J / max det J (1 = affine)
  double aspect_ratio = 1.0;
  double warping_deg = 0.0;
};

struct QualityReport {
  std::vector<ElementQuality> elements;
  double min_jacobian_ratio = 1.0;
  double max_jacobian_ratio = 0.0;
  double max_aspect_ratio = 0.0;
  double max_warping_deg = 0.0;
  double volume = 0.0;  // sum of the element volumes (full integration rule)
};

// Throws InputError naming the element (TElement::jacobian) when det J <= 0 at an integration
// point (inverted or degenerate), and InputError for an element type the registry does not know.
QualityReport assess_quality(const Model& model, const ElementRegistry& registry);

}  // namespace styk::mesher
