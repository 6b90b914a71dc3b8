// Axisymmetric models drawn as the body they stand for: every axisymmetric element
// (TElement::form() == Axisymmetric: its section in the r-z plane, x = r, y = the axis) is swept
// about the y axis through `degrees` in `segments` sectors, each sector a brick of the element's
// nodes on two rings (and a middle ring for the mid-edge nodes of a quadratic element: a 4-node
// section makes C3D8 sectors, an 8-node one C3D20). Nodes on the axis (r = 0) are one node for
// every angle. Other elements are left out: an axisymmetric picture shows the revolved body.
//
// The results follow the geometry: a node's displacement (u_r, u_z) turns with its angle (u_r
// along the radius, u_z along y, no hoop displacement), and a field evaluated on the section
// (field.hpp) is copied to every ring: node values to each copy of the node, element values to
// each sector. Stress and strain components keep the axisymmetric meaning the section's element
// computed them in (11 radial, 22 axial, 33 hoop, 12 rz) — a cylindrical frame that turns with
// the body; invariants (Mises, principal stresses) are the same in any frame.
#pragma once

#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/render/field.hpp"

namespace styk::render {

struct RevolvedModel {
  Model model;
  std::vector<Vec3> U;              // per revolved node; empty without displacements
  std::vector<int> source_node;     // per revolved node: the section node it copies
  std::vector<int> source_element;  // per revolved element: the section element it sweeps
  // Per revolved element node (Model::connectivity layout): the section element's local node.
  std::vector<int> source_local;
};

// Throws InputError when the model has no axisymmetric element, when an axisymmetric element is
// neither a 4-node nor an 8-node quadrilateral, or for degrees outside (0, 360] or segments < 1.
RevolvedModel revolve_axisymmetric(const Model& model, const ElementRegistry& registry,
                                   const IncrementResult* increment, double degrees, int segments);

// The field of the section carried over to the revolved model.
ScalarField revolve_field(const ScalarField& field, const Model& section,
                          const RevolvedModel& revolved);

}  // namespace styk::render
