// The placed geometry of one model element and its formulation (private to the studies).
#pragma once

#include "styk/core/element.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::studies::detail {

// The formulation of element e; throws InputError when the registry does not know its type.
const TElement& formulation_of(const Model& model, const ElementRegistry& registry, int e);

// Node coordinates of element e, one row per element node.
ElementGeometry geometry_of(const Model& model, int e);

// The point N(xi) X of an element.
Vec3 map_point(const Eigen::VectorXd& N, const ElementGeometry& g);

// Whether the element lives on the reference cube [-1, 1]^3 (a hexahedron of any node count).
bool is_hexahedron(const TElement& element);

}  // namespace styk::studies::detail
