// *COUPLING with *KINEMATIC (CalculiX): the listed translations of every surface node follow the
// rigid motion of the reference node, u_i = u_ref + theta x (x_i - x_ref) along each listed
// direction (global, or the axes of the coupling's *ORIENTATION at the node). The rotation theta
// is carried by the translations of an extra node, as CalculiX does, so the coupled surface may
// rotate freely about the reference node unless something else holds it.
#include <set>

#include <Eigen/Geometry>

#include "constraint_lowering.hpp"
#include "styk/core/local_axes.hpp"

namespace styk::solver_detail {
namespace {

std::set<int> surface_nodes(const Model& model, const ElementRegistry& registry,
                            const Surface& surface) {
  if (surface.kind == Surface::Kind::Nodes) return {surface.nodes.begin(), surface.nodes.end()};
  std::set<int> nodes;
  for (const SurfaceFace& sf : surface.faces) {
    const TElement* element = registry.find(model.elements[sf.element].type);
    if (!element || sf.face < 1 || sf.face > static_cast<int>(element->faces().size())) continue;
    const int* element_nodes = model.element_nodes(sf.element);
    for (int local : element->faces()[sf.face - 1].nodes) nodes.insert(element_nodes[local]);
  }
  return nodes;
}

Id next_free_id(const Model& model) {
  Id largest = 0;
  for (Id id : model.node_ids) largest = std::max(largest, id);
  return largest + 1;
}

}  // namespace

void lower_kinematic_couplings(Model& lowered, const ElementRegistry& registry,
                               EquationBuilder& equations) {
  for (const Coupling& coupling : lowered.couplings) {
    if (coupling.kind != Coupling::Kind::Kinematic) continue;
    const Surface& surface = lowered.surfaces.at(coupling.surface);
    const LocalAxes* axes = coupling.orientation.empty()
                                ? nullptr
                                : &lowered.orientations.at(coupling.orientation).axes;
    const int reference = coupling.reference_node;
    const Vec3 x_ref = lowered.coords[reference];
    // The rotation node: its translations are the reference node's rotations.
    const int rotation = lowered.add_node(next_free_id(lowered), x_ref, coupling.where);
    for (int node : surface_nodes(lowered, registry, surface)) {
      if (node == reference) continue;
      const Eigen::Vector3d r(lowered.coords[node][0] - x_ref[0],
                              lowered.coords[node][1] - x_ref[1],
                              lowered.coords[node][2] - x_ref[2]);
      Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
      if (axes && !local_axes_at(*axes, lowered.coords[node], R))
        throw InputError(coupling.where,
                         "*COUPLING " + coupling.name + ": node " +
                             std::to_string(lowered.node_ids[node]) +
                             " lies on the axis of ORIENTATION=" + coupling.orientation);
      for (int dof : coupling.dofs) {
        const Eigen::Vector3d e = R.col(dof - 1);
        equations.add({{node, e}, {reference, -e}, {rotation, -r.cross(e)}}, node, coupling.where);
      }
    }
  }
}

}  // namespace styk::solver_detail
