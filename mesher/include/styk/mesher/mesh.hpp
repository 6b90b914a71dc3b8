// The mesher's working mesh: nodes, hexahedra, named node/element sets, surfaces (element faces)
// and interfaces (coincident node pairs). Blocks are added to one Mesh, merged, converted, then
// turned into a Model with to_model(). Indices are 0-based; faces are 0-based Abaqus faces
// (0 = S1 zeta=-1, 1 = S2 zeta=+1, 2 = S3 eta=-1, 3 = S4 xi=+1, 4 = S5 eta=+1, 5 = S6 xi=-1).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "styk/core/model.hpp"

namespace styk::mesher {

struct MeshElement {
  std::string type;        // upper-case element type name (C3D8, C3D20, C3D21, C3D10, ...)
  std::vector<int> nodes;  // node indices in the element's own numbering
};

struct FaceRef {
  int element = 0;
  int face = 0;  // 0-based, S1 = 0
  bool operator==(const FaceRef& o) const { return element == o.element && face == o.face; }
  bool operator<(const FaceRef& o) const {
    return element != o.element ? element < o.element : face < o.face;
  }
};

// A zero-thickness interface made by split_interface(): node a (body A) coincides with node b
// (body B). The contact keywords that will consume it arrive with the contact issue.
struct Interface {
  std::string name;
  std::vector<std::pair<int, int>> pairs;
  std::string surface_a;  // names of the two facing surfaces in Mesh::surfaces
  std::string surface_b;
};

struct Mesh {
  std::vector<Vec3> nodes;
  std::vector<MeshElement> elements;
  std::map<std::string, std::vector<int>> node_sets;     // upper-case names, sorted unique
  std::map<std::string, std::vector<int>> element_sets;  // upper-case names, sorted unique
  std::map<std::string, std::vector<FaceRef>> surfaces;  // upper-case names, sorted unique
  std::vector<Interface> interfaces;
  // The faces of every element type in the mesh: per type, per face (S1 first), the element-local
  // nodes on it, corners first. Filled by whoever adds elements of a type: mesh_block() for its
  // C3D8/C3D20 bricks, convert_elements() and the splits from the type's own TElement::faces(),
  // so the mesh answers surface questions for any type without a table of type names.
  std::map<std::string, std::vector<std::vector<int>>> faces_of_type;

  int add_node(const Vec3& x) {
    nodes.push_back(x);
    return static_cast<int>(nodes.size()) - 1;
  }
  int add_element(std::string type, std::vector<int> element_nodes) {
    elements.push_back({std::move(type), std::move(element_nodes)});
    return static_cast<int>(elements.size()) - 1;
  }

  // Adds to a named set / surface (created when absent), keeping it sorted and unique.
  void add_to_node_set(const std::string& name, const std::vector<int>& members);
  void add_to_element_set(const std::string& name, const std::vector<int>& members);
  void add_to_surface(const std::string& name, const std::vector<FaceRef>& faces);

  // Node indices on a surface (sorted, unique). Throws std::logic_error for a surface on an element
  // type whose faces the mesh was not told (faces_of_type).
  std::vector<int> surface_nodes(const std::string& name) const;

  // Applies a node renumbering (old index -> new index, -1 = removed) to the elements, node sets
  // and interfaces (a set member or an interface pair whose node is removed is dropped);
  // `new_count` is the number of nodes kept. Node coordinates are moved along.
  void renumber_nodes(const std::vector<int>& old_to_new, int new_count);

  // Removes nodes no element uses (after a merge or a conversion). Returns how many.
  int remove_unused_nodes();

  // Length of the bounding-box diagonal (0 for an empty mesh).
  double size() const;
};

// A Model holding the mesh: node ids 1..n, element ids 1..m in mesh order, every node set and
// element set (surfaces and interfaces are not Model data yet); coordinates below 1e-13 x the
// model size are written as 0. Materials, sections, boundary
// conditions and steps are the caller's.
Model to_model(const Mesh& mesh, const std::string& source = "styk mesher");

// to_model() with one isotropic material MAT (E, nu) given to every element by a section on EALL,
// the heading `heading`: a solvable model of a single-material mesh.
Model finish_model(const Mesh& mesh, const std::string& heading, double young, double poisson);

}  // namespace styk::mesher
