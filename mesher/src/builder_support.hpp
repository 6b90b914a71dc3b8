// Shared pieces of the SPEC builders (private to the mesher).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher::detail {

constexpr double kPi = 3.14159265358979323846;

// The element family parameter shared by every builder.
ParamDecl family_param(const std::string& default_family, const std::vector<std::string>& allowed);
// Reads and checks it.
std::string family(const BuilderParams& params, const std::vector<std::string>& allowed);
// Every hexahedron family a builder can mesh with: the thesis' five, then the other built-in
// formulations (the studies' refinement series use them; builders opt in one by one).
extern const std::vector<std::string> kAllHexFamilies;
// What to mesh blocks with: the type the family converts from (TElement::conversion(): C3D8 for
// C3D14, C3D20 for C3D21/C3D28), the brick a tetrahedral or wedge family is split from (C3D8 for
// C3D4/C3D6, C3D20 for C3D10/C3D15), or the family itself.
std::string base_type(const ElementRegistry& registry, const std::string& family);
// Whether the family is made by splitting bricks (tetrahedra, wedges: mesher/split.hpp).
bool splits_bricks(const ElementRegistry& registry, const std::string& family);
// Converts a base mesh to the family as its element describes (mesher::convert_elements): every
// element (C3D14), or the layer of `contact_surface`, whose faces become the contact face
// (C3D21/C3D28); splits the bricks of a tetrahedral or wedge family (mesher/split.hpp); nothing
// for the bricks themselves.
void apply_family(Mesh& mesh, const ElementRegistry& registry, const std::string& family,
                  const std::string& contact_surface);

// An axis-aligned box as a block map.
BlockMap box_map(const Vec3& origin, const Vec3& size);

std::vector<int> nodes_where(const Mesh& mesh, const std::function<bool(const Vec3&)>& inside);

// Equivalent nodal areas A_i of the faces' nodes (TElement::nodal_areas, summed per node; C3D20
// corners are negative) and their total, summed in face order.
struct NodalAreas {
  std::map<int, double> area;  // node -> A_i
  double sum = 0.0;
};
NodalAreas equivalent_nodal_areas(const Model& model, const ElementRegistry& registry,
                                  const std::vector<FaceRef>& faces);

// Consistent nodal forces of a uniform traction with resultant `total` on the faces (A_i of every
// face node from TElement::nodal_areas, summed per node).
std::vector<ConcentratedLoad> traction_loads(const Model& model, const ElementRegistry& registry,
                                             const std::vector<FaceRef>& faces, const Vec3& total);

// A point force at `target`: on the node there, or shared between the two candidate nodes
// nearest to it in inverse proportion to their distances (a point between two nodes of an
// element edge). Returns the loads and the loaded nodes.
std::vector<ConcentratedLoad> point_force(const Mesh& mesh, const std::vector<int>& candidates,
                                          const Vec3& target, const Vec3& force,
                                          std::vector<int>* loaded = nullptr);

void fix(Model& model, const std::vector<int>& nodes, std::initializer_list<int> dofs);
void add_node_set(Model& model, const std::string& name, const std::vector<int>& nodes);
Step static_step();
OutputRequest print_request(OutputRequest::Kind kind, const std::string& set,
                            std::vector<std::string> vars, bool totals = false);

}  // namespace styk::mesher::detail
