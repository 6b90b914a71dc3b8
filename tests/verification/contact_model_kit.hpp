// Contact models for the tests, built with the mesher library (blocks, merge, interface split,
// C3D21/C3D28/C3D14 conversion) and completed here: materials per element set, the mesher's
// surfaces as *SURFACE data, contact pairs with their interactions, supports and loads picked by
// position. Header-only; the registry comes from registry_with_plugins() (hex_model_builder.hpp).
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::test {

// An axis-parallel box [lo, hi] meshed as one block.
inline mesher::Block add_box(mesher::Mesh& mesh, const Vec3& lo, const Vec3& hi,
                             std::array<int, 3> divisions, const std::string& type,
                             const std::string& elset,
                             std::array<double, 3> grading = {1.0, 1.0, 1.0}) {
  const mesher::BlockMap map = [lo, hi](const Vec3& xi) {
    Vec3 x;
    for (int d = 0; d < 3; ++d) x[d] = lo[d] + 0.5 * (xi[d] + 1.0) * (hi[d] - lo[d]);
    return x;
  };
  mesher::BlockSpec spec;
  spec.type = type;
  spec.divisions = divisions;
  spec.grading = grading;
  spec.elset = elset;
  return mesher::mesh_block(mesh, map, spec);
}

struct MaterialSpec {
  std::string elset;
  double young = 1.0;
  double poisson = 0.3;
};

// The mesh as a Model with one material and section per MaterialSpec (every element must be in
// exactly one of the sets), every mesh surface as an element-face *SURFACE, and one static step.
inline Model contact_model(const mesher::Mesh& mesh, const std::vector<MaterialSpec>& materials) {
  Model model = mesher::to_model(mesh, "contact-test.inp");
  for (const MaterialSpec& spec : materials) {
    Material material;
    material.name = "M_" + spec.elset;
    material.young = spec.young;
    material.poisson = spec.poisson;
    model.materials.push_back(material);
    Section section;
    section.elset = spec.elset;
    section.material = material.name;
    section.material_index = static_cast<int>(model.materials.size()) - 1;
    model.sections.push_back(section);
    for (int e : model.elsets.at(spec.elset).elements)
      model.elements[e].section = static_cast<int>(model.sections.size()) - 1;
  }
  for (const auto& [name, faces] : mesh.surfaces) {
    Surface surface;
    surface.name = name;
    for (const mesher::FaceRef& f : faces) surface.faces.push_back({f.element, f.face + 1});
    model.surfaces[name] = surface;
  }
  Step step;
  step.name = "LOAD";
  step.has_procedure = true;
  model.steps.push_back(step);
  return model;
}

// Adds interaction NAME (friction: nullopt = frictionless) and a node-to-surface pair.
inline void add_contact_pair(Model& model, const std::string& slave, const std::string& master,
                             const std::string& name, std::optional<Friction> friction) {
  SurfaceInteraction interaction;
  interaction.name = name;
  interaction.friction = friction;
  model.surface_interactions[name] = interaction;
  ContactPair pair;
  pair.slave = slave;
  pair.master = master;
  pair.interaction = name;
  model.contact_pairs.push_back(pair);
}

inline Friction coulomb(double mu) {
  Friction f;
  f.kind = Friction::Kind::Isotropic;
  f.mu = mu;
  return f;
}

using NodePredicate = std::function<bool(const Vec3&)>;

inline std::vector<int> nodes_where(const Model& model, const NodePredicate& where) {
  std::vector<int> out;
  for (int n = 0; n < model.node_count(); ++n)
    if (where(model.coords[n])) out.push_back(n);
  return out;
}

// Nodes used by the elements of `elset` only.
inline std::vector<int> nodes_of(const Model& model, const std::string& elset) {
  std::vector<char> used(model.node_count(), 0);
  for (int e : model.elsets.at(elset).elements)
    for (int k = 0; k < model.elements[e].node_count; ++k) used[model.element_nodes(e)[k]] = 1;
  std::vector<int> out;
  for (int n = 0; n < model.node_count(); ++n)
    if (used[n]) out.push_back(n);
  return out;
}

inline void fix(Model& model, const std::vector<int>& nodes, std::vector<int> dofs,
                double value = 0.0) {
  for (int n : nodes)
    for (int dof : dofs) model.boundaries.push_back({n, dof, value, {}});
}

inline bool near(double a, double b) { return std::abs(a - b) < 1e-9; }

}  // namespace styk::test
