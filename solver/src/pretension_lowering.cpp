// *PRE-TENSION SECTION, SURFACE= (CalculiX's construction): every node of the surface gets a copy
// that takes its place in the elements whose faces make up the surface, so the section is cut.
// Across the cut the two sides stay tied in the section plane (two equations per node along
// directions t and d perpendicular to the normal n), and along n every node pair opens by the
// same amount, that of the first pair, which equals dof 1 of the reference node:
//   n . (u_copy - u_node) = u_ref,1          (first pair)
//   n . (u_copy - u_node) = n . (u_copy,1 - u_node,1)   (every other pair)
// n points away from the surface's elements, so a positive u_ref (or a positive *CLOAD on it)
// shortens the bolt: tension.
#include <algorithm>
#include <array>
#include <map>

#include <Eigen/Geometry>

#include "constraint_lowering.hpp"
#include "styk/core/element.hpp"

namespace styk::solver_detail {
namespace {

Id next_free_id(const Model& model) {
  Id largest = 0;
  for (Id id : model.node_ids) largest = std::max(largest, id);
  return largest + 1;
}

// The outward unit normal of face `face` (0-based) of element e at its centre.
Eigen::Vector3d face_normal(const Model& model, const TElement& element, int e, int face) {
  ElementGeometry g;
  const int n = element.node_count();
  const int* nodes = model.element_nodes(e);
  g.X.resize(n, 3);
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < 3; ++d) g.X(k, d) = model.coords[nodes[k]][d];
  std::vector<Vec3> points;
  std::vector<Eigen::Vector3d> weighted;
  const FaceDef& f = element.faces()[face];
  element.face_quadrature(g, f, points, weighted);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& w : weighted) sum += w;
  // face_quadrature's vectors point along +axis; out of the element is -axis on a -1 face.
  return (f.value > 0.0 ? 1.0 : -1.0) * sum.normalized();
}

// t and d: CalculiX's in-plane directions for normal n (t from the x or y unit vector).
std::pair<Eigen::Vector3d, Eigen::Vector3d> in_plane(const Eigen::Vector3d& n) {
  const Eigen::Vector3d base =
      std::abs(n[0]) < 0.95 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t = (base - base.dot(n) * n).normalized();
  return {t, n.cross(t)};
}

}  // namespace

void lower_pretension_sections(Model& lowered, const ElementRegistry& registry,
                               EquationBuilder& equations, std::vector<std::string>* notes) {
  for (const PretensionSection& section : lowered.pretension_sections) {
    const Surface& surface = lowered.surfaces.at(section.surface);
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    if (section.normal) {
      n = Eigen::Vector3d((*section.normal)[0], (*section.normal)[1], (*section.normal)[2]);
    } else {
      for (const SurfaceFace& sf : surface.faces)
        n += face_normal(lowered, *registry.find(lowered.elements[sf.element].type), sf.element,
                         sf.face - 1);
      if (!(n.norm() > 0.0))
        throw InputError(section.where, "*PRE-TENSION SECTION: the face normals of surface " +
                                            section.surface +
                                            " cancel; give the normal on a "
                                            "data line");
      n.normalize();
      if (notes)
        notes->push_back(section.where.str() + ": *PRE-TENSION SECTION " + section.surface +
                         ": mean normal (" + std::to_string(n[0]) + ", " + std::to_string(n[1]) +
                         ", " + std::to_string(n[2]) + ")");
    }
    // Plane and axisymmetric elements move in the x-y plane only: their nodes have no z dof, so
    // the section takes n and t in that plane and no equation along d = z.
    const bool planar =
        std::all_of(surface.faces.begin(), surface.faces.end(), [&](const SurfaceFace& sf) {
          const ElementForm form = registry.find(lowered.elements[sf.element].type)->form();
          return form == ElementForm::Planar || form == ElementForm::Axisymmetric;
        });
    if (planar && std::abs(n[2]) > 1e-12)
      throw InputError(section.where, "*PRE-TENSION SECTION: the normal of surface " +
                                          section.surface +
                                          " of plane or axisymmetric elements must lie in the "
                                          "x-y plane");
    const auto [t, d] = in_plane(n);
    // The copy's components the three equations eliminate: distinct, with the largest product of
    // the coefficients n_a t_b d_c (CalculiX picks such a "Latin hypercube" too).
    std::array<int, 3> pick{0, 1, 2}, best = pick;
    double best_product = -1.0;
    do {
      const double product = std::abs(n[pick[0]] * t[pick[1]] * d[pick[2]]);
      if (product > best_product) {
        best_product = product;
        best = pick;
      }
    } while (std::next_permutation(pick.begin(), pick.end()));
    // Split: a copy per surface node, in place of the node in the surface's elements.
    std::map<int, int> copy_of;  // node -> copy, in node order (the first pair is the lowest)
    for (const SurfaceFace& sf : surface.faces) {
      const TElement& element = *registry.find(lowered.elements[sf.element].type);
      int* nodes = lowered.connectivity.data() + lowered.elements[sf.element].first_node;
      for (int local : element.faces()[sf.face - 1].nodes) {
        const int node = nodes[local];
        const auto [it, added] = copy_of.emplace(node, -1);
        if (added)
          it->second = lowered.add_node(next_free_id(lowered), lowered.coords[node], section.where);
        nodes[local] = it->second;
      }
    }
    // Elements that share a surface node without owning a face of the surface stay on the
    // original side; surface nodes already replaced (shared faces) keep their copy.
    const int reference = section.reference_node;
    const auto first = copy_of.begin();
    for (const auto& [node, copy] : copy_of) {
      equations.add({{copy, t}, {node, -t}}, copy, section.where, best[1]);
      if (!planar) equations.add({{copy, d}, {node, -d}}, copy, section.where, best[2]);
      if (node == first->first)
        equations.add({{copy, n}, {node, -n}, {reference, -Eigen::Vector3d::UnitX()}}, copy,
                      section.where, best[0]);
      else
        equations.add({{copy, n}, {node, -n}, {first->second, -n}, {first->first, n}}, copy,
                      section.where, best[0]);
    }
  }
}

}  // namespace styk::solver_detail
